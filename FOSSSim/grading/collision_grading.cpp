#include "grading/collision_grading.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fosssim {

std::string describe_collision(const CollisionRecord& collision) {
  std::ostringstream out;
  out << "Particle " << collision.first << " - ";
  switch (collision.kind) {
    case CollisionKind::kParticleParticle:
      out << "Particle ";
      break;
    case CollisionKind::kParticleEdge:
      out << "Edge ";
      break;
    case CollisionKind::kParticleHalfPlane:
      out << "Halfplane ";
      break;
    case CollisionKind::kParticleSphere:
      out << "Sphere ";
      break;
  }
  out << collision.second << " with normal =";
  for (int c = 0; c < collision.normal.size(); ++c) out << " " << collision.normal[c];
  return out.str();
}

namespace {
const CollisionRecord* find_pair(const std::vector<CollisionRecord>& list,
                                 const CollisionRecord& pair) {
  for (const CollisionRecord& c : list) {
    if (c.same_pair(pair)) return &c;
  }
  return nullptr;
}
}  // namespace

void compare_collisions(const std::vector<CollisionRecord>& reference,
                        const std::vector<CollisionRecord>& file, CollisionGrade& grade) {
  for (const CollisionRecord& expected : reference) {
    const CollisionRecord* found = find_pair(file, expected);
    if (found == nullptr) {
      // A pair the reference found twice is missed once.
      if (&expected != find_pair(reference, expected)) continue;
      grade.lines.push_back("  Missed collision: " + describe_collision(expected));
      ++grade.missed;
      continue;
    }
    const bool same_size = found->normal.size() == expected.normal.size();
    if (!same_size || !((found->normal - expected.normal).norm() < kCollisionNormalTolerance)) {
      if (&expected != find_pair(reference, expected)) continue;
      grade.lines.push_back("  Collision with wrong normal: " + describe_collision(*found) +
                            " should be " + describe_collision(expected));
      ++grade.wrong_normal;
    }
  }
  for (const CollisionRecord& written : file) {
    if (find_pair(reference, written) != nullptr) continue;
    if (&written != find_pair(file, written)) continue;
    grade.lines.push_back("  Superfluous collision: " + describe_collision(written));
    ++grade.superfluous;
  }
}

bool compare_polynomials(const std::vector<Polynomial>& reference,
                         const std::vector<Polynomial>& file, std::vector<std::string>& lines) {
  if (reference.size() != file.size()) {
    lines.emplace_back("Wrong number of polynomials!");
    return false;
  }
  for (std::size_t k = 0; k < reference.size(); ++k) {
    if (reference[k].coefficients().size() != file[k].coefficients().size()) {
      lines.emplace_back("Wrong polynomial degree!");
      return false;
    }
  }
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const std::vector<double>& ours = reference[k].coefficients();
    const std::vector<double>& theirs = file[k].coefficients();
    double sum_ours = 0.0, sum_theirs = 0.0;
    for (double c : ours) sum_ours += std::abs(c);
    for (double c : theirs) sum_theirs += std::abs(c);
    const bool ours_zero = sum_ours < kPolynomialTolerance;
    const bool theirs_zero = !(sum_theirs >= kPolynomialTolerance);  // NaN counts as zero
    if (ours_zero && theirs_zero) continue;
    if (ours_zero != theirs_zero) {
      lines.emplace_back("Polynomial coefficients are close to all zero!");
      return false;
    }
    const double scale = sum_theirs / sum_ours;
    for (std::size_t c = 0; c < ours.size(); ++c) {
      if (!(std::abs(theirs[c] - ours[c] * scale) <= kPolynomialTolerance)) {
        lines.emplace_back("Wrong polynomial coefficients!");
        return false;
      }
    }
  }
  return true;
}

bool compare_sync_polynomials(const std::vector<Polynomial>& reference, std::size_t logged,
                              const std::vector<Polynomial>& file, std::int64_t step,
                              std::vector<std::string>& lines) {
  const auto end =
      reference.begin() + static_cast<std::ptrdiff_t>(std::min(logged, reference.size()));
  std::vector<std::string> found;
  if (compare_polynomials({reference.begin(), end}, file, found)) return true;
  for (const std::string& line : found) {
    lines.push_back("  Sync record of step " + std::to_string(step) + ": " + line);
  }
  return false;
}

}  // namespace fosssim
