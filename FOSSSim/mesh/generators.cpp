#include "mesh/generators.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.h"

namespace fosssim {

namespace {

/// "a × b × c", for messages.
std::string sizes(std::initializer_list<int> counts) {
  std::string out;
  for (const int count : counts) out += (out.empty() ? "" : " × ") + std::to_string(count);
  return out;
}

/// A lattice of (nx+1)(ny+1)(nz+1) points with spacing h, lowest corner at `origin`, and the
/// Kuhn tets of the cubes `keep` accepts (by the cube's centre); unused points dropped.
template <typename Keep>
Mesh kuhn_lattice(int nx, int ny, int nz, const Eigen::Vector3d& spacing,
                  const Eigen::Vector3d& origin, Keep keep) {
  const auto lattice_index = [&](int ix, int iy, int iz) {
    return ix + (nx + 1) * (iy + (ny + 1) * iz);
  };
  const int num_points = (nx + 1) * (ny + 1) * (nz + 1);
  std::vector<int> compact(num_points, -1);
  Mesh mesh;
  const auto vertex = [&](int ix, int iy, int iz) {
    int& index = compact[lattice_index(ix, iy, iz)];
    if (index < 0) {
      index = mesh.num_vertices();
      mesh.vertices.push_back(origin + Eigen::Vector3d(ix, iy, iz).cwiseProduct(spacing));
    }
    return index;
  };
  constexpr std::array<std::array<int, 3>, 6> kAxisOrders = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int iz = 0; iz < nz; ++iz) {
    for (int iy = 0; iy < ny; ++iy) {
      for (int ix = 0; ix < nx; ++ix) {
        const Eigen::Vector3d centre =
            origin +
            (Eigen::Vector3d(ix, iy, iz) + Eigen::Vector3d::Constant(0.5)).cwiseProduct(spacing);
        if (!keep(centre)) continue;
        for (const auto& order : kAxisOrders) {
          std::array<int, 3> corner{ix, iy, iz};
          std::array<int, 4> tet;
          tet[0] = vertex(corner[0], corner[1], corner[2]);
          for (int step = 0; step < 3; ++step) {
            ++corner[order[step]];
            tet[step + 1] = vertex(corner[0], corner[1], corner[2]);
          }
          mesh.tets.push_back(tet);
          if (compute_tet_volume(mesh, tet) < 0.0)
            std::swap(mesh.tets.back()[2], mesh.tets.back()[3]);
        }
      }
    }
  }
  return mesh;
}

}  // namespace

const std::vector<int>* GeneratedMesh::find_pins(const std::string& name) const {
  for (const auto& [set_name, vertices] : pin_sets) {
    if (set_name == name) return &vertices;
  }
  return nullptr;
}

std::string GeneratedMesh::pin_set_names() const {
  std::string names;
  for (std::size_t k = 0; k < pin_sets.size(); ++k) {
    if (k > 0) names += k + 1 == pin_sets.size() ? " or " : ", ";
    names += pin_sets[k].first;
  }
  return names;
}

GeneratedMesh generate_cloth(int nx, int ny, double width, double height, bool horizontal,
                             bool bend, std::int64_t max_vertices) {
  check_vertex_count(saturating_product({nx, ny}), max_vertices,
                     "a cloth of " + sizes({nx, ny}) + " vertices");
  GeneratedMesh out;
  Mesh& mesh = out.mesh;
  const auto id = [nx](int r, int c) { return r * nx + c; };
  for (int r = 0; r < ny; ++r) {
    for (int c = 0; c < nx; ++c) {
      const double x = -0.5 * width + width * c / (nx - 1);
      const double along = height * r / (ny - 1);
      mesh.vertices.push_back(horizontal ? Eigen::Vector3d(x, 0.0, along)
                                         : Eigen::Vector3d(x, 0.0 - along, 0.0));
    }
  }
  for (int r = 0; r + 1 < ny; ++r) {
    for (int c = 0; c + 1 < nx; ++c) {
      mesh.faces.push_back({id(r, c), id(r + 1, c), id(r + 1, c + 1), id(r, c + 1)});
    }
  }
  if (bend) {
    for (int r = 0; r < ny; ++r) {
      for (int c = 0; c < nx; ++c) {
        if (c + 2 < nx) mesh.segments.push_back({id(r, c), id(r, c + 2)});
        if (r + 2 < ny) mesh.segments.push_back({id(r, c), id(r + 2, c)});
      }
    }
  }
  std::vector<int> top_row(nx), left_column(ny);
  for (int c = 0; c < nx; ++c) top_row[c] = id(0, c);
  for (int r = 0; r < ny; ++r) left_column[r] = id(r, 0);
  out.pin_sets = {{"corners", {id(0, 0), id(0, nx - 1)}},
                  {"top-row", top_row},
                  {"left-column", left_column},
                  {"none", {}}};
  out.default_pins = "corners";
  return out;
}

GeneratedMesh generate_chain(int links, double length, std::int64_t max_vertices) {
  check_vertex_count(std::int64_t{links} + 1, max_vertices,
                     "a chain of " + std::to_string(links) + " links");
  GeneratedMesh out;
  for (int k = 0; k <= links; ++k) out.mesh.vertices.emplace_back(length * k / links, 0.0, 0.0);
  for (int k = 0; k < links; ++k) out.mesh.segments.push_back({k, k + 1});
  out.pin_sets = {{"first", {0}}, {"ends", {0, links}}, {"none", {}}};
  out.default_pins = "first";
  return out;
}

