// FOSSSim runs the fast mass-springs assignment's JSON scenes as the assignment does: whole
// trajectories of meshes made here, compared with an independent reference solution
// (assignment_reference.h). Prints the largest difference on each scene:
//   build/release/tests/io3d/io3d_tests --gtest_filter='JsonAssignment.*'

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "assignment_reference.h"
#include "core/step/simulation.h"
#include "io/json_scene_reader.h"
#include "support/scratch_folder.h"

namespace fosssim {
namespace {

using testing::AssignmentReference;
using testing::ObjMesh;
using testing::ReferenceRules;

/// A scene of the assignment's format: a mesh, k, the 1-based pins "b" and maybe "m".
struct AssignmentScene {
  std::string name;
  ObjMesh mesh;
  double k;
  std::vector<int> pinned;
  std::optional<double> mass;
};

/// A flag: a grid of nx × ny vertices on a tilted plane, cells 0.1 m × 0.07 m (rectangles, so
/// the fanned quads give right triangles that are not isosceles), quads faces; vertex (r, c)
/// is r·nx + c, and the pole is column 0.
ObjMesh flag(int nx, int ny) {
  const Eigen::Vector3d along = 0.1 * Eigen::Vector3d(0.8, -0.6, 0.0);
  const Eigen::Vector3d up = 0.07 * Eigen::Vector3d(0.36, 0.48, -0.8);
  ObjMesh mesh;
  for (int r = 0; r < ny; ++r) {
    for (int c = 0; c < nx; ++c) mesh.vertices.push_back(c * along + r * up);
  }
  for (int r = 0; r + 1 < ny; ++r) {
    for (int c = 0; c + 1 < nx; ++c)
      mesh.faces.push_back({r * nx + c, (r + 1) * nx + c, (r + 1) * nx + c + 1, r * nx + c + 1});
  }
  return mesh;
}

/// Removes vertices on no face, renumbering the rest in order; returns old → new.
std::map<int, int> drop_unused_vertices(ObjMesh& mesh) {
  std::map<int, int> renumbered;
  for (const auto& face : mesh.faces)
    for (int v : face) renumbered[v] = 0;
  ObjMesh kept;
  for (auto& [old_index, new_index] : renumbered) {
    new_index = static_cast<int>(kept.vertices.size());
    kept.vertices.push_back(mesh.vertices[old_index]);
  }
  for (const auto& face : mesh.faces) {
    std::vector<int> corners;
    for (int v : face) corners.push_back(renumbered.at(v));
    kept.faces.push_back(corners);
  }
  mesh = kept;
  return renumbered;
}

/// A jittered 10 × 8 grid with a corner cut off and a hole: quads, triangles split along
/// either diagonal, and one hexagon, so that triangles of every shape (obtuse ones included),
/// polygons fanned from their first corner and an irregular boundary all occur. Returns the
/// mesh and, through `pins`, three vertices (1-based): two top corners and one inside.
ObjMesh irregular_patch(std::vector<int>& pins) {
  const int nx = 10, ny = 8;
  const auto id = [nx](int r, int c) { return r * nx + c; };
  std::uint32_t seed = 12345;
  const auto jitter = [&seed] {  // uniform in [-0.035, 0.035], reproducibly
    seed = seed * 1664525u + 1013904223u;
    return 0.07 * (static_cast<double>(seed >> 8) / 16777216.0 - 0.5);
  };
  ObjMesh mesh;
  for (int r = 0; r < ny; ++r) {
    for (int c = 0; c < nx; ++c) {
      mesh.vertices.emplace_back(0.1 * c + jitter(), -0.1 * r + jitter(),
                                 0.02 * std::sin(c) * std::cos(r));
    }
  }
  mesh.faces.push_back({id(1, 1), id(2, 1), id(2, 2), id(2, 3), id(1, 3), id(1, 2)});  // hexagon
  for (int r = 0; r + 1 < ny; ++r) {
    for (int c = 0; c + 1 < nx; ++c) {
      const bool hexagon = r == 1 && (c == 1 || c == 2);
      const bool cut = (r >= 5 && c >= 6) || (r == 3 && c == 4);
      if (hexagon || cut) continue;
      const int a = id(r, c), b = id(r + 1, c), d = id(r + 1, c + 1), e = id(r, c + 1);
      switch ((r + 2 * c) % 3) {
        case 0:
          mesh.faces.push_back({a, b, d, e});
          break;
        case 1:
          mesh.faces.push_back({a, b, d});
          mesh.faces.push_back({a, d, e});
          break;
        default:
          mesh.faces.push_back({a, b, e});
          mesh.faces.push_back({b, d, e});
      }
    }
  }
  const auto renumbered = drop_unused_vertices(mesh);
  pins = {renumbered.at(id(0, 0)) + 1, renumbered.at(id(0, nx - 1)) + 1,
          renumbered.at(id(3, 2)) + 1};
  return mesh;
}

/// Rows of flat obtuse triangles, then right triangles with legs 3/32 and 1/4 (exact in
/// binary, so the right angles are exact), then rectangles tilted out of the plane as quads.
ObjMesh strips() {
  ObjMesh mesh;
  const auto row = [&mesh](int count, double x0, double y, double z) {
    const int first = static_cast<int>(mesh.vertices.size());
    for (int i = 0; i < count; ++i) mesh.vertices.emplace_back(x0 + 0.25 * i, y, z);
    return first;
  };
  const int a = row(7, 0.0, 0.0, 0.0);
  const int b = row(6, 0.125, -0.0625, 0.0);
  const int c = row(6, 0.125, -0.15625, 0.0);
  const int d = row(6, 0.125, -0.3125, 0.0625);
  for (int i = 0; i < 6; ++i) mesh.faces.push_back({a + i, a + i + 1, b + i});  // obtuse at b
  for (int i = 0; i < 5; ++i) {
    mesh.faces.push_back({a + i + 1, b + i + 1, b + i});         // obtuse at a + i + 1
    mesh.faces.push_back({b + i, c + i, c + i + 1});             // right at c + i
    mesh.faces.push_back({b + i, c + i + 1, b + i + 1});         // right at b + i + 1
    mesh.faces.push_back({c + i, d + i, d + i + 1, c + i + 1});  // a rectangle
  }
  return mesh;
}

/// A horizontal net of 8 × 8 vertices 0.1 m apart whose springs are "f i j" lines along the
/// grid (no faces, so the masses must be given).
ObjMesh net() {
  const int n = 8;
  ObjMesh mesh;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      mesh.vertices.emplace_back(0.1 * c, 0.0, 0.1 * r);
      if (c + 1 < n) mesh.faces.push_back({r * n + c, r * n + c + 1});
      if (r + 1 < n) mesh.faces.push_back({r * n + c, (r + 1) * n + c});
    }
  }
  return mesh;
}

