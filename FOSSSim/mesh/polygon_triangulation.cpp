#include "mesh/polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "core/error.h"

namespace fosssim {

namespace {

using Point = Eigen::Vector2d;

/// Twice the signed area of (a, b, c).
double orient(const Point& a, const Point& b, const Point& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// Positive when d lies inside the circumcircle of the counter-clockwise triangle (a, b, c)
/// (the classic 3 × 3 determinant with coordinates relative to d).
double incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point ad = a - d, bd = b - d, cd = c - d;
  return ad.squaredNorm() * (bd.x() * cd.y() - bd.y() * cd.x()) +
         bd.squaredNorm() * (cd.x() * ad.y() - cd.y() * ad.x()) +
         cd.squaredNorm() * (ad.x() * bd.y() - ad.y() * bd.x());
}

int next(int k) { return k == 2 ? 0 : k + 1; }
int prev(int k) { return k == 0 ? 2 : k - 1; }

/// Triangles with their neighbours: nb[t][k] is the triangle across the side opposite corner k
/// of t, or -1 on the outline.
class Triangulation {
 public:
  explicit Triangulation(const std::vector<Point>& points) : p_(points) {}

  /// Ear clipping of the closed walk of point indices `walk` (the outline, or the outline
  /// joined to its holes by bridges: `bridged`).
  void clip_ears(const std::vector<int>& walk, bool bridged) {
    walk_ = walk;
    bridged_ = bridged;
    const int corners = static_cast<int>(walk.size());
    std::vector<int> before(corners), after(corners);
    for (int k = 0; k < corners; ++k) {
      before[k] = (k + corners - 1) % corners;
      after[k] = (k + 1) % corners;
    }
    int remaining = corners, cursor = 0, tried = 0;
    while (remaining > 3) {
      if (is_ear(before[cursor], cursor, after[cursor], after)) {
        tri_.push_back({walk_[before[cursor]], walk_[cursor], walk_[after[cursor]]});
        after[before[cursor]] = after[cursor];
        before[after[cursor]] = before[cursor];
        cursor = before[cursor];  // its corner changed: it may be an ear now
        --remaining;
        tried = 0;
      } else {
        cursor = after[cursor];
        if (++tried > remaining) {
          throw Error(ErrorKind::kBadInput,
                      "the polygon could not be triangulated (it has no ear: is it simple?)");
        }
      }
    }
    const int a = cursor, b = after[a], c = after[b];
    if (!(orient(at(a), at(b), at(c)) > 0.0)) {
      throw Error(ErrorKind::kBadInput,
                  "the polygon could not be triangulated (its last triangle is flat)");
    }
    tri_.push_back({walk_[a], walk_[b], walk_[c]});
  }

  /// Remembers which triangle holds each directed side, for cut_side.
  void index_sides() {
    for (int t = 0; t < static_cast<int>(tri_.size()); ++t) remember_sides(t);
  }

  /// Splits the outline side from `from` to `to` at `cuts` (in order from `from`), each cut
  /// dividing the one triangle on the remaining piece of the side in two.
  void cut_side(int from, int to, const std::vector<int>& cuts) {
    int start = from;
    for (const int cut : cuts) {
      const int t = side_triangle_.at({start, to});
      int k = 0;
      while (tri_[t][k] != start) ++k;
      const int w = tri_[t][prev(k)];  // the corner opposite the side
      tri_[t] = {start, cut, w};
      tri_.push_back({cut, to, w});
      remember_sides(t);
      remember_sides(static_cast<int>(tri_.size()) - 1);
      start = cut;
    }
  }

  /// Fills nb_ from the triangles' shared sides.
  void link() {
    std::map<std::pair<int, int>, std::pair<int, int>> directed;
    for (int t = 0; t < static_cast<int>(tri_.size()); ++t) {
      for (int k = 0; k < 3; ++k) directed[{tri_[t][next(k)], tri_[t][prev(k)]}] = {t, k};
    }
    nb_.assign(tri_.size(), {-1, -1, -1});
    for (int t = 0; t < static_cast<int>(tri_.size()); ++t) {
      for (int k = 0; k < 3; ++k) {
        const auto other = directed.find({tri_[t][prev(k)], tri_[t][next(k)]});
        if (other != directed.end()) nb_[t][k] = other->second.first;
      }
    }
  }

