#pragma once
// The one way forces write Hessians: D×D blocks into triplets, or into a recorded pattern.

#include <vector>

#include "core/hessian_pattern.h"
#include "core/types.h"

namespace fosssim {

/// Accumulates scaled D×D blocks of a Hessian; forces write their Hessians through it so that
/// the scatter into the global sparse matrix is written once. The scale belongs to whoever
/// assembles (forces only add blocks): it lets one assembly hold h²·hessX + h·hessV without
/// temporaries.
///
/// Three modes, the same for the forces:
/// - triplets: every value becomes a triplet, summed by build();
/// - recording: where each block goes is recorded in a HessianPattern (values are dropped);
/// - scatter: values go straight into the slots the pattern recorded, in a matrix of that
///   pattern: no triplets, no sorting, no allocation (core/hessian_pattern.h).
class HessianBuilder {
 public:
  /// Triplet mode.
  explicit HessianBuilder(double scale = 1.0) : scale_(scale) {}
  /// Recording mode: appends every write to `pattern` (cleared first by the caller).
  static HessianBuilder recording(HessianPattern& pattern) {
    HessianBuilder builder;
    builder.mode_ = Mode::kRecording;
    builder.pattern_ = &pattern;
    return builder;
  }
  /// Scatter mode: adds every write into `values`, the values of a matrix with the pattern
  /// `pattern` recorded; afterwards pattern.scattered_all() tells whether the writes were the
  /// recorded ones.
  static HessianBuilder scattering(HessianPattern& pattern, double* values) {
    HessianBuilder builder;
    builder.mode_ = Mode::kScatter;
    builder.pattern_ = &pattern;
    builder.values_ = values;
    pattern.begin_scatter();
    return builder;
  }

  /// Sets the factor applied to every block added from now on.
  void set_scale(double scale) { scale_ = scale; }
  /// From now on, also subtracts value·u[col] from product[row] for every value written, in
  /// write order, over every degree of freedom (whatever the pattern drops); nullptr stops it.
  void set_product(const Vector* u, Vector* product) {
    u_ = u;
    product_ = product;
  }

  /// Makes room for `entries` more triplets (triplet mode).
  void reserve(std::size_t entries) {
    if (mode_ == Mode::kTriplets) triplets_.reserve(triplets_.size() + entries);
  }

  /// Adds scale·H to the block of rows of particle pi and columns of particle pj.
  template <int D>
  void add_block(int pi, int pj, const Mat<D>& H) {
    if (product_ != nullptr) {
      for (int c = 0; c < D; ++c) {
        for (int r = 0; r < D; ++r) (*product_)[D * pi + r] -= scale_ * H(r, c) * (*u_)[D * pj + c];
      }
    }
    switch (mode_) {
      case Mode::kTriplets:
        for (int c = 0; c < D; ++c) {
          for (int r = 0; r < D; ++r) {
            triplets_.emplace_back(D * pi + r, D * pj + c, scale_ * H(r, c));
          }
        }
        break;
      case Mode::kRecording:
        pattern_->record_block(pi, pj);
        break;
      case Mode::kScatter:
        pattern_->scatter_block<D>(pi, pj, scale_, H, values_);
        break;
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
  void add_diagonal(int dof, double value) { add_entry(dof, dof, value); }
  /// Adds scale·value at (row, col), for Hessians that are not made of blocks.
  void add_entry(int row, int col, double value) {
    if (product_ != nullptr) (*product_)[row] -= scale_ * value * (*u_)[col];
    switch (mode_) {
      case Mode::kTriplets:
        triplets_.emplace_back(row, col, scale_ * value);
        break;
      case Mode::kRecording:
        pattern_->record_entry(row, col);
        break;
      case Mode::kScatter:
        pattern_->scatter_entry(row, col, scale_ * value, values_);
        break;
    }
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
  enum class Mode { kTriplets, kRecording, kScatter };
  Mode mode_ = Mode::kTriplets;
  double scale_ = 1.0;
  std::vector<Triplet> triplets_;
  HessianPattern* pattern_ = nullptr;
  double* values_ = nullptr;
  const Vector* u_ = nullptr;
  Vector* product_ = nullptr;
};

}  // namespace fosssim
