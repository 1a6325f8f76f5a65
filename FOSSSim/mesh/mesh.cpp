#include "mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>

namespace fosssim {

namespace {

/// Collects unique unordered pairs in order of first appearance.
class PairSet {
 public:
  void add(int a, int b) {
    const std::array<int, 2> pair{std::min(a, b), std::max(a, b)};
    const auto key =
        (static_cast<unsigned long long>(pair[0]) << 32) | static_cast<unsigned>(pair[1]);
    if (seen_.insert(key).second) pairs_.push_back(pair);
  }
  std::vector<std::array<int, 2>> take() { return std::move(pairs_); }

 private:
  std::unordered_set<unsigned long long> seen_;
  std::vector<std::array<int, 2>> pairs_;
};

constexpr std::array<std::array<int, 2>, 6> kTetEdges = {
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

/// The faces of tet (a, b, c, d) of positive volume, each oriented outward.
constexpr std::array<std::array<int, 3>, 4> kTetFaces = {
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

}  // namespace

std::vector<std::array<int, 2>> compute_spring_pairs(const Mesh& mesh) {
  PairSet pairs;
  for (const auto& face : mesh.faces) {
    for (std::size_t a = 0; a < face.size(); ++a) {
      for (std::size_t b = a + 1; b < face.size(); ++b) pairs.add(face[a], face[b]);
    }
  }
  for (const auto& segment : mesh.segments) pairs.add(segment[0], segment[1]);
  for (const auto& tet : mesh.tets) {
    for (const auto& edge : kTetEdges) pairs.add(tet[edge[0]], tet[edge[1]]);
  }
  return pairs.take();
}

std::vector<std::array<int, 3>> compute_face_triangles(const Mesh& mesh) {
  std::vector<std::array<int, 3>> triangles;
  for (const auto& face : mesh.faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      triangles.push_back({face[0], face[k], face[k + 1]});
    }
  }
  return triangles;
}

std::vector<std::array<int, 3>> compute_tet_boundary(const Mesh& mesh) {
  // Count each face by its sorted corners; keep the oriented copy of those seen once.
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces;
  std::vector<std::array<int, 3>> order;
  for (const auto& tet : mesh.tets) {
    const bool positive = compute_tet_volume(mesh, tet) >= 0.0;
    for (const auto& local : kTetFaces) {
      std::array<int, 3> face{tet[local[0]], tet[local[1]], tet[local[2]]};
      if (!positive) std::swap(face[1], face[2]);
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = faces.try_emplace(key, 0, face);
      if (inserted) order.push_back(key);
      ++it->second.first;
    }
  }
  std::vector<std::array<int, 3>> boundary;
  for (const auto& key : order) {
    const auto& [count, face] = faces.at(key);
    if (count == 1) boundary.push_back(face);
  }
  return boundary;
}

double compute_tet_volume(const Mesh& mesh, const std::array<int, 4>& tet) {
  const Eigen::Vector3d& a = mesh.vertices[tet[0]];
  return (mesh.vertices[tet[1]] - a)
             .cross(mesh.vertices[tet[2]] - a)
             .dot(mesh.vertices[tet[3]] - a) /
         6.0;
}

double compute_triangle_area(const Mesh& mesh, const std::array<int, 3>& triangle) {
  const Eigen::Vector3d& a = mesh.vertices[triangle[0]];
  return 0.5 * (mesh.vertices[triangle[1]] - a).cross(mesh.vertices[triangle[2]] - a).norm();
}

std::array<double, 3> compute_voronoi_corner_areas(const Mesh& mesh,
                                                   const std::array<int, 3>& triangle) {
  const double area = compute_triangle_area(mesh, triangle);
  if (area == 0.0) return {0.0, 0.0, 0.0};  // no area to share, and maybe no angles
  std::array<double, 3> length{}, cosine{}, weight{};
  for (int c = 0; c < 3; ++c) {
    length[c] =
        (mesh.vertices[triangle[(c + 1) % 3]] - mesh.vertices[triangle[(c + 2) % 3]]).norm();
  }
  for (int c = 0; c < 3; ++c) {
    const double a = length[(c + 1) % 3];
    const double b = length[(c + 2) % 3];
    cosine[c] = (a * a + b * b - length[c] * length[c]) / (2.0 * a * b);
  }
  for (int o = 0; o < 3; ++o) {
    if (cosine[o] < 0.0) {  // obtuse at o: the circumcentre lies outside the triangle
      std::array<double, 3> shares;
      shares.fill(0.25 * area);
      shares[o] = 0.5 * area;
      return shares;
    }
  }
  for (int c = 0; c < 3; ++c) weight[c] = cosine[c] * length[c];
  const double sum = weight[0] + weight[1] + weight[2];
  std::array<double, 3> part{}, shares{};
  for (int c = 0; c < 3; ++c) part[c] = area * weight[c] / sum;
  for (int c = 0; c < 3; ++c) shares[c] = 0.5 * (part[(c + 1) % 3] + part[(c + 2) % 3]);
  return shares;
}

std::vector<double> compute_vertex_masses(const Mesh& mesh, const MassRule& rule) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  const int n = mesh.num_vertices();
  if (n == 0) fail("the mesh has no vertices");
  std::vector<double> mass(n, 0.0);
  switch (rule.kind) {
    case MassRule::kUniform:
      std::fill(mass.begin(), mass.end(), rule.value);
      return mass;
    case MassRule::kTotal:
      std::fill(mass.begin(), mass.end(), rule.value / n);
      return mass;
    case MassRule::kArea: {
      if (mesh.faces.empty()) fail("masses from areas need faces, and the mesh has none");
      for (const auto& triangle : compute_face_triangles(mesh)) {
        const double share = rule.value * compute_triangle_area(mesh, triangle) / 3.0;
        for (int corner : triangle) mass[corner] += share;
      }
      break;
    }
    case MassRule::kVoronoi: {
      if (mesh.faces.empty()) fail("masses from areas need faces, and the mesh has none");
      for (const auto& triangle : compute_face_triangles(mesh)) {
        const std::array<double, 3> shares = compute_voronoi_corner_areas(mesh, triangle);
        for (int c = 0; c < 3; ++c) mass[triangle[c]] += rule.value * shares[c];
      }
      break;
    }
    case MassRule::kVolume: {
      if (mesh.tets.empty()) fail("masses from volumes need tets, and the mesh has none");
      for (const auto& tet : mesh.tets) {
        const double share = rule.value * std::abs(compute_tet_volume(mesh, tet)) / 4.0;
        for (int corner : tet) mass[corner] += share;
      }
      break;
    }
  }
  for (int v = 0; v < n; ++v) {
    if (!(mass[v] > 0.0)) {
      fail("vertex " + std::to_string(v) + " (0-based) gets no mass: it lies on no " +
           (rule.kind == MassRule::kVolume ? "tet of positive volume" : "face of positive area") +
           "; give masses per vertex instead");
    }
  }
  return mass;
}

std::vector<int> select_extreme_vertices(const Mesh& mesh, int axis, bool highest, double within) {
  std::vector<int> selected;
  if (mesh.vertices.empty()) return selected;
  double extreme = mesh.vertices[0][axis];
  for (const auto& x : mesh.vertices)
    extreme = highest ? std::max(extreme, x[axis]) : std::min(extreme, x[axis]);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (std::abs(mesh.vertices[v][axis] - extreme) <= within) selected.push_back(v);
  }
  return selected;
}

}  // namespace fosssim