  /// Lawson flips over every inner side until none is illegal: the constrained Delaunay
  /// triangulation of the outline.
  void make_delaunay() {
    std::vector<std::pair<int, int>> stack;
    for (int t = 0; t < static_cast<int>(tri_.size()); ++t) {
      for (int k = 0; k < 3; ++k) {
        if (nb_[t][k] > t) stack.push_back({t, k});
      }
    }
    legalize(stack, true);
  }

  /// Inserts points[index], which lies strictly inside the triangulated polygon.
  void insert(int index) {
    const Point& x = p_[index];
    const auto [t, on_side] = locate(x);
    std::vector<std::pair<int, int>> stack;
    if (on_side < 0) {
      split_triangle(t, index, stack);
    } else {
      split_side(t, on_side, index, stack);
    }
    legalize(stack, false);
  }

  std::vector<std::array<int, 3>> triangles() && { return std::move(tri_); }

 private:
  /// The point at position k of the walk.
  const Point& at(int k) const { return p_[walk_[k]]; }

  /// Corner i between h and j (positions in the walk) is a strictly convex corner whose
  /// triangle holds no other remaining vertex (on its sides included). Without bridges only
  /// corners that are not strictly convex are tested: only they can lie in an ear (a convex one
  /// would make a side cross the ear). That argument is made for simple polygons; a walk with
  /// bridges is only weakly simple, so there every vertex is tested but the other appearances
  /// of h, i and j, which sit on the ear's corners (docs/forces.md, 'Polygon triangulation').
  bool is_ear(int h, int i, int j, const std::vector<int>& after) const {
    if (!(orient(at(h), at(i), at(j)) > 0.0)) return false;
    int before = j;
    for (int k = after[j]; k != h; k = after[k]) {
      const int following = after[k];
      const bool convex = orient(at(before), at(k), at(following)) > 0.0;
      before = k;
      if (bridged_) {
        if (walk_[k] == walk_[h] || walk_[k] == walk_[i] || walk_[k] == walk_[j]) continue;
      } else if (convex) {
        continue;
      }
      if (orient(at(h), at(i), at(k)) >= 0.0 && orient(at(i), at(j), at(k)) >= 0.0 &&
          orient(at(j), at(h), at(k)) >= 0.0)
        return false;
    }
    return true;
  }

  /// The triangle holding x and, when x is exactly on one of its sides, the corner opposite
  /// that side (else -1): a walk from the last triangle made, towards x; if the walk meets the
  /// outline (the polygon need not be convex) or goes on too long, every triangle is tried.
  std::pair<int, int> locate(const Point& x) const {
    int t = static_cast<int>(tri_.size()) - 1;
    for (std::size_t step = 0; step <= tri_.size(); ++step) {
      int across = -1;
      for (int k = 0; k < 3 && across < 0; ++k) {
        if (orient(p_[tri_[t][next(k)]], p_[tri_[t][prev(k)]], x) < 0.0) across = k;
      }
      if (across < 0) return {t, side_under(t, x)};
      t = nb_[t][across];
      if (t < 0) break;
    }
    for (int s = 0; s < static_cast<int>(tri_.size()); ++s) {
      bool inside = true;
      for (int k = 0; k < 3; ++k)
        inside = inside && orient(p_[tri_[s][next(k)]], p_[tri_[s][prev(k)]], x) >= 0.0;
      if (inside) return {s, side_under(s, x)};
    }
    throw Error(ErrorKind::kBadInput, "an interior point of the polygon lies outside it");
  }

  /// The corner of t opposite the side x lies on, or -1.
  int side_under(int t, const Point& x) const {
    for (int k = 0; k < 3; ++k) {
      if (orient(p_[tri_[t][next(k)]], p_[tri_[t][prev(k)]], x) == 0.0) return k;
    }
    return -1;
  }

  /// In triangle s, the neighbour that pointed to `from` now points to `to`.
  void relink(int s, int from, int to) {
    if (s < 0) return;
    for (int k = 0; k < 3; ++k) {
      if (nb_[s][k] == from) nb_[s][k] = to;
    }
  }

