#pragma once
// A hierarchical grid of axis-aligned boxes: which boxes overlap a given one, in time close to
// the number of boxes it overlaps (docs/collisions.md, "Broad phase").

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/types.h"

namespace fosssim {

/// An axis-aligned box, closed: lo ≤ hi on every axis for a non-empty box.
template <int D>
struct Box {
  Vec<D> lo, hi;

  bool overlaps(const Box& other) const {
    // Every comparison, without early exits: the outcome is hard to predict, branches cost more.
    bool all = true;
    for (int a = 0; a < D; ++a) {
      const bool below = lo[a] <= other.hi[a], above = other.lo[a] <= hi[a];
      all &= below & above;
    }
    return all;
  }
  bool contains(const Box& other) const {
    for (int a = 0; a < D; ++a) {
      if (!(lo[a] <= other.lo[a] && other.hi[a] <= hi[a])) return false;
    }
    return true;
  }
  /// The smallest box holding both.
  Box united(const Box& other) const { return {lo.cwiseMin(other.lo), hi.cwiseMax(other.hi)}; }
  /// The longest side.
  double extent() const { return (hi - lo).maxCoeff(); }
};

/// Boxes filed by size and place, for overlap queries (a hierarchical hashed grid, as in
/// Mirtich's and Eitz and Lixu's "hierarchical spatial hashing"). Level L has cubic cells of
/// side base_cell·2^L; each box is filed once, in the cell of its lower corner at the smallest
/// level where it spans at most two cells along every axis. A query at level L then looks at
/// the cells from one below the query box's lower corner to its upper corner, at most three
/// along each axis for a box no larger than the cells, or scans the level's boxes when that is
/// cheaper. A level stores its cells densely (an array over the cells' bounding range) when
/// that range is small, and in a hash table otherwise, so a few far-away boxes cost no memory.
/// Boxes too large (or not finite) for every level go to a list every query scans.
///
/// Exact in the sense that matters: cell coordinates are floor(x / cell) computed by one
/// multiplication and one floor, monotonic in x, and a box's level is chosen by checking the
/// cell coordinates it actually gets, so no overlap is lost to round-off.
template <int D>
class BoxGrid {
 public:
  /// Files boxes[k] as object k. `base_cell` > 0 is the side of level 0's cells; choose about
  /// the size of a typical box. Reuses the memory of the previous build.
  void build(std::span<const Box<D>> boxes, double base_cell);

  /// The level object k was filed at (kUnbounded for the list every query scans).
  int level_of(int object) const { return level_of_[object]; }
  static constexpr int kUnbounded = 64;

  /// Calls visit(k, box) for every object k filed, with its box: level by level, cell by cell,
  /// the unbounded list last. Neighbours in space come close together in this order, which keeps
  /// the queries of a sweep over all objects in cache.
  template <typename Visit>
  void for_each_filed(Visit&& visit) const {
    for (const Level& level : levels_) {
      for (std::size_t k = 0; k < level.items.size(); ++k) {
        visit(level.items[k], level.item_boxes[k]);
      }
    }
    for (std::size_t k = 0; k < unbounded_.size(); ++k) visit(unbounded_[k], unbounded_boxes_[k]);
  }

  /// Calls visit(k) once for every object k filed at a level ≥ min_level whose box overlaps
  /// `box` (closed boxes: touching counts), levels in increasing order; the unbounded list
  /// counts as level kUnbounded.
  template <typename Visit>
  void query(const Box<D>& box, int min_level, Visit&& visit) const {
    for (const Level& level : levels_) {
      if (level.index >= min_level) query_level(level, box, visit);
    }
    if (min_level > kUnbounded) return;
    for (std::size_t k = 0; k < unbounded_.size(); ++k) {
      if (unbounded_boxes_[k].overlaps(box)) visit(unbounded_[k]);
    }
  }

 private:
  using Cell = std::array<std::int64_t, D>;
  /// Cell coordinates are clamped to ±kLimit, which keeps them monotonic in x.
  static constexpr double kLimit = 1099511627776.0;  // 2^40

  struct Level {
    int index = 0;
    double inv_cell = 0.0;  // 1 / cell side
    bool dense = false;
    Cell min{}, dims{};                     // dense: the cells' bounding range
    std::vector<int> start;                 // per cell (dense) or per hashed cell: first item
    std::vector<int> items;                 // objects, by cell, in index order within a cell
    std::vector<Box<D>> item_boxes;         // their boxes, in the same order
    std::vector<std::uint64_t> table_keys;  // hashed: open addressing, key 0 = empty slot
    std::vector<int> table_cells;           // hashed: the cell number of each slot
    std::uint64_t mask = 0;
  };