std::vector<AssignmentScene> assignment_scenes() {
  std::vector<AssignmentScene> scenes;
  std::vector<int> pole;
  for (int r = 0; r < 9; ++r) pole.push_back(r * 16 + 1);
  scenes.push_back({"flag, masses from areas", flag(16, 9), 5000.0, pole, std::nullopt});
  std::vector<int> patch_pins;
  ObjMesh patch = irregular_patch(patch_pins);
  scenes.push_back({"irregular patch, areas", patch, 3000.0, patch_pins, std::nullopt});
  scenes.push_back({"obtuse and right, areas", strips(), 2000.0, {1, 7}, std::nullopt});
  scenes.push_back({"net of f i j lines, m", net(), 5000.0, {1, 8, 57, 64}, 0.01});
  scenes.push_back({"flag, m given", flag(16, 9), 5000.0, {1, 129}, 0.002});
  return scenes;
}

/// The JSON scene text of the assignment's format around "mesh.obj".
std::string json_text(const AssignmentScene& scene) {
  std::string text = "{\"obj\": \"mesh.obj\", \"k\": " + std::to_string(scene.k) + ", \"b\": [";
  for (std::size_t p = 0; p < scene.pinned.size(); ++p)
    text += (p > 0 ? ", " : "") + std::to_string(scene.pinned[p]);
  text += "]";
  if (scene.mass) {
    char mass[64];
    std::snprintf(mass, sizeof mass, ", \"m\": %.17g", *scene.mass);
    text += mass;
  }
  return text + "}";
}

/// Number of the fanned triangles of the mesh's faces with an obtuse and a right angle (up to
/// a cosine of 1e-12, which round-off can put on either side).
std::pair<int, int> count_obtuse_and_right(const ObjMesh& mesh) {
  int obtuse = 0, right = 0;
  for (const auto& face : mesh.faces) {
    for (std::size_t j = 1; j + 1 < face.size(); ++j) {
      const std::array<int, 3> t{face[0], face[j], face[j + 1]};
      for (int corner = 0; corner < 3; ++corner) {
        const Eigen::Vector3d& x = mesh.vertices[t[corner]];
        const Eigen::Vector3d u = mesh.vertices[t[(corner + 1) % 3]] - x;
        const Eigen::Vector3d w = mesh.vertices[t[(corner + 2) % 3]] - x;
        const double cosine = u.dot(w) / (u.norm() * w.norm());
        obtuse += cosine < -1e-12;
        right += std::abs(cosine) <= 1e-12;
      }
    }
  }
  return {obtuse, right};
}

