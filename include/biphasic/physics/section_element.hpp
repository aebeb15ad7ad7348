// Element kernel of the two-dimensional models (plane strain, axisymmetric) on the Taylor–Hood
// P2/P1 triangle: the same weak form as the tetrahedron's (biphasic_element.hpp),
//   R_u = ∫Ω₀ (P_eff − p J F⁻ᵀ) : ∂F/∂u_d dX + ∫Ω₀ c_e(J) J̇ (F⁻ᵀ : ∂F/∂u_d) dX
//   R_p = ∫Ω₀ g J̇ dX + ∫Ω₀ J (F⁻ᵀ∇₀g)·(F⁻ᵀ∇₀q) dX,   q = k(J) p + β ṗ
// written for any displacement gradient that is linear in the nodal unknowns: each local
// displacement unknown d has a constant 3 × 3 direction B_d = ∂F/∂u_d. In plane strain
// B_(a,i) = e_i ⊗ ∇₀N_a; axisymmetric adds the hoop part (N_a/R) e_θ ⊗ e_Θ to i = r, so F is
// block diagonal (r, z | θ) with F_θΘ = 1 + u_r/R. With L_d = B_d F⁻¹ and β_d = tr L_d
// (∂J/∂u_d = J β_d):
//   ∂J̇/∂u_e = J (div v β_e − tr(L_v L_e)) (incremental, L_v = Ḟ F⁻¹)
//            = (J β_e − Jₙ βₙ_e)/Δt            (conservative, βₙ_e = tr(B_e Fₙ⁻¹))
//   ∂(F⁻ᵀ : B_d)/∂u_e = −tr(L_e L_d),   ∂(F⁻ᵀ∇₀g)/∂u_e = −L_eᵀ F⁻ᵀ∇₀g.
// The tangent ∂P/∂F of the mixture stress comes from the solid law's own stiffness() through
// unit reference gradients, on the five components (rR, rZ, zR, zZ, θΘ) F can have.
// Local unknowns: u of the 6 nodes (index 2a + i, i = 0: x or r, 1: y or z), then p of the 3
// corners (12 + c). Units: u mm, p MPa, R_u N, R_p mm³/s (per mm of thickness in plane
// strain, over the full circle when axisymmetric).
#pragma once

#include <Eigen/Core>
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "biphasic/material/neo_hookean.hpp"
#include "biphasic/material/permeability_law.hpp"
#include "biphasic/material/solid_law.hpp"
#include "biphasic/physics/biphasic_element.hpp"
#include "biphasic/physics/section_geometry.hpp"

namespace biphasic {

inline constexpr int kSectionElementDofs = 15;
using SectionElementVector = Eigen::Matrix<double, kSectionElementDofs, 1>;
using SectionElementMatrix = Eigen::Matrix<double, kSectionElementDofs, kSectionElementDofs>;

struct SectionElementOutput {
  SectionElementVector residual;
  SectionElementMatrix dfdy;     ///< ∂R/∂y
  SectionElementMatrix dfdydot;  ///< ∂R/∂ẏ
};

namespace section_detail {

/// The five entries of F that a section model can have, as (row, column) of the 3 × 3 matrix
/// in the order (x/r, y/z, θ).
inline constexpr std::array<std::array<int, 2>, 5> kComponents{
    {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 2}}};

/// ∂P_m/∂F_n of a law's point response on the five components: the law's stiffness() with
/// reference gradients e_J (so its b rows are the rows of F⁻¹ and G = I).
template <class Response>
Eigen::Matrix<double, 5, 5> tangent_on_section(const Response& response, const Mat3& Finv) {
  ShapeGradients b = ShapeGradients::Zero();
  b.topRows<3>() = Finv;
  ShapeProducts G = ShapeProducts::Zero();
  G.topLeftCorner<3, 3>().setIdentity();
  Eigen::Matrix<double, 5, 5> A;
  for (int m = 0; m < 5; ++m)
    for (int n = 0; n < 5; ++n)
      A(m, n) = response.stiffness(b, G, kComponents[m][1], kComponents[m][0], kComponents[n][1],
                                   kComponents[n][0]);
  return A;
}

}  // namespace section_detail

