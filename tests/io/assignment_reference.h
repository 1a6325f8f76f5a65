#pragma once
// A reference solution of the fast mass-springs assignment, written from its text (Liu et al.
// 2013 as the assignment poses it) and from the choices its starter code and data make, not
// from FOSSSim's code: tests compare FOSSSim's JSON scenes with it.
//
// The assignment's system, for n vertices at positions p (n × 3), springs e = (i, j) with rest
// lengths r_e and one stiffness k, masses M = diag(m), pinned vertices C (one row per pin):
//   Q = k AᵀA + M/h² + w CᵀC          (A: the signed incidence matrix, #springs × n)
//   each step, from pⁿ and pⁿ⁻¹ (pⁿ⁻¹ = pⁿ at the start: the mesh starts at rest):
//     p = pⁿ; 50 times: d_e = r_e (p_i - p_j)/|p_i - p_j|   (local)
//                        Q p = k Aᵀd + M(2pⁿ - pⁿ⁻¹)/h² + f_ext + w CᵀC p_rest   (global)
// with h = 1/30, w = 1e10 and f_ext = (0, -9.8, 0) on every vertex. Springs join every pair of
// corners of every face (a quad gets both diagonals) and the two ends of "f i j" lines. Without
// a given mass, the masses are libigl's default mass matrix of the faces fanned from their first
// corner: for each triangle of area A, A/2 to an obtuse corner and A/4 to the others, else each
// corner's Voronoi area (Meyer et al. 2003), written here with cotangents.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fosssim::testing {

/// A mesh as an OBJ file of the assignment holds it: faces of 3 or more corners, and faces of
/// two corners ("f i j"), which are springs. 0-based here; written 1-based.
struct ObjMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
};

/// The OBJ text of the mesh, with every coordinate written so that it reads back exactly.
inline std::string obj_text(const ObjMesh& mesh) {
  std::string text;
  char line[128];
  for (const Eigen::Vector3d& x : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", x.x(), x.y(), x.z());
    text += line;
  }
  for (const auto& face : mesh.faces) {
    text += "f";
    for (int corner : face) text += " " + std::to_string(corner + 1);
    text += "\n";
  }
  return text;
}

/// Which rules the reference follows; the defaults are the assignment's. The others let a
/// test show that it tells the rules apart.
struct ReferenceRules {
  bool voronoi_masses = true;  ///< false: a third of each triangle's area to each corner
  bool start_current = true;   ///< false: iterations start at 2pⁿ - pⁿ⁻¹
};

class AssignmentReference {
 public:
  static constexpr double kTimeStep = 1.0 / 30.0;
  static constexpr int kIterations = 50;
  static constexpr double kPenalty = 1e10;
  static constexpr double kGravity = -9.8;

