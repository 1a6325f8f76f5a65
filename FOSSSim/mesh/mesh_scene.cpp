#include "mesh/mesh_scene.h"

#include "core/forces/make_for_dim.h"
#include "core/forces/spring_set_force.h"
#include "core/text.h"

namespace fosssim {

namespace {

/// Particles drawn at this fraction of the mean spring length, edges at a third of it.
constexpr double kParticleRadiusPerLength = 0.15;
constexpr double kEdgeRadiusPerLength = 0.05;

}  // namespace

std::unique_ptr<Force> append_mesh(Scene& scene, const Mesh& mesh, const MeshMaterial& material,
                                   const std::vector<int>& pinned, const std::string& label) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  SceneModel& model = scene.model;
  const int dim = model.dim;
  const int n = mesh.num_vertices();
  if (dim == 2) {
    for (int v = 0; v < n; ++v) {
      if (mesh.vertices[v].z() != 0.0 || material.velocity.z() != 0.0) {
        fail("vertex " + std::to_string(v) + " has z = " + to_text(mesh.vertices[v].z()) +
             " (or the initial velocity has a z component), but the scene is 2D; use "
             "<scene dim=\"3\">");
      }
    }
  }
  const std::vector<double> masses = compute_vertex_masses(mesh, material.mass);
  for (int v : pinned) {
    if (v < 0 || v >= n) {
      fail("pinned vertex " + std::to_string(v) + " is out of range (the mesh has " +
           std::to_string(n) + " vertices, 0-based)");
    }
  }
  const auto pairs = compute_spring_pairs(mesh);
  std::vector<SpringTerm> springs;
  springs.reserve(pairs.size());
  const int first = model.num_particles();
  double total_length = 0.0;
  for (const auto& [a, b] : pairs) {
    const double length = (mesh.vertices[a] - mesh.vertices[b]).norm();
    if (length == 0.0) {
      fail("vertices " + std::to_string(a) + " and " + std::to_string(b) +
           " (0-based) coincide, so the spring between them has no direction");
    }
    springs.push_back({first + a, first + b, material.k, length, material.b});
    total_length += length;
  }

  // Particles.
  const int total = first + n;
  model.mass.conservativeResize(dim * total);
  scene.initial.q.conservativeResize(dim * total);
  scene.initial.v.conservativeResize(dim * total);
  for (int v = 0; v < n; ++v) {
    const int p = first + v;
    model.mass.segment(dim * p, dim).setConstant(masses[v]);
    scene.initial.q.segment(dim * p, dim) = mesh.vertices[v].head(dim);
    scene.initial.v.segment(dim * p, dim) = material.velocity.head(dim);
  }
  model.fixed.resize(total, false);
  for (int v : pinned) {
    model.fixed[first + v] = true;
    scene.initial.v.segment(dim * (first + v), dim).setZero();  // pins start at rest
  }
  scene.particle_tags.resize(total);

  // Edges and appearance.
  // The mean spring length sets the drawn sizes.
  const double length = springs.empty() ? 0.0 : total_length / static_cast<double>(springs.size());
  Appearance& look = scene.appearance;
  model.particle_radius.resize(total, kParticleRadiusPerLength * length);
  look.particle_color.resize(total, Appearance::kDefaultMeshColor);
  model.edge_collides.resize(model.edges.size(), true);
  for (const SpringTerm& s : springs) {
    model.edges.push_back({s.i, s.j});
    model.edge_collides.push_back(false);  // a mesh's springs are not collision capsules
    model.edge_radius.push_back(kEdgeRadiusPerLength * length);
    look.edge_color.push_back(Appearance::kDefaultEdgeColor);
  }
  auto add_triangles = [&](const std::vector<std::array<int, 3>>& triangles) {
    for (const auto& t : triangles)
      look.triangles.push_back({first + t[0], first + t[1], first + t[2]});
  };
  add_triangles(compute_face_triangles(mesh));
  const auto boundary = compute_tet_boundary(mesh);
  add_triangles(boundary);
  // Tet vertices off the boundary are inside the closed surface: pictures do not draw them.
  std::vector<bool> inside(n, false);
  for (const auto& tet : mesh.tets)
    for (int v : tet) inside[v] = true;
  for (const auto& face : boundary)
    for (int v : face) inside[v] = false;
  for (int v = 0; v < n; ++v)
    if (inside[v]) look.interior_particles.push_back(first + v);
  return make_for_dim<SpringSetForce>(dim, std::move(springs), label);
}

}  // namespace fosssim
