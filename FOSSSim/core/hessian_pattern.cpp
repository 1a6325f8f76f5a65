#include "core/hessian_pattern.h"

#include <algorithm>

namespace fosssim {

namespace {
/// (column, row) as one sortable key, columns first: the order of a compressed column matrix.
std::uint64_t key(int column, int row) {
  return (static_cast<std::uint64_t>(column) << 32) | static_cast<std::uint32_t>(row);
}
int key_column(std::uint64_t k) { return static_cast<int>(k >> 32); }
int key_row(std::uint64_t k) { return static_cast<int>(k & 0xffffffffu); }

void sort_unique(std::vector<std::uint64_t>& keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}
}  // namespace

HessianPattern::HessianPattern(int dim, std::vector<int> particle_map, int size)
    : dim_(dim), map_(std::move(particle_map)), size_(size) {}

void HessianPattern::clear() {
  writes_.clear();
  first_pass_ = kNoPass;
  repeated_ = false;
  outer_.clear();
  diagonal_slots_.clear();
  begin_scatter();
}

int HessianPattern::find_slot(int row, int col, const SparseMatrix& matrix) const {
  const auto* inner = matrix.innerIndexPtr();
  const auto* begin = inner + outer_[col];
  const auto* end = inner + outer_[col + 1];
  const auto* found = std::lower_bound(begin, end, row);
  return found != end && *found == row ? static_cast<int>(found - inner) : -1;
}

bool HessianPattern::finish(SparseMatrix& matrix) {
  // A second pass that repeats the first is kept once; the list loses the spare room that
  // recording left by doubling it (it would be kept for the whole run).
  const auto same_write = [](const Write& a, const Write& b) { return a.i == b.i && a.j == b.j; };
  repeated_ = first_pass_ != kNoPass && writes_.size() == 2 * first_pass_ &&
              std::equal(writes_.begin(), writes_.begin() + first_pass_,
                         writes_.begin() + first_pass_, same_write);
  if (repeated_) writes_.resize(first_pass_);
  writes_.shrink_to_fit();
  const int D = dim_;
  const auto map_dof = [&](int dof) {
    const int p = map_[dof / D];
    return p < 0 ? -1 : D * p + dof % D;
  };
  // The particle blocks and single entries of the matrix, sorted by column, then row.
  std::vector<std::uint64_t> blocks, entries;
  for (const Write& w : writes_) {
    if (w.i >= 0) {
      if (map_[w.i] >= 0 && map_[w.j] >= 0) blocks.push_back(key(map_[w.j], map_[w.i]));
    } else {
      const int row = map_dof(-1 - w.i), col = map_dof(w.j);
      if (row >= 0 && col >= 0) entries.push_back(key(col, row));
    }
  }
  for (int i = 0; i < size_; ++i) entries.push_back(key(i, i));
  sort_unique(blocks);
  sort_unique(entries);

  // Each column's rows: those of its particle's blocks merged with its single entries.
  outer_.assign(static_cast<std::size_t>(size_) + 1, 0);
  std::vector<SparseMatrix::StorageIndex> inner;
  inner.reserve(blocks.size() * D * D + entries.size());
  std::size_t block = 0, entry = 0;
  for (int particle = 0; particle < size_ / D; ++particle) {
    const std::size_t first = block;
    while (block < blocks.size() && key_column(blocks[block]) == particle) ++block;
    for (int c = 0; c < D; ++c) {
      const int col = D * particle + c;
      std::size_t b = first;
      int r = 0;  // next row within block b
      while (b < block || (entry < entries.size() && key_column(entries[entry]) == col)) {
        const int block_row = b < block ? D * key_row(blocks[b]) + r : size_;
        const bool has_entry = entry < entries.size() && key_column(entries[entry]) == col;
        const int entry_row = has_entry ? key_row(entries[entry]) : size_;
        const int row = std::min(block_row, entry_row);
        inner.push_back(row);
        if (block_row == row && ++r == D) {
          r = 0;
          ++b;
        }
        if (entry_row == row) ++entry;
      }
      outer_[col + 1] = static_cast<SparseMatrix::StorageIndex>(inner.size());
    }
  }

  matrix.resize(size_, size_);
  matrix.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer_.begin(), outer_.end(), matrix.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), matrix.innerIndexPtr());
  std::fill_n(matrix.valuePtr(), inner.size(), -0.0);

  // Every write's slot; a block's D rows must follow each other at one offset in its D columns.
  for (Write& w : writes_) {
    w.slot = -1;
    if (w.i >= 0) {
      if (map_[w.i] < 0 || map_[w.j] < 0) continue;
      const int row = D * map_[w.i], column = D * map_[w.j];
      const int slot = find_slot(row, column, matrix);
      const int offset = slot - outer_[column];
      for (int c = 0; c < D; ++c) {
        for (int r = 0; r < D; ++r) {
          const int at = outer_[column + c] + offset + r;
          if (at >= outer_[column + c + 1] || inner[at] != row + r) return false;
        }
      }
      w.slot = offset;
    } else {
      const int row = map_dof(-1 - w.i), col = map_dof(w.j);
      if (row >= 0 && col >= 0) w.slot = find_slot(row, col, matrix);
    }
  }
  diagonal_slots_.resize(static_cast<std::size_t>(size_));
  for (int i = 0; i < size_; ++i) diagonal_slots_[i] = find_slot(i, i, matrix);
  begin_scatter();
  return true;
}

void HessianPattern::begin_second_pass() {
  if (first_pass_ == kNoPass || cursor_ != first_pass_) broken_ = true;
  if (repeated_) cursor_ = 0;
  second_pass_ = true;
}

void HessianPattern::scatter_entry(int row, int col, double value, double* values) {
  if (broken_ || cursor_ == writes_.size() || writes_[cursor_].i != -1 - row ||
      writes_[cursor_].j != col) {
    broken_ = true;
    return;
  }
  const int slot = writes_[cursor_++].slot;
  if (slot >= 0) values[slot] += value;
}

std::size_t HessianPattern::bytes() const {
  return writes_.capacity() * sizeof(Write) + map_.capacity() * sizeof(int) +
         outer_.capacity() * sizeof(SparseMatrix::StorageIndex) +
         diagonal_slots_.capacity() * sizeof(int);
}

}  // namespace fosssim