/// Evaluates the residual and, if `with_jacobian`, both Jacobian blocks of one triangle.
/// Throws std::domain_error if det F ≤ 0 at a quadrature point (or a law refuses J).
template <SolidLaw Solid, PermeabilityLaw Permeability>
void section_element(const std::vector<SectionPointGeometry>& geometry, const Solid& solid,
                     const Permeability& permeability, const ElementCoefficients& coefficients,
                     const SectionElementVector& y, const SectionElementVector& ydot,
                     bool with_jacobian, SectionElementOutput& out) {
  using section_detail::kComponents;
  constexpr int nu = 12;
  const double ce_ref = coefficients.gls_c;
  const double k_ref = ce_ref != 0.0 ? permeability.permeability(1.0) : 0.0;
  const double dt_c = coefficients.volume_rate_dt;
  const bool conservative = dt_c > 0.0;

  const Eigen::Map<const Eigen::Matrix<double, 2, 6>> u(y.data());
  const Eigen::Map<const Eigen::Matrix<double, 2, 6>> v(ydot.data());
  const Eigen::Vector3d p = y.tail<3>();
  const Eigen::Vector3d pdot = ydot.tail<3>();

  out.residual.setZero();
  if (with_jacobian) {
    out.dfdy.setZero();
    out.dfdydot.setZero();
  }

  // ∂F/∂u_d on the five components, and F of a nodal field w.
  Eigen::Matrix<double, 5, nu> B;
  auto deformation_gradient = [&](const SectionPointGeometry& g, const auto& w, bool affine) {
    Mat3 F = Mat3::Zero();
    if (affine) F.setIdentity();
    F.topLeftCorner<2, 2>() += w * g.dN;
    F(2, 2) += g.inverse_radius * w.row(0).dot(g.N.transpose());
    return F;
  };
  auto as_matrix = [](const auto& c5) {
    Mat3 M = Mat3::Zero();
    for (int m = 0; m < 5; ++m) M(kComponents[m][0], kComponents[m][1]) = c5(m);
    return M;
  };

  std::array<Mat3, nu> L, Ln;
  Eigen::Matrix<double, nu, 1> beta, beta_n;
  for (const SectionPointGeometry& g : geometry) {
    B.setZero();
    for (int a = 0; a < 6; ++a) {
      B(0, 2 * a) = g.dN(a, 0);
      B(1, 2 * a) = g.dN(a, 1);
      B(4, 2 * a) = g.inverse_radius * g.N(a);
      B(2, 2 * a + 1) = g.dN(a, 0);
      B(3, 2 * a + 1) = g.dN(a, 1);
    }
    const Mat3 F = deformation_gradient(g, u, true);
    const Mat3 Fdot = deformation_gradient(g, v, false);
    const double J = checked_jacobian(F);
    const Mat3 Finv = F.inverse();
    const Mat3 FinvT = Finv.transpose();
    const Mat3 Lv = Fdot * Finv;
    const double divv = Lv.trace();
    // Spatial gradients of the P1 functions e_c = F⁻ᵀ∇₀N^p_c (as rows), of p and of ṗ.
    Eigen::Matrix3d e;
    for (int c = 0; c < 3; ++c) e.row(c) = Eigen::RowVector3d(g.dNp(c, 0), g.dNp(c, 1), 0.0) * Finv;
    const double pq = g.Np.dot(p);
    const Vec3 gp = e.transpose() * p;
    const Vec3 gpdot = e.transpose() * pdot;
    const double k = permeability.permeability(J);
    const double dk_dJ = with_jacobian ? permeability.permeability_derivative(J) : 0.0;
    const PointStabilisation stab = point_stabilisation(coefficients, k_ref, k, dk_dJ);
    const double ce = stab.ce;
    const double beta_f = stab.beta;
    double Jn = 0.0;
    Mat3 Fn_inv = Mat3::Zero();
    if (conservative) {
      const Eigen::Matrix<double, 2, 6> un = u - dt_c * v;
      const Mat3 Fn = deformation_gradient(g, un, true);
      Jn = checked_jacobian(Fn);
      Fn_inv = Fn.inverse();
    }
    const double Jdot = conservative ? (J - Jn) / dt_c : J * divv;
    const auto stress = solid.response(F, J).with_pore_pressure(pq * J);
    const Mat3 P = stress.first_piola(F, FinvT);
    Eigen::Matrix<double, 5, 1> P5;
    for (int m = 0; m < 5; ++m) P5(m) = P(kComponents[m][0], kComponents[m][1]);
    for (int d = 0; d < nu; ++d) {
      const Mat3 Bd = as_matrix(B.col(d));
      L[d] = Bd * Finv;
      beta(d) = L[d].trace();
      if (conservative) {
        Ln[d] = Bd * Fn_inv;
        beta_n(d) = Ln[d].trace();
      }
    }
    const double w = g.weight;

    // Momentum (+ GLS) rows, then mass rows.
    out.residual.head<nu>() += w * (B.transpose() * P5 + (ce * Jdot) * beta);
    const Vec3 gq = k * gp + beta_f * gpdot;
    for (int c = 0; c < 3; ++c) out.residual(nu + c) += w * (g.Np(c) * Jdot + J * e.row(c).dot(gq));

    if (!with_jacobian) continue;

    const Eigen::Matrix<double, 5, 5> A = section_detail::tangent_on_section(stress, Finv);
    // ∂J̇/∂u_e and ∂J̇/∂u̇_e.
    Eigen::Matrix<double, nu, 1> dJdot, dJdot_rate;
    for (int d = 0; d < nu; ++d) {
      if (conservative) {
        dJdot(d) = (J * beta(d) - Jn * beta_n(d)) / dt_c;
        dJdot_rate(d) = Jn * beta_n(d);
      } else {
        dJdot(d) = J * (divv * beta(d) - (Lv * L[d]).trace());
        dJdot_rate(d) = J * beta(d);
      }
    }
    // Displacement–displacement: the tangent, the GLS term's dependence on u and on u̇.
    Eigen::Matrix<double, nu, nu> Kuu = B.transpose() * A * B;
    for (int d = 0; d < nu; ++d)
      for (int f = 0; f < nu; ++f)
        Kuu(d, f) += ce * (-(L[f] * L[d]).trace() * Jdot + beta(d) * dJdot(f));
    out.dfdy.topLeftCorner<nu, nu>() += w * Kuu;
    out.dfdydot.topLeftCorner<nu, nu>() += (w * ce) * beta * dJdot_rate.transpose();
    // Displacement–pressure: −∫ N^p_c J (F⁻ᵀ : B_d).
    out.dfdy.topRightCorner<nu, 3>() -= (w * J) * beta * g.Np.transpose();
    // Mass rows: J̇ and the flux J e_c·∇ₓq.
    for (int c = 0; c < 3; ++c) {
      const double ecgq = e.row(c).dot(gq);
      for (int f = 0; f < nu; ++f) {
        const double flux =
            J * (beta(f) * ecgq - e.row(c).dot(L[f] * gq) - e.row(c).dot(L[f].transpose() * gq));
        out.dfdy(nu + c, f) += w * (g.Np(c) * dJdot(f) + flux);
        out.dfdydot(nu + c, f) += w * g.Np(c) * dJdot_rate(f);
      }
      for (int dd = 0; dd < 3; ++dd) {
        const double ee = J * e.row(c).dot(e.row(dd));
        out.dfdy(nu + c, nu + dd) += w * k * ee;
        out.dfdydot(nu + c, nu + dd) += w * beta_f * ee;
      }
    }
    // k = k(J): ∂k/∂u_f = dk/dJ J β_f in the Darcy term, and likewise through c_e(J) and β(J)
    // (point_stabilisation) in the GLS and flux-perturbation terms.
    if (dk_dJ != 0.0) {
      if (stab.dce_dJ != 0.0)
        out.dfdy.topLeftCorner<nu, nu>() += (w * stab.dce_dJ * J * Jdot) * beta * beta.transpose();
      for (int c = 0; c < 3; ++c) {
        double s = w * J * J * dk_dJ * e.row(c).dot(gp);
        if (stab.dbeta_dJ != 0.0) s += w * J * J * stab.dbeta_dJ * e.row(c).dot(gpdot);
        out.dfdy.block<1, nu>(nu + c, 0) += s * beta.transpose();
      }
    }
  }
}

}  // namespace biphasic
