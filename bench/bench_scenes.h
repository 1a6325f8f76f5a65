#pragma once
// The scenes the implicit-solver benchmark runs, built in code at any size.

#include <string_view>

#include "core/scene.h"
#include "mesh/mesh.h"

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

/// The stand-in for the CSC417 a2 coarse bunny (not in this repository; docs/solvers.md, "The
/// bunny"): a box of 5 × 13 × 7 cubes of 12 units, five tets each (alternating), 672
/// vertices, 2,275 tets and 3,328 springs (the bunny: 699, 2,274 and 3,521; mean spring count
/// per vertex 9.9 against 10.1), whose step matrix's LDLᵀ factor under AMD has about 116,000
/// non-zeros (the bunny's: 133,000; the 823-vertex tet ball's: 323,000); 16 bottom vertices
/// at one corner pinned (the bunny: 17), and the assignment's settings otherwise.
Scene bunny_stand_in(std::string_view integrator = "linearly-implicit-euler");

/// The CSC417 a2 assignment's settings on any tet mesh: springs on tet edges of 10⁵ N/m, 1 kg
/// per vertex, the vertices within `pin_within` of the lowest y pinned (the assignment's 3 units
/// on its bunny), gravity, h = 0.005 s.
Scene assignment_tet_scene(const Mesh& mesh, double pin_within,
                           std::string_view integrator = "linearly-implicit-euler");

/// A flag in the fast mass-springs assignment's conventions (its JSON scenes): an nx × ny
/// cloth hanging in the xy plane (2 m × 1 m, structural and shear springs of 20000 N/m,
/// 1 kg per vertex), its pole edge held by penalty pins of 10¹⁰ N/m, gravity as a force of
/// -9.8 N on every vertex, h = 1/30 s, 50 local/global iterations. 80 × 40 = 3,200 vertices.
Scene flag(int nx, int ny, std::string_view integrator = "local-global");

/// Sets an integrator option when the method has it.
void set_option(Scene& scene, std::string_view name, double value);
void set_option(Scene& scene, std::string_view name, std::string_view choice);

}  // namespace fosssim::bench
