#pragma once

#include <array>
#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// Rest data of a constant strain triangle, computed once at load from its rest corners.
struct CstRest {
  /// B = D̄⁻¹ for the rest edge matrix D̄ = [x̄2 - x̄1 | x̄3 - x̄1] written in the rest
  /// triangle's own plane (in 2D, the plane's coordinates are x and y).
  Mat<2> B;
  double area = 0.0;  ///< Ā = ½ |(x̄3 - x̄1) × (x̄2 - x̄1)|
};

/// The rest data of the triangle with corners x̄1, x̄2, x̄3 (D = 2 or 3). In 3D the corners are
/// written in an orthonormal frame of their plane (first axis along x̄2 - x̄1), which leaves
/// every length and angle, and so the energy, unchanged. Ā is 0 for collinear corners.
template <int D>
CstRest compute_cst_rest(const Vec<D>& x1, const Vec<D>& x2, const Vec<D>& x3);

/// The course's Theme 4 constant strain triangle (CST), a linear finite element with the
/// plane-stress St Venant–Kirchhoff law (docs/forces.md, 'Elastic bodies'). Corners x1, x2, x3.
///
///   F = D B (D×2), D = [x2 - x1 | x3 - x1];  ε = FᵀF - I (the course's strain: no factor ½);
///   U = E Ā / (2(1 - ν²)) [εxx² + 2ν εxx εyy + εyy² + 2(1 - ν) εxy²].
///   With K = E Ā / (1 - ν²), S = [[εxx + ν εyy, (1 - ν) εxy], [(1 - ν) εxy, εyy + ν εxx]] and
///   G = 2K F S Bᵀ: ∇_{x2}U = G column 0, ∇_{x3}U = G column 1, ∇_{x1}U = -(both).
///   hessX = K [Σ_st C_st ∇ε_s ∇ε_tᵀ + Σ_s σ_s ∇²ε_s] (exact), C the plane-stress matrix
///   [[1, ν, 0], [ν, 1, 0], [0, 0, 2(1 - ν)]], σ = C ε; hessV = 0.
/// In 2D this is the course's element; in 3D the same formulas, with F a 3×2 matrix, make it a
/// membrane (FOSSSim's own). U depends only on FᵀF: it is invariant under rigid motions and
/// reflections, and finite for degenerate and inverted current triangles. hessX is indefinite
/// in general (compressed, squashed, inverted, or in 3D folded triangles); with
/// ForceInput::definite_hessian the whole 3D×3D element block is projected onto the positive
/// semi-definite matrices (its negative eigenvalues set to 0: core/forces/psd_projection.h).
template <int D>
class ElasticBodyCstForce final : public Force {
 public:
  /// i1, i2, i3: distinct particle indices; youngs_modulus: E > 0 (Pa, per unit thickness);
  /// poisson_ratio: ν in (-1, 1); rest: from compute_cst_rest, of positive area.
  ElasticBodyCstForce(std::array<int, 3> corners, double youngs_modulus, double poisson_ratio,
                      const CstRest& rest)
      : corners_(corners), E_(youngs_modulus), nu_(poisson_ratio), rest_(rest) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override;
  /// Local/global: explicit. The St. Venant-Kirchhoff energy of FᵀF - I is quartic in the
  /// positions, not the squared distance to a projection, so it has no constant matrix
  /// (docs/integrators.md, 'Local/global').
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kExplicit; }
  /// One triangle, its strain the principal stretch of largest magnitude, its density U / Ā.
  void append_elements(const Vector& q, std::vector<ForceElement>& elements) const override;

 private:
  /// F = D B of the current positions.
  Eigen::Matrix<double, D, 2> deformation_gradient(const Vector& q) const;

  std::array<int, 3> corners_;
  double E_, nu_;
  CstRest rest_;
};

/// Reads `elasticbodycstforce i1 i2 i3 youngsmodulus poissonratio [xb1x ... xb3y]` (in 3D also
/// xb1z, xb2z, xb3z); each rest coordinate defaults to the matching initial coordinate of the
/// matching particle. Rejects repeated indices, E ≤ 0, |ν| ≥ 1 and rest triangles of zero area;
/// warns for ν < 0 or ν > 0.5; ignores the handout's rest strain (ebxx, ebyy, ebxy) with a
/// warning.
std::unique_ptr<Force> make_elastic_body_cst_force(ForceParameters& params,
                                                   const ForceContext& context);

}  // namespace fosssim