  /// Splits triangle t = (a, b, c) at p into (p, a, b), (p, b, c), (p, c, a).
  void split_triangle(int t, int p, std::vector<std::pair<int, int>>& stack) {
    const auto [a, b, c] = tri_[t];
    const auto [na, nb, nc] = nb_[t];
    const int t1 = static_cast<int>(tri_.size()), t2 = t1 + 1;
    tri_[t] = {p, a, b};
    nb_[t] = {nc, t1, t2};
    tri_.push_back({p, b, c});
    nb_.push_back({na, t2, t});
    tri_.push_back({p, c, a});
    nb_.push_back({nb, t, t1});
    relink(na, t, t1);
    relink(nb, t, t2);
    for (const int s : {t, t1, t2}) stack.push_back({s, 0});
  }

  /// Splits the side of t opposite corner k, which holds p, and the two triangles beside it
  /// into four, each with p first.
  void split_side(int t, int k, int p, std::vector<std::pair<int, int>>& stack) {
    const int u = nb_[t][k];
    if (u < 0) throw Error(ErrorKind::kBadInput, "an interior point of the polygon is on it");
    const int a = tri_[t][k], b = tri_[t][next(k)], c = tri_[t][prev(k)];
    const int ntb = nb_[t][next(k)], ntc = nb_[t][prev(k)];  // across (c, a) and (a, b)
    int m = 0;
    while (tri_[u][m] == b || tri_[u][m] == c) ++m;
    const int d = tri_[u][m];                                // u = (d, c, b)
    const int nuc = nb_[u][next(m)], nub = nb_[u][prev(m)];  // across (b, d) and (d, c)
    const int t2 = static_cast<int>(tri_.size()), u2 = t2 + 1;
    tri_[t] = {p, a, b};
    nb_[t] = {ntc, u2, t2};
    tri_.push_back({p, c, a});
    nb_.push_back({ntb, t, u});
    tri_[u] = {p, d, c};
    nb_[u] = {nub, t2, u2};
    tri_.push_back({p, b, d});
    nb_.push_back({nuc, u, t});
    relink(ntb, t, t2);
    relink(nuc, u, u2);
    for (const int s : {t, t2, u, u2}) stack.push_back({s, 0});
  }

  /// The side opposite corner k of t should be flipped: the far corner d of its neighbour is
  /// inside t's circumcircle by more than round-off and the quadrilateral is strictly convex.
  bool should_flip(int t, int k) const {
    const int u = nb_[t][k];
    if (u < 0) return false;
    const Point& a = p_[tri_[t][k]];
    const Point& b = p_[tri_[t][next(k)]];
    const Point& c = p_[tri_[t][prev(k)]];
    const Point& d = p_[far_corner(t, k)];
    const double size = std::max({(a - d).cwiseAbs().maxCoeff(), (b - d).cwiseAbs().maxCoeff(),
                                  (c - d).cwiseAbs().maxCoeff()});
    const double tolerance = 1e-12 * size * size * size * size;
    return incircle(a, b, c, d) > tolerance && orient(a, b, d) > 0.0 && orient(a, d, c) > 0.0;
  }

  /// The corner of t's neighbour across the side opposite corner k that is not on that side.
  int far_corner(int t, int k) const {
    const int u = nb_[t][k];
    const int b = tri_[t][next(k)], c = tri_[t][prev(k)];
    for (const int v : tri_[u]) {
      if (v != b && v != c) return v;
    }
    return -1;  // not reached: u shares exactly the side (b, c) with t
  }

  /// Flips the side opposite corner k of t = (a, b, c), whose neighbour is u = (d, c, b):
  /// t becomes (a, b, d) and u becomes (a, d, c).
  void flip(int t, int k) {
    const int u = nb_[t][k];
    const int a = tri_[t][k], b = tri_[t][next(k)], c = tri_[t][prev(k)];
    int m = 0;
    while (tri_[u][m] == b || tri_[u][m] == c) ++m;
    const int d = tri_[u][m];
    const int nta = nb_[t][next(k)], ntb = nb_[t][prev(k)];  // across (c, a) and (a, b)
    const int nub = nb_[u][next(m)], nuc = nb_[u][prev(m)];  // across (b, d) and (d, c)
    tri_[t] = {a, b, d};
    nb_[t] = {nub, u, ntb};
    tri_[u] = {a, d, c};
    nb_[u] = {nuc, nta, t};
    relink(nub, u, t);
    relink(nta, t, u);
  }

