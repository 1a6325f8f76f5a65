#pragma once
// The scenes the implicit-solver benchmark runs, built in code at any size.

#include <string_view>

#include "core/scene.h"

namespace fosssim::bench {

/// Liu et al. 2013's cloth at any resolution: a flat 1 m square of nx × nx vertices lying in
/// the xz plane, 1 kg, structural, shear and bend springs of k N/m, held at two corners, in
/// gravity, h = 1/30 s. nx = 81 is the paper's (6,561 vertices, 19,677 free unknowns).
Scene cloth_3d(int nx, std::string_view integrator, double k = 1000.0);

/// A 2D damped cloth: nx × nx particles hanging in the plane from the two corners of the top
/// row, 1 kg, structural and shear springs of 1000 N/m damped with 0.5 N·s/m (non-symmetric
/// step matrices), gravity, h = 0.01 s, the course's linearized implicit Euler by default.
Scene damped_cloth_2d(int nx, std::string_view integrator = "linearized-implicit-euler");

/// The stand-in for the CSC417 a2 bunny (a 699-vertex tet mesh, not in this repository): a
/// tetrahedralized ball of radius 1 with `cells` cubes across (10 gives 823 vertices, 4,614
/// springs), the assignment's settings: springs on tet edges of 10⁵ N/m, 1 kg per vertex,
/// the vertices within 1e-3 of the lowest y pinned, gravity, h = 0.005 s, linearly implicit
/// Euler.
Scene tet_ball(int cells, std::string_view integrator = "linearly-implicit-euler");

/// A flag in the fast mass-springs assignment's conventions (its JSON scenes): an nx × ny
/// cloth hanging in the xy plane (2 m × 1 m, structural and shear springs of 20000 N/m,
/// 1 kg per vertex), its pole edge held by penalty pins of 10¹⁰ N/m, gravity as a force of
/// -9.8 N on every vertex, h = 1/30 s, 50 local/global iterations. 80 × 40 = 3,200 vertices.
Scene flag(int nx, int ny, std::string_view integrator = "local-global");

/// Sets an integrator option when the method has it.
void set_option(Scene& scene, std::string_view name, double value);
void set_option(Scene& scene, std::string_view name, std::string_view choice);

}  // namespace fosssim::bench
