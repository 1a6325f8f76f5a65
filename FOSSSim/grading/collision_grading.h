#pragma once
// Grading a step's collisions, polynomials and sync record (course-compatible criteria, plus
// FOSSSim's check of the sync record; docs/collisions.md, 'Grading').

#include <cstdint>
#include <string>
#include <vector>

#include "core/collisions/collision_record.h"
#include "core/collisions/polynomial.h"
#include "core/step/step_record.h"
#include "grading/grader.h"
#include "io/trajectory_file.h"

namespace fosssim {

/// A normal in the file passes when it is closer than this to the reference's, in the 2-norm.
constexpr double kCollisionNormalTolerance = 1e-9;
/// Tolerance of polynomial coefficients after rescaling, and of "all zero".
constexpr double kPolynomialTolerance = 1e-10;

/// "Particle 0 - Edge 2 with normal = 0.4 0", as the course's report describes a collision.
std::string describe_collision(const CollisionRecord& collision);

/// Compares the reference's collisions of one step with the file's as sets keyed by (type,
/// first, second): order and duplicates do not matter, nor does the time; the pair's order
/// does. Appends "  Missed collision: <reference>", "  Superfluous collision: <file>" and
/// "  Collision with wrong normal: <file> should be <reference>" (‖n_file - n_ref‖ ≥ 1e-9)
/// lines to `grade` and counts them.
void compare_collisions(const std::vector<CollisionRecord>& reference,
                        const std::vector<CollisionRecord>& file, CollisionGrade& grade);

/// Compares the reference's polynomial log of one step with the file's: the same number, the
/// same lengths, and each polynomial equal to the reference's times a positive factor (each
/// coefficient within 1e-10 of the reference's scaled by Σ|file|/Σ|reference|); two
/// polynomials whose coefficients are all below 1e-10 in sum are equal. A file polynomial near
/// zero where the reference's is not fails (the course lets it pass: FOSSSim is stricter).
/// Returns false after appending the course's line ("Wrong number of polynomials!", "Wrong
/// polynomial degree!", "Polynomial coefficients are close to all zero!" or "Wrong polynomial
/// coefficients!").
bool compare_polynomials(const std::vector<Polynomial>& reference,
                         const std::vector<Polynomial>& file, std::vector<std::string>& lines);

/// Compares the polynomials of a step's sync record in the file with the first `logged` of the
/// reference's polynomial log (those built before the sync point), as compare_polynomials does.
/// Returns false after appending "  Sync record of step K: " and compare_polynomials' line.
/// (FOSSSim's own check; the course's grader never reads them.)
bool compare_sync_polynomials(const std::vector<Polynomial>& reference, std::size_t logged,
                              const std::vector<Polynomial>& file, std::int64_t step,
                              std::vector<std::string>& lines);

}  // namespace fosssim