  /// Flips sides from the stack while they are illegal. After a flip, the two sides opposite
  /// the kept corner are checked (all four outer sides with all_sides, for the pass over a
  /// whole triangulation). Stops, leaving a valid triangulation, after a generous number of
  /// flips, in case round-off ever made flips cycle.
  void legalize(std::vector<std::pair<int, int>>& stack, bool all_sides) {
    const double cap = 100.0 * static_cast<double>(tri_.size()) * static_cast<double>(tri_.size());
    double flips = 0.0;
    while (!stack.empty() && flips < cap) {
      const auto [t, k] = stack.back();
      stack.pop_back();
      if (!should_flip(t, k)) continue;
      const int u = nb_[t][k];
      flip(t, k);
      flips += 1.0;
      stack.push_back({t, 0});
      stack.push_back({u, 0});
      if (all_sides) {
        stack.push_back({t, 2});
        stack.push_back({u, 1});
      }
    }
  }

  const std::vector<Point>& p_;
  std::vector<std::array<int, 3>> tri_;
  std::vector<std::array<int, 3>> nb_;
  std::map<std::pair<int, int>, int> side_triangle_;  // directed side -> triangle, for cutting
  std::vector<int> walk_;  // the walk being clipped: point indices, bridge ends twice
  bool bridged_ = false;

  void remember_sides(int t) {
    for (int k = 0; k < 3; ++k) side_triangle_[{tri_[t][k], tri_[t][next(k)]}] = t;
  }
};

/// Strictly inside the polygon's angle at corner v, whose sides come from `from` and go to `to`
/// with the polygon on their left: the direction from v to x, off both sides.
bool inside_polygon_corner(const Point& from, const Point& v, const Point& to, const Point& x) {
  const double first = orient(from, v, x), second = orient(v, to, x);
  if (orient(from, v, to) >= 0.0) return first > 0.0 && second > 0.0;  // convex or straight
  return first > 0.0 || second > 0.0;  // reflex: all but the closed outside wedge
}

/// A loop of corners: points first .. first + count - 1, in order.
struct PolygonLoop {
  int first = 0;
  int count = 0;
  int corner(int k) const { return first + (k % count + count) % count; }
};

/// The outline (loops[0]) joined to the holes (loops[1 ..]) by bridges, as one closed walk of
/// point indices (polygon_triangulation.h, step 0). Throws Error when a hole has no bridge.
class HoleBridges {
 public:
  HoleBridges(const std::vector<Point>& points, std::vector<PolygonLoop> loops)
      : p_(points), loops_(std::move(loops)), merged_(loops_.size(), 0) {
    for (int k = 0; k < loops_[0].count; ++k) walk_.push_back(loops_[0].corner(k));
    merged_[0] = 1;
  }

  std::vector<int> join() && {
    std::vector<int> order;
    for (int h = 1; h < static_cast<int>(loops_.size()); ++h) order.push_back(h);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return p_[rightmost(a)].x() > p_[rightmost(b)].x(); });
    for (const int h : order) join_hole(h);
    return std::move(walk_);
  }

 private:
  /// The corner of loop h of largest x (the first of them in the loop's order).
  int rightmost(int h) const {
    int best = loops_[h].first;
    for (int k = 1; k < loops_[h].count; ++k) {
      if (p_[loops_[h].corner(k)].x() > p_[best].x()) best = loops_[h].corner(k);
    }
    return best;
  }

