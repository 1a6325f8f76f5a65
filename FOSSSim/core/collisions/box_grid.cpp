#include "core/collisions/box_grid.h"

#include <algorithm>

namespace fosssim {

template <int D>
void BoxGrid<D>::build(std::span<const Box<D>> boxes, double base_cell) {
  const int n = static_cast<int>(boxes.size());
  level_of_.assign(n, kUnbounded);
  by_level_.resize(kUnbounded);
  for (std::vector<int>& objects : by_level_) objects.clear();
  unbounded_.clear();
  unbounded_boxes_.clear();
  std::array<double, kUnbounded> inv_cells;
  for (int level = 0; level < kUnbounded; ++level) {
    inv_cells[level] = 1.0 / std::ldexp(base_cell, level);
  }
  for (int k = 0; k < n; ++k) {
    const Box<D>& box = boxes[k];
    const double extent = box.extent();
    int level = 0;
    if (!std::isfinite(extent)) {
      level = kUnbounded;  // infinite or NaN: no level holds it
    } else if (extent > base_cell) {
      level = std::clamp(std::ilogb(extent / base_cell), 0, static_cast<int>(kUnbounded));
    }
    // The first level at which the box spans at most two cells along every axis, checked on
    // the cell coordinates it gets.
    for (; level < kUnbounded; ++level) {
      const double inv_cell = inv_cells[level];
      bool fits = true;
      for (int a = 0; a < D; ++a) {
        fits = fits && coordinate(box.hi[a], inv_cell) - coordinate(box.lo[a], inv_cell) <= 1;
      }
      if (fits) break;
    }
    level_of_[k] = level;
    if (level == kUnbounded) {
      unbounded_.push_back(k);
      unbounded_boxes_.push_back(box);
    } else {
      by_level_[level].push_back(k);
    }
  }
  std::size_t used = 0;
  for (int index = 0; index < kUnbounded; ++index) {
    if (by_level_[index].empty()) continue;
    if (used == levels_.size()) levels_.emplace_back();
    Level& level = levels_[used++];
    level.index = index;
    level.inv_cell = 1.0 / std::ldexp(base_cell, index);
    file_level(level, boxes, by_level_[index]);
  }
  levels_.resize(used);
}

template <int D>
void BoxGrid<D>::file_level(Level& level, std::span<const Box<D>> boxes,
                            std::span<const int> objects) {
  const int m = static_cast<int>(objects.size());
  cells_.resize(m);
  Cell lo, hi;
  lo.fill(static_cast<std::int64_t>(kLimit));
  hi.fill(static_cast<std::int64_t>(-kLimit));
  for (int i = 0; i < m; ++i) {
    cells_[i] = cell_of(boxes[objects[i]].lo, level.inv_cell);
    for (int a = 0; a < D; ++a) {
      lo[a] = std::min(lo[a], cells_[i][a]);
      hi[a] = std::max(hi[a], cells_[i][a]);
    }
  }
  double range = 1.0;
  for (int a = 0; a < D; ++a) range *= static_cast<double>(hi[a] - lo[a] + 1);
  level.dense = range <= 8.0 * m + 64.0;
  cell_number_.resize(m);
  int num_cells = 0;
  if (level.dense) {
    level.min = lo;
    for (int a = 0; a < D; ++a) level.dims[a] = hi[a] - lo[a] + 1;
    num_cells = static_cast<int>(range);
    for (int i = 0; i < m; ++i) {
      std::int64_t linear = 0;
      for (int a = D - 1; a >= 0; --a) {
        linear = linear * level.dims[a] + (cells_[i][a] - level.min[a]);
      }
      cell_number_[i] = static_cast<int>(linear);
    }
  } else {
    std::size_t capacity = 16;
    while (capacity < 2 * static_cast<std::size_t>(m)) capacity *= 2;
    level.mask = capacity - 1;
    level.table_keys.assign(capacity, 0);
    level.table_cells.resize(capacity);
    for (int i = 0; i < m; ++i) {
      const std::uint64_t key = hash(cells_[i]);
      std::uint64_t slot = key & level.mask;
      while (level.table_keys[slot] != 0 && level.table_keys[slot] != key) {
        slot = (slot + 1) & level.mask;
      }
      if (level.table_keys[slot] == 0) {
        level.table_keys[slot] = key;
        level.table_cells[slot] = num_cells++;
      }
      cell_number_[i] = level.table_cells[slot];
    }
  }
  // Counting sort of the objects by cell, stable: index order within a cell.
  level.start.assign(num_cells + 1, 0);
  for (int i = 0; i < m; ++i) ++level.start[cell_number_[i] + 1];
  for (int c = 0; c < num_cells; ++c) level.start[c + 1] += level.start[c];
  level.items.resize(m);
  level.item_boxes.resize(m);
  for (int i = 0; i < m; ++i) {
    const int at = level.start[cell_number_[i]]++;
    level.items[at] = objects[i];
    level.item_boxes[at] = boxes[objects[i]];
  }
  for (int c = num_cells; c > 0; --c) level.start[c] = level.start[c - 1];
  level.start[0] = 0;
}

template class BoxGrid<2>;
template class BoxGrid<3>;

}  // namespace fosssim