GeneratedMesh generate_net(int nx, int ny, double width, double depth, std::int64_t max_vertices) {
  check_vertex_count(saturating_product({nx, ny}), max_vertices,
                     "a net of " + sizes({nx, ny}) + " vertices");
  GeneratedMesh out;
  Mesh& mesh = out.mesh;
  const auto id = [nx](int r, int c) { return r * nx + c; };
  std::vector<int> border;
  for (int r = 0; r < ny; ++r) {
    for (int c = 0; c < nx; ++c) {
      mesh.vertices.emplace_back(-0.5 * width + width * c / (nx - 1), 0.0,
                                 -0.5 * depth + depth * r / (ny - 1));
      if (c + 1 < nx) mesh.segments.push_back({id(r, c), id(r, c + 1)});
      if (r + 1 < ny) mesh.segments.push_back({id(r, c), id(r + 1, c)});
      if (r == 0 || c == 0 || r + 1 == ny || c + 1 == nx) border.push_back(id(r, c));
    }
  }
  out.pin_sets = {{"corners", {id(0, 0), id(0, nx - 1), id(ny - 1, 0), id(ny - 1, nx - 1)}},
                  {"border", border},
                  {"none", {}}};
  out.default_pins = "corners";
  return out;
}

GeneratedMesh generate_skirt(int segments, int rings, double top_radius, double bottom_radius,
                             double height, bool bend, std::int64_t max_vertices) {
  check_vertex_count(saturating_product({segments, rings}), max_vertices,
                     "a skirt of " + sizes({rings, segments}) + " vertices (rings × segments)");
  GeneratedMesh out;
  Mesh& mesh = out.mesh;
  const auto id = [segments](int ring, int k) { return ring * segments + (k % segments); };
  for (int ring = 0; ring < rings; ++ring) {
    const double t = static_cast<double>(ring) / (rings - 1);
    const double radius = (1.0 - t) * top_radius + t * bottom_radius;
    for (int k = 0; k < segments; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / segments;
      mesh.vertices.emplace_back(radius * std::cos(angle), -t * height, radius * std::sin(angle));
    }
  }
  for (int ring = 0; ring + 1 < rings; ++ring) {
    for (int k = 0; k < segments; ++k) {
      mesh.faces.push_back({id(ring, k), id(ring, k + 1), id(ring + 1, k + 1), id(ring + 1, k)});
    }
  }
  if (bend) {
    for (int ring = 0; ring < rings; ++ring) {
      for (int k = 0; k < segments; ++k) {
        mesh.segments.push_back({id(ring, k), id(ring, k + 2)});  // pairs are made unique later
        if (ring + 2 < rings) mesh.segments.push_back({id(ring, k), id(ring + 2, k)});
      }
    }
  }
  std::vector<int> top(segments);
  for (int k = 0; k < segments; ++k) top[k] = id(0, k);
  out.pin_sets = {{"top", top}, {"none", {}}};
  out.default_pins = "top";
  return out;
}

GeneratedMesh generate_tet_box(int nx, int ny, int nz, double size_x, double size_y, double size_z,
                               std::int64_t max_vertices) {
  check_vertex_count(
      saturating_product({nx + std::int64_t{1}, ny + std::int64_t{1}, nz + std::int64_t{1}}),
      max_vertices, "a tetbox of " + sizes({nx, ny, nz}) + " cubes");
  const Eigen::Vector3d size(size_x, size_y, size_z);
  GeneratedMesh out;
  out.mesh = kuhn_lattice(nx, ny, nz, size.cwiseQuotient(Eigen::Vector3d(nx, ny, nz)), -0.5 * size,
                          [](const Eigen::Vector3d&) { return true; });
  const double tiny = 1e-9 * size.maxCoeff();
  out.pin_sets = {{"none", {}},
                  {"bottom", select_extreme_vertices(out.mesh, 1, false, tiny)},
                  {"left", select_extreme_vertices(out.mesh, 0, false, tiny)}};
  out.default_pins = "none";
  return out;
}

GeneratedMesh generate_tet_ball(int cells, double radius, std::int64_t max_vertices) {
  // The lattice of (cells + 1)³ points is indexed whole, so it is what is counted.
  const std::int64_t points = cells + std::int64_t{1};
  check_vertex_count(saturating_product({points, points, points}), max_vertices,
                     "a tetball of " + std::to_string(cells) + " cells across");
  const double spacing = 2.0 * radius / cells;
  GeneratedMesh out;
  out.mesh = kuhn_lattice(
      cells, cells, cells, Eigen::Vector3d::Constant(spacing), Eigen::Vector3d::Constant(-radius),
      [radius](const Eigen::Vector3d& centre) { return centre.norm() <= radius; });
  out.pin_sets = {{"none", {}},
                  {"bottom", select_extreme_vertices(out.mesh, 1, false, 1e-9 * radius)}};
  out.default_pins = "none";
  return out;
}

}  // namespace fosssim
