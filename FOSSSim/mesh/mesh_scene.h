#pragma once
// Turns a mesh into particles, edges and springs of a scene.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/force.h"
#include "core/scene.h"
#include "mesh/mesh.h"

namespace fosssim {

/// The physical parameters a scene gives a mesh.
struct MeshMaterial {
  double k = 0.0;  ///< stiffness of every spring, N/m
  double b = 0.0;  ///< damping of every spring, N·s/m
  MassRule mass;
  /// Initial velocity of every vertex that is not pinned (pinned vertices start at rest).
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
};

/// Appends the mesh to the scene: its vertices become particles (masses by material.mass,
/// fixed when listed in `pinned`, moving with material.velocity unless pinned), and each
/// of its spring pairs (compute_spring_pairs) an edge and a spring of rest length equal to its
/// initial length. The springs are returned as one SpringSetForce, labelled `label`, for the
/// caller to place in the force order. The appearance gets small particles and edges (scaled
/// by the mean spring length) and the surface triangles. In a 2D scene every vertex must have
/// z = 0. Throws Error (kBadInput) on a massless vertex, coincident spring ends, a pinned index
/// out of range, or z ≠ 0 in 2D, leaving the scene unchanged.
std::unique_ptr<Force> append_mesh(Scene& scene, const Mesh& mesh, const MeshMaterial& material,
                                   const std::vector<int>& pinned, const std::string& label);

}  // namespace fosssim