  static std::int64_t coordinate(double x, double inv_cell) {
    const double c = x * inv_cell;
    if (!(c >= -kLimit)) return static_cast<std::int64_t>(-kLimit);  // NaN too
    if (c > kLimit) return static_cast<std::int64_t>(kLimit);
    // floor(c), without a call into the maths library: truncation, one down for negatives.
    const auto truncated = static_cast<std::int64_t>(c);
    return c < static_cast<double>(truncated) ? truncated - 1 : truncated;
  }
  static Cell cell_of(const Vec<D>& x, double inv_cell) {
    Cell c;
    for (int a = 0; a < D; ++a) c[a] = coordinate(x[a], inv_cell);
    return c;
  }
  static std::uint64_t hash(const Cell& c) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int a = 0; a < D; ++a) {
      h ^= static_cast<std::uint64_t>(c[a]) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h *= 0xbf58476d1ce4e5b9ull;
      h ^= h >> 31;
    }
    return h | 1;  // never 0, the empty slot
  }
  /// The cell's number in a hashed level, or -1 when no box is filed there.
  static int find_hashed(const Level& level, const Cell& c) {
    const std::uint64_t key = hash(c);
    for (std::uint64_t slot = key & level.mask;; slot = (slot + 1) & level.mask) {
      const std::uint64_t k = level.table_keys[slot];
      if (k == key) return level.table_cells[slot];
      if (k == 0) return -1;
    }
  }

  template <typename Visit>
  static void visit_cell(const Level& level, int cell, const Box<D>& box, Visit& visit) {
    for (int k = level.start[cell]; k < level.start[cell + 1]; ++k) {
      if (level.item_boxes[k].overlaps(box)) visit(level.items[k]);
    }
  }

  template <typename Visit>
  static void query_level(const Level& level, const Box<D>& box, Visit& visit) {
    // A level of a few boxes (the big objects of a scene) is scanned without finding cells.
    constexpr std::size_t kFew = D == 2 ? 9 : 27;  // no more than the cells a query visits
    if (level.items.size() <= kFew) {
      for (std::size_t k = 0; k < level.items.size(); ++k) {
        if (level.item_boxes[k].overlaps(box)) visit(level.items[k]);
      }
      return;
    }
    Cell lo = cell_of(box.lo, level.inv_cell), hi = cell_of(box.hi, level.inv_cell);
    double cells = 1.0;
    for (int a = 0; a < D; ++a) {
      lo[a] -= 1;  // a box filed one cell lower may reach into this one
      if (level.dense) {
        lo[a] = std::max(lo[a], level.min[a]);
        hi[a] = std::min(hi[a], level.min[a] + level.dims[a] - 1);
        if (hi[a] < lo[a]) return;
      }
      cells *= static_cast<double>(hi[a] - lo[a] + 1);
    }
    if (cells >= static_cast<double>(level.items.size())) {  // scanning is cheaper
      for (std::size_t k = 0; k < level.items.size(); ++k) {
        if (level.item_boxes[k].overlaps(box)) visit(level.items[k]);
      }
      return;
    }
    Cell c = lo;
    if (level.dense) {
      // Cells along the first axis are consecutive, and so are their objects: one run of
      // objects per row of cells.
      while (true) {
        std::int64_t linear = 0;
        for (int a = D - 1; a > 0; --a) linear = linear * level.dims[a] + (c[a] - level.min[a]);
        linear *= level.dims[0];
        const std::int64_t first = linear + (lo[0] - level.min[0]);
        const std::int64_t last = linear + (hi[0] - level.min[0]);
        for (int k = level.start[first]; k < level.start[last + 1]; ++k) {
          if (level.item_boxes[k].overlaps(box)) visit(level.items[k]);
        }
        int a = 1;
        for (; a < D; ++a) {
          if (++c[a] <= hi[a]) break;
          c[a] = lo[a];
        }
        if (a == D) break;
      }
      return;
    }
    while (true) {
      const int cell = find_hashed(level, c);
      if (cell >= 0) visit_cell(level, cell, box, visit);
      int a = 0;
      for (; a < D; ++a) {
        if (++c[a] <= hi[a]) break;
        c[a] = lo[a];
      }
      if (a == D) break;
    }
  }

  void file_level(Level& level, std::span<const Box<D>> boxes, std::span<const int> objects);

  std::vector<Level> levels_;  // non-empty levels, by index
  std::vector<int> level_of_;
  std::vector<int> unbounded_;
  std::vector<Box<D>> unbounded_boxes_;
  // Scratch of build().
  std::vector<std::vector<int>> by_level_;
  std::vector<Cell> cells_;
  std::vector<int> cell_number_;
};

}  // namespace fosssim