  /// Splices hole h into the walk through a bridge from its rightmost corner m to the nearest
  /// point of the walk (ties: the smaller index) that sees it.
  void join_hole(int h) {
    const PolygonLoop& hole = loops_[h];
    const int m = rightmost(h);
    const int km = m - hole.first;
    const Point& pm = p_[m];
    // Candidates nearest first, from a heap: most holes take the first or second.
    std::vector<std::pair<double, int>> heap;
    for (const int v : walk_) heap.push_back({(p_[v] - pm).squaredNorm(), v});
    const auto later = [](const std::pair<double, int>& a, const std::pair<double, int>& b) {
      return a > b;
    };
    std::make_heap(heap.begin(), heap.end(), later);
    int last = -1;
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), later);
      const int v = heap.back().second;
      heap.pop_back();
      if (v == last) continue;  // a bridge's end appears twice
      last = v;
      if (!inside_polygon_corner(p_[hole.corner(km - 1)], pm, p_[hole.corner(km + 1)], p_[v]))
        continue;
      const int at = seeing_position(v, m);
      if (at < 0 || !clear(v, m)) continue;
      std::vector<int> inserted;
      for (int k = 0; k <= hole.count; ++k) inserted.push_back(hole.corner(km + k));
      inserted.push_back(v);
      walk_.insert(walk_.begin() + at + 1, inserted.begin(), inserted.end());
      merged_[h] = 1;
      return;
    }
    throw Error(ErrorKind::kBadInput,
                "a hole could not be joined to the outline (no corner sees its corner " +
                    std::to_string(km) + ")");
  }

  /// The position in the walk of the appearance of point v whose angle holds the direction to
  /// point m strictly, or -1.
  int seeing_position(int v, int m) const {
    const int n = static_cast<int>(walk_.size());
    for (int k = 0; k < n; ++k) {
      if (walk_[k] != v) continue;
      if (inside_polygon_corner(p_[walk_[(k + n - 1) % n]], p_[v], p_[walk_[(k + 1) % n]], p_[m]))
        return k;
    }
    return -1;
  }

  /// The segment from v to m meets no side of the walk or of a hole not yet joined, apart from
  /// the sides that end at v or m (which the corner tests keep off it).
  bool clear(int v, int m) const {
    const auto blocks = [&](int a, int b) {
      if (a == v || a == m || b == v || b == m) return false;
      return closed_segments_meet(p_[v], p_[m], p_[a], p_[b]);
    };
    const int n = static_cast<int>(walk_.size());
    for (int k = 0; k < n; ++k) {
      if (blocks(walk_[k], walk_[(k + 1) % n])) return false;
    }
    for (std::size_t h = 1; h < loops_.size(); ++h) {
      if (merged_[h]) continue;
      for (int k = 0; k < loops_[h].count; ++k) {
        if (blocks(loops_[h].corner(k), loops_[h].corner(k + 1))) return false;
      }
    }
    return true;
  }

  const std::vector<Point>& p_;
  std::vector<PolygonLoop> loops_;
  std::vector<char> merged_;
  std::vector<int> walk_;
};

}  // namespace

bool closed_segments_meet(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  const auto on = [](const Point& p, const Point& q, const Point& x) {
    return x.x() >= std::min(p.x(), q.x()) && x.x() <= std::max(p.x(), q.x()) &&
           x.y() >= std::min(p.y(), q.y()) && x.y() <= std::max(p.y(), q.y());
  };
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
         (o4 == 0 && on(c, d, b));
}

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector2d>& points,
                                                    const std::vector<int>& loop_corners,
                                                    const std::vector<int>& cuts_per_side) {
  std::vector<PolygonLoop> loops;
  int corners = 0;
  for (const int count : loop_corners) {
    loops.push_back({corners, count});
    corners += count;
  }
  std::vector<int> walk;
  if (loops.size() == 1) {
    for (int k = 0; k < corners; ++k) walk.push_back(k);
  } else {
    walk = HoleBridges(points, loops).join();
  }
  Triangulation mesh(points);
  mesh.clip_ears(walk, loops.size() > 1);
  mesh.index_sides();
  int point = corners, side = 0;
  for (const PolygonLoop& loop : loops) {
    for (int k = 0; k < loop.count; ++k, ++side) {
      std::vector<int> cuts(cuts_per_side[side]);
      for (int& cut : cuts) cut = point++;
      mesh.cut_side(loop.corner(k), loop.corner(k + 1), cuts);
    }
  }
  mesh.link();
  mesh.make_delaunay();
  for (; point < static_cast<int>(points.size()); ++point) mesh.insert(point);
  return std::move(mesh).triangles();
}

}  // namespace fosssim
