#pragma once
// Where an assembly's Hessian blocks land in a compressed sparse matrix, recorded once.

#include <cstdint>
#include <vector>

#include "core/types.h"

namespace fosssim {

/// The sparsity pattern of an assembled matrix and, for every block and entry the forces
/// write (in the order they write them), the slot of its values: recorded from one assembly,
/// then reused by every assembly that writes the same sequence, which scatters values into
/// fixed slots (HessianBuilder in scatter mode) instead of collecting and sorting triplets.
///
/// Writes are in the forces' numbering (particles, degrees of freedom); a particle map takes
/// them to the matrix's: particle p becomes map[p], or its writes are dropped when map[p] < 0
/// (the fixed-particle rules of core/systems/step_matrix.h). Every diagonal entry of the matrix
/// is in the pattern, for the mass the assembler adds last.
///
/// An assembly may write in two passes (StepMatrix: hessX, then hessV). When the second pass
/// writes the same blocks in the same order as the first (springs with damping do), the
/// sequence is kept once and walked twice.
///
/// Values of one entry are summed in write order, starting from -0.0 (the exact identity of
/// floating-point addition), which is how Eigen's setFromTriplets sums duplicates: an
/// assembly gives the same bits either way. A block's D×D values must occupy D consecutive
/// rows in each of its D columns, at the same offset from each column's start; this holds for
/// every pattern made of whole blocks and single entries on the diagonal. finish() checks it.
class HessianPattern {
 public:
  /// dim: D of the blocks (2 or 3); particle_map: the matrix's particle for each particle, or
  /// -1; size: the matrix's dimension (dim × its particles).
  HessianPattern(int dim, std::vector<int> particle_map, int size);

  int dim() const { return dim_; }
  int size() const { return size_; }

  /// Forgets the recorded writes, to record a new sequence.
  void clear();
  /// Recording: the next write is the block of particles (pi, pj).
  void record_block(int pi, int pj) { writes_.push_back({pi, pj, -1}); }
  /// Recording: the next write is the single entry (row, col).
  void record_entry(int row, int col) { writes_.push_back({-1 - row, col, -1}); }
  /// Recording: the writes that follow are the second pass.
  void mark_second_pass() { first_pass_ = writes_.size(); }
  /// Builds the pattern of the recorded writes and every diagonal entry into `matrix` (size ×
  /// size, values -0.0) and finds every write's slot. Returns false when a block does not sit
  /// as described above: the pattern cannot be used (assemble from triplets instead).
  bool finish(SparseMatrix& matrix);

  /// Scattering: starts a new pass over the recorded writes.
  void begin_scatter() {
    cursor_ = 0;
    broken_ = false;
    second_pass_ = false;
  }
  /// Scattering: the writes that follow are the second pass, as when recording.
  void begin_second_pass();
  /// Adds scale·H to the slots of the next write, which must be the block (pi, pj).
  template <int D>
  void scatter_block(int pi, int pj, double scale, const Mat<D>& H, double* values);
  /// Adds value to the slot of the next write, which must be the entry (row, col).
  void scatter_entry(int row, int col, double value, double* values);
  /// True when every recorded write was made, in order, and no other: the values are complete.
  bool scattered_all() const {
    return !broken_ && cursor_ == writes_.size() && second_pass_ == (first_pass_ != kNoPass);
  }

  /// The slot of the diagonal entry (i, i) of the matrix.
  int diagonal_slot(int i) const { return diagonal_slots_[i]; }
  /// Bytes held (the write records, the index arrays), for memory accounting.
  std::size_t bytes() const;

 private:
  struct Write {
    int i;     ///< block: particle pi; entry: -1 - row
    int j;     ///< block: particle pj; entry: col
    int slot;  ///< block: offset of row D·map[pi] in column D·map[pj]; entry: its slot; -1: dropped
  };
  /// The slot of (row, col) of the matrix, or -1 when it is not in the pattern.
  int find_slot(int row, int col, const SparseMatrix& matrix) const;

  int dim_;
  std::vector<int> map_;
  int size_;
  std::vector<Write> writes_;
  std::vector<SparseMatrix::StorageIndex> outer_;  // the matrix's column starts
  std::vector<int> diagonal_slots_;
  static constexpr std::size_t kNoPass = static_cast<std::size_t>(-1);
  std::size_t first_pass_ = kNoPass;  // writes of the first pass, when a second was marked
  bool repeated_ = false;             // the second pass is the first again: kept once
  std::size_t cursor_ = 0;
  bool broken_ = false;
  bool second_pass_ = false;
};

template <int D>
void HessianPattern::scatter_block(int pi, int pj, double scale, const Mat<D>& H, double* values) {
  if (broken_ || cursor_ == writes_.size() || writes_[cursor_].i != pi ||
      writes_[cursor_].j != pj) {
    broken_ = true;
    return;
  }
  const int offset = writes_[cursor_++].slot;
  if (offset < 0) return;
  const int column = D * map_[pj];
  for (int c = 0; c < D; ++c) {
    double* slot = values + outer_[column + c] + offset;
    for (int r = 0; r < D; ++r) slot[r] += scale * H(r, c);
  }
}

}  // namespace fosssim
