#pragma once
// Numeric types shared by the whole simulator.

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fosssim {

/// A state-sized vector: coordinates interleaved per particle, [x0, y0, (z0,) x1, y1, ...].
using Vector = Eigen::VectorXd;
/// Column-major sparse matrix over degrees of freedom.
using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;

/// Fixed-size per-particle vector and matrix in D = 2 or 3 dimensions.
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
template <int D>
using Mat = Eigen::Matrix<double, D, D>;

/// n particles' D-vectors as an n×D row-major matrix. Its storage is the interleaved layout of
/// a state vector, so a Vector of size D·n maps onto it without copying (map_points).
template <int D>
using Points = Eigen::Matrix<double, Eigen::Dynamic, D, Eigen::RowMajor>;

/// Views a state-sized vector as n×D points.
template <int D>
Eigen::Map<Points<D>> map_points(Vector& x) {
  return Eigen::Map<Points<D>>(x.data(), x.size() / D, D);
}
template <int D>
Eigen::Map<const Points<D>> map_points(const Vector& x) {
  return Eigen::Map<const Points<D>>(x.data(), x.size() / D, D);
}

/// The z component of the cross product of two planar vectors, a.x b.y − a.y b.x (in this order:
/// the course's rigid-body and bending code compute it so).
inline double cross(const Vec<2>& a, const Vec<2>& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Reads particle p's D coordinates out of a state-sized vector.
template <int D, typename Derived>
Vec<D> particle_vec(const Eigen::MatrixBase<Derived>& x, int p) {
  return x.template segment<D>(D * p);
}

}  // namespace fosssim