  /// `pinned` 1-based, as the JSON's "b"; `mass` the JSON's "m", if given.
  AssignmentReference(const ObjMesh& mesh, double k, const std::vector<int>& pinned,
                      std::optional<double> mass, ReferenceRules rules = {})
      : rules_(rules), k_(k), rest_(as_matrix(mesh.vertices)) {
    const int n = static_cast<int>(mesh.vertices.size());
    std::set<std::pair<int, int>> edges;
    for (const auto& face : mesh.faces) {
      for (std::size_t a = 0; a < face.size(); ++a) {
        for (std::size_t b = a + 1; b < face.size(); ++b)
          edges.emplace(std::min(face[a], face[b]), std::max(face[a], face[b]));
      }
    }
    edges_.assign(edges.begin(), edges.end());
    std::vector<Eigen::Triplet<double>> a_entries;
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      const auto [i, j] = edges_[e];
      a_entries.emplace_back(static_cast<int>(e), i, 1.0);
      a_entries.emplace_back(static_cast<int>(e), j, -1.0);
      rest_lengths_.push_back((rest_.row(i) - rest_.row(j)).norm());
    }
    A_.resize(static_cast<int>(edges_.size()), n);
    A_.setFromTriplets(a_entries.begin(), a_entries.end());
    masses_ = mass ? Eigen::VectorXd::Constant(n, *mass) : area_masses(mesh);
    std::vector<Eigen::Triplet<double>> c_entries;
    for (std::size_t row = 0; row < pinned.size(); ++row)
      c_entries.emplace_back(static_cast<int>(row), pinned[row] - 1, 1.0);
    C_.resize(static_cast<int>(pinned.size()), n);
    C_.setFromTriplets(c_entries.begin(), c_entries.end());
    Eigen::SparseMatrix<double> M(n, n);
    for (int v = 0; v < n; ++v) M.insert(v, v) = masses_[v];
    M_ = M;
    const double h = kTimeStep;
    const Eigen::SparseMatrix<double> Q =
        k_ * Eigen::SparseMatrix<double>(A_.transpose() * A_) + M_ / (h * h) +
        kPenalty * Eigen::SparseMatrix<double>(C_.transpose() * C_);
    factor_.compute(Q);
    current_ = rest_;
    previous_ = rest_;
  }

  /// One time step of the assignment.
  void step() {
    const double h = kTimeStep;
    Eigen::MatrixXd external = Eigen::MatrixXd::Zero(current_.rows(), 3);
    external.col(1).setConstant(kGravity);
    const Eigen::MatrixXd inertial = 2.0 * current_ - previous_;
    const Eigen::MatrixXd constant =
        M_ * inertial / (h * h) + external + kPenalty * (C_.transpose() * (C_ * rest_));
    Eigen::MatrixXd p = rules_.start_current ? current_ : inertial;
    Eigen::MatrixXd d(static_cast<int>(edges_.size()), 3);
    for (int iteration = 0; iteration < kIterations; ++iteration) {
      for (std::size_t e = 0; e < edges_.size(); ++e) {
        const Eigen::RowVector3d spring = p.row(edges_[e].first) - p.row(edges_[e].second);
        d.row(static_cast<int>(e)) = rest_lengths_[e] * spring / spring.norm();
      }
      p = factor_.solve(k_ * (A_.transpose() * d) + constant);
    }
    previous_ = current_;
    current_ = p;
  }

  const Eigen::MatrixXd& positions() const { return current_; }
  const Eigen::VectorXd& masses() const { return masses_; }
  int num_springs() const { return static_cast<int>(edges_.size()); }
  /// The length of the diagonal of the rest mesh's bounding box.
  double diagonal() const {
    return (rest_.colwise().maxCoeff() - rest_.colwise().minCoeff()).norm();
  }

 private:
  static Eigen::MatrixXd as_matrix(const std::vector<Eigen::Vector3d>& points) {
    Eigen::MatrixXd out(static_cast<int>(points.size()), 3);
    for (std::size_t v = 0; v < points.size(); ++v) out.row(static_cast<int>(v)) = points[v];
    return out;
  }

  /// Each corner's share of triangle (a, b, c), by the rules.
  std::array<double, 3> shares(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) const {
    const std::array<Eigen::Vector3d, 3> x{a, b, c};
    const double twice_area = (b - a).cross(c - a).norm();
    const double area = 0.5 * twice_area;
    if (!rules_.voronoi_masses) return {area / 3.0, area / 3.0, area / 3.0};
    std::array<double, 3> dot{};  // of the two sides leaving each corner
    for (int corner = 0; corner < 3; ++corner) {
      dot[corner] = (x[(corner + 1) % 3] - x[corner]).dot(x[(corner + 2) % 3] - x[corner]);
    }
    for (int corner = 0; corner < 3; ++corner) {
      if (dot[corner] < 0.0) {  // obtuse
        std::array<double, 3> out{area / 4.0, area / 4.0, area / 4.0};
        out[corner] = area / 2.0;
        return out;
      }
    }
    // Meyer et al.: corner P of triangle PQR gets (|PQ|² cot R + |PR|² cot Q) / 8.
    std::array<double, 3> out{};
    for (int corner = 0; corner < 3; ++corner) {
      const int q = (corner + 1) % 3, r = (corner + 2) % 3;
      const double cot_q = dot[q] / twice_area, cot_r = dot[r] / twice_area;
      out[corner] =
          ((x[q] - x[corner]).squaredNorm() * cot_r + (x[r] - x[corner]).squaredNorm() * cot_q) /
          8.0;
    }
    return out;
  }

  Eigen::VectorXd area_masses(const ObjMesh& mesh) const {
    Eigen::VectorXd m = Eigen::VectorXd::Zero(static_cast<int>(mesh.vertices.size()));
    for (const auto& face : mesh.faces) {
      for (std::size_t j = 1; j + 1 < face.size(); ++j) {  // the fan from the first corner
        const std::array<int, 3> t{face[0], face[j], face[j + 1]};
        const auto s = shares(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
        for (int corner = 0; corner < 3; ++corner) m[t[corner]] += s[corner];
      }
    }
    return m;
  }

  ReferenceRules rules_;
  double k_;
  Eigen::MatrixXd rest_;
  std::vector<std::pair<int, int>> edges_;
  std::vector<double> rest_lengths_;
  Eigen::SparseMatrix<double> A_, C_, M_;
  Eigen::VectorXd masses_;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor_;
  Eigen::MatrixXd current_, previous_;
};

}  // namespace fosssim::testing