constexpr int kSteps = 300;  // 10 s

/// The largest distance of a vertex of FOSSSim's run from the reference's over kSteps steps,
/// relative to the rest mesh's bounding-box diagonal, for each of `rules`.
std::vector<double> largest_differences(const AssignmentScene& scene,
                                        const std::vector<ReferenceRules>& rules) {
  testing::ScratchFolder dir;
  dir.write("mesh.obj", obj_text(scene.mesh));
  const Scene loaded = load_json_scene_file(dir.write("scene.json", json_text(scene)));
  Simulation simulation(loaded.model, loaded.initial);
  std::deque<AssignmentReference> references;  // not movable: they hold their factors
  for (const ReferenceRules& rule : rules)
    references.emplace_back(scene.mesh, scene.k, scene.pinned, scene.mass, rule);
  std::vector<double> largest(rules.size(), 0.0);
  const int n = static_cast<int>(scene.mesh.vertices.size());
  for (int step = 0; step < kSteps; ++step) {
    simulation.step();
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> q(
        simulation.state().q.data(), n, 3);
    for (std::size_t r = 0; r < rules.size(); ++r) {
      references[r].step();
      const double distance = (q - references[r].positions()).rowwise().norm().maxCoeff();
      largest[r] = std::max(largest[r], distance / references[r].diagonal());
    }
  }
  return largest;
}

TEST(JsonAssignment, WholeTrajectoriesMatchAnIndependentReferenceToRoundOff) {
  const ReferenceRules exact;
  ReferenceRules thirds, inertial;
  thirds.voronoi_masses = false;
  inertial.start_current = false;
  std::printf(
      "\nFOSSSim's JSON scenes against the reference solution of the assignment, %d steps of "
      "1/30 s, 50 iterations each.\nLargest distance of a vertex from the reference's, relative "
      "to the bounding-box diagonal; the last two columns compare with the reference following\n"
      "other rules, to show that the check tells them apart (masses a third of each triangle; "
      "iterations starting at 2pⁿ - pⁿ⁻¹):\n\n",
      kSteps);
  std::printf("%-26s %8s %8s %8s %8s %11s  %11s %11s\n", "scene", "vertices", "springs", "obtuse",
              "right", "difference", "thirds", "inertial");
  for (const AssignmentScene& scene : assignment_scenes()) {
    const bool areas = !scene.mass.has_value();
    std::vector<ReferenceRules> rules{exact, inertial};
    if (areas) rules.push_back(thirds);
    const std::vector<double> largest = largest_differences(scene, rules);
    const auto [obtuse, right] = count_obtuse_and_right(scene.mesh);
    const AssignmentReference reference(scene.mesh, scene.k, scene.pinned, scene.mass);
    char thirds_text[32] = "-";
    if (areas) std::snprintf(thirds_text, sizeof thirds_text, "%.2e", largest[2]);
    std::printf("%-26s %8zu %8d %8d %8d %11.2e  %11s %11.2e\n", scene.name.c_str(),
                scene.mesh.vertices.size(), reference.num_springs(), obtuse, right, largest[0],
                thirds_text, largest[1]);
    EXPECT_LT(largest[0], 1e-11) << scene.name;
    EXPECT_GT(largest[1], 1e-5) << scene.name << ": the start should matter";
    if (areas) {
      EXPECT_GT(largest[2], 1e-4) << scene.name << ": the mass rule should matter";
    }
  }
  std::printf("\n");
}

TEST(JsonAssignment, TheMeshesExerciseEveryCase) {
  const auto scenes = assignment_scenes();
  const auto [patch_obtuse, patch_right] = count_obtuse_and_right(scenes[1].mesh);
  EXPECT_GT(patch_obtuse, 5);
  const auto [strip_obtuse, strip_right] = count_obtuse_and_right(scenes[2].mesh);
  EXPECT_GE(strip_obtuse, 11);
  EXPECT_GE(strip_right, 10);
  bool hexagon = false;
  for (const auto& face : scenes[1].mesh.faces) hexagon = hexagon || face.size() == 6;
  EXPECT_TRUE(hexagon);
  EXPECT_LT(scenes[1].mesh.vertices.size(), 80u) << "the cut corner's vertices are gone";
}

}  // namespace
}  // namespace fosssim
