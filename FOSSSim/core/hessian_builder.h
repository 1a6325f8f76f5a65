#pragma once
// Collects per-particle D×D Hessian blocks as sparse triplets.

#include <vector>

#include "core/types.h"

namespace fosssim {

/// Accumulates scaled D×D blocks into a list of triplets; forces write their Hessians through it
/// so that the scatter into the global sparse matrix is written once. The scale belongs to
/// whoever assembles (forces only add blocks): it lets one list hold h²·hessX + h·hessV
/// without temporaries.
class HessianBuilder {
 public:
  explicit HessianBuilder(double scale = 1.0) : scale_(scale) {}

  /// Sets the factor applied to every block added from now on.
  void set_scale(double scale) { scale_ = scale; }

  /// Makes room for `entries` more triplets.
  void reserve(std::size_t entries) { triplets_.reserve(triplets_.size() + entries); }

  /// Adds scale·H to the block of rows of particle pi and columns of particle pj.
  template <int D>
  void add_block(int pi, int pj, const Mat<D>& H) {
    for (int c = 0; c < D; ++c) {
      for (int r = 0; r < D; ++r) {
        triplets_.emplace_back(D * pi + r, D * pj + c, scale_ * H(r, c));
      }
    }
  }

  /// The pair pattern of pair forces (docs/forces.md): +H to blocks (i,i) and (j,j), -H to (i,j)
  /// and (j,i).
  template <int D>
  void add_pair(int pi, int pj, const Mat<D>& H) {
    add_block<D>(pi, pi, H);
    add_block<D>(pj, pj, H);
    add_block<D>(pi, pj, -H);
    add_block<D>(pj, pi, -H);
  }

  /// Adds scale·value at (dof, dof).
  void add_diagonal(int dof, double value) { triplets_.emplace_back(dof, dof, scale_ * value); }
  /// Adds scale·value at (row, col), for Hessians that are not made of blocks.
  void add_entry(int row, int col, double value) {
    triplets_.emplace_back(row, col, scale_ * value);
  }

  std::vector<Triplet>& triplets() { return triplets_; }
  const std::vector<Triplet>& triplets() const { return triplets_; }
  void clear() { triplets_.clear(); }

  /// Sums the collected triplets into an n×n matrix.
  SparseMatrix build(int n) const {
    SparseMatrix matrix(n, n);
    matrix.setFromTriplets(triplets_.begin(), triplets_.end());
    return matrix;
  }

 private:
  double scale_;
  std::vector<Triplet> triplets_;
};

}  // namespace fosssim
