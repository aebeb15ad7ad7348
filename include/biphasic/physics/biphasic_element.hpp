// Element kernel of the finite-strain biphasic mixture (docs/formulation.md, the paper §2–3):
//   R_u = ∫Ω₀ ∇₀f : (P_eff − p J F⁻ᵀ) dX + ∫Ω₀ c_e(J) (F⁻ᵀ : ∇₀f) J̇ dX     (momentum + GLS)
//   R_p = ∫Ω₀ g J̇ dX + ∫Ω₀ k(J) J (F⁻ᵀ∇₀p)·(F⁻ᵀ∇₀g) dX                   (mass, Darcy)
// with J̇ = J F⁻ᵀ : ∇₀u̇ (incremental form) or, for backward Euler, J̇ = (J − Jₙ)/Δt with
// Jₙ = det(I + ∇₀uₙ), uₙ = u − Δt u̇ (conservative form, ElementCoefficients::volume_rate_dt > 0),
// and optionally the flux-perturbation stabilisation (Aguilar et al.
// 2008, FEBio's `tau`): w = −k∇ₓ(p + τṗ), i.e. R_p += ∫Ω₀ β J (F⁻ᵀ∇₀ṗ)·(F⁻ᵀ∇₀g) dX, β = kτ. Local
// unknowns: u of the 10 nodes (index 3a + i), then p of the 4 corners (index 30 + c). Units: u mm,
// p MPa, R_u N, R_p mm³/s. P_eff and its tangent come from a SolidLaw, k(J) and dk/dJ from a
// PermeabilityLaw (docs/model_layer.md); the kernel is a template over both.
#pragma once

#include <Eigen/Core>
#include <Eigen/Dense>
#include <vector>

#include "biphasic/material/constant_permeability.hpp"
#include "biphasic/material/neo_hookean.hpp"
#include "biphasic/material/permeability_law.hpp"
#include "biphasic/material/solid_law.hpp"
#include "biphasic/physics/element_geometry.hpp"

namespace biphasic {

inline constexpr int kElementDofs = 34;
using ElementVector = Eigen::Matrix<double, kElementDofs, 1>;
using ElementMatrix = Eigen::Matrix<double, kElementDofs, kElementDofs>;

/// The per-element coefficients of the stabilisations and of the volume rate.
struct ElementCoefficients {
  /// c_e = h²/(4k(1)) of the semidiscrete GLS term at the reference permeability [MPa s]; the
  /// kernel uses c_e k(1)/k(J) = h²/(4k(J)) at each quadrature point.
  double gls_c = 0.0;
  double flux_beta = 0.0;  ///< β = h²/(4 H_A) of the flux perturbation [mm⁴ N⁻¹]
  /// Δt [s] > 0: J̇ = (J − Jₙ)/Δt, uₙ = u − Δt u̇ (conservative); 0: J̇ = J F⁻ᵀ:∇₀u̇.
  double volume_rate_dt = 0.0;
};

/// The paper's material: a Neo-Hookean skeleton with constant permeability.
struct ElementParameters : ElementCoefficients {
  NeoHookean material;
  double permeability = 1e-3;  ///< k [mm⁴ N⁻¹ s⁻¹]
};

/// Local state: y = (u₀ₓ, u₀ᵧ, u₀𝓏, …, u₉𝓏, p₀, …, p₃) and its rate ẏ.
struct ElementOutput {
  ElementVector residual;
  ElementMatrix dfdy;     ///< ∂R/∂y
  ElementMatrix dfdydot;  ///< ∂R/∂ẏ
};

/// Evaluates the residual and, if `with_jacobian`, both Jacobian blocks.
/// Throws std::domain_error if det F ≤ 0 at a quadrature point (or a law refuses J).
template <SolidLaw Solid, PermeabilityLaw Permeability>
void biphasic_element(const std::vector<PointGeometry>& geometry, const Solid& solid,
                      const Permeability& permeability, const ElementCoefficients& coefficients,
                      const ElementVector& y, const ElementVector& ydot, bool with_jacobian,
                      ElementOutput& out);

/// The same for ElementParameters (Neo-Hookean, constant k).
void biphasic_element(const std::vector<PointGeometry>& geometry, const ElementParameters& params,
                      const ElementVector& y, const ElementVector& ydot, bool with_jacobian,
                      ElementOutput& out);

template <SolidLaw Solid, PermeabilityLaw Permeability>
void biphasic_element(const std::vector<PointGeometry>& geometry, const Solid& solid,
                      const Permeability& permeability, const ElementCoefficients& coefficients,
                      const ElementVector& y, const ElementVector& ydot, bool with_jacobian,
                      ElementOutput& out) {
  using Mat4x3 = Eigen::Matrix<double, 4, 3>;
  // GLS: c_e(J) = h²/(4 k(J)) = c_e,ref k(1)/k(J) at each quadrature point (docs/formulation.md,
  // "GLS with a strain-dependent permeability"); for a constant k the ratio is exactly 1.
  const double ce_ref = coefficients.gls_c;
  const double k_ref = ce_ref != 0.0 ? permeability.permeability(1.0) : 0.0;
  const double beta_f = coefficients.flux_beta;
  const double dt_c = coefficients.volume_rate_dt;
  const bool conservative = dt_c > 0.0;

  // Nodal displacement and velocity as 10 × 3, pressure as 4-vector.
  const Eigen::Map<const Eigen::Matrix<double, 3, 10>> u(y.data());
  const Eigen::Map<const Eigen::Matrix<double, 3, 10>> v(ydot.data());
  const Eigen::Vector4d p = y.tail<4>();
  const Eigen::Vector4d pdot = ydot.tail<4>();

  out.residual.setZero();
  if (with_jacobian) {
    out.dfdy.setZero();
    out.dfdydot.setZero();
  }

  for (const PointGeometry& g : geometry) {
    const Mat3 F = Mat3::Identity() + u * g.dN;  // F_iJ = δ_iJ + Σ_a u_ai ∂N_a/∂X_J
    const Mat3 Fdot = v * g.dN;
    const double J = checked_jacobian(F);
    const Mat3 Finv = F.inverse();
    const Mat3 FinvT = Finv.transpose();
    const ShapeGradients b = g.dN * Finv;  // b_a = F⁻ᵀ∇₀N_a = ∇ₓN_a
    const Mat4x3 e = g.dNp * Finv;         // e_c = ∇ₓN^p_c
    const double pq = g.Np.dot(p);
    const Vec3 gp = e.transpose() * p;        // ∇ₓp
    const Vec3 gpdot = e.transpose() * pdot;  // ∇ₓṗ
    const Mat3 L = Fdot * Finv;               // velocity gradient
    const double divv = L.trace();
    const double k = permeability.permeability(J);
    const double ce = ce_ref != 0.0 ? ce_ref * (k_ref / k) : 0.0;
    // Conservative form: the previous state uₙ = u − Δt u̇, Jₙ = det Fₙ, bₙ = F⁻ᵀₙ∇₀N.
    double Jn = 0.0;
    ShapeGradients bn_prev;
    if (conservative) {
      const Mat3 Fn = Mat3::Identity() + (u - dt_c * v) * g.dN;
      Jn = checked_jacobian(Fn);
      if (with_jacobian) bn_prev = g.dN * Fn.inverse();
    }
    const double Jdot = conservative ? (J - Jn) / dt_c : J * divv;
    // Stress and tangent of the mixture: the solid's P_eff − pJF⁻ᵀ.
    const auto stress = solid.response(F, J).with_pore_pressure(pq * J);
    const Mat3 P = stress.first_piola(F, FinvT);
    const double w = g.weight;

    // Momentum (+ GLS) rows.
    const ShapeGradients Ru = g.dN * P.transpose() + (ce * Jdot) * b;
    for (int a = 0; a < 10; ++a)
      for (int i = 0; i < 3; ++i) out.residual(3 * a + i) += w * Ru(a, i);
    // Mass rows.
    for (int c = 0; c < 4; ++c)
      out.residual(30 + c) += w * (g.Np(c) * Jdot + J * e.row(c).dot(k * gp + beta_f * gpdot));

    if (!with_jacobian) continue;

    const ShapeProducts G = g.dN * g.dN.transpose();
    // ∂J̇/∂u_bk at fixed u̇: incremental J (div v · b_bk − (Lᵀ b_b)_k), (b L)_bk = (Lᵀ b_b)_k;
    // conservative (J b_bk − Jₙ bₙ_bk)/Δt.
    ShapeGradients dJdot;
    if (conservative)
      dJdot = (J * b - Jn * bn_prev) / dt_c;
    else
      dJdot = J * (divv * b - b * L);
    // ∂J̇/∂u̇_bk = Jv bv_bk: J b (incremental), Jₙ bₙ (conservative).
    const double Jv = conservative ? Jn : J;
    const ShapeGradients& bv = conservative ? bn_prev : b;

    for (int a = 0; a < 10; ++a) {
      for (int bn = 0; bn < 10; ++bn) {
        for (int i = 0; i < 3; ++i) {
          for (int kk = 0; kk < 3; ++kk) {
            double kuu = stress.stiffness(b, G, a, i, bn, kk);
            kuu += ce * (-b(a, kk) * b(bn, i) * Jdot + b(a, i) * dJdot(bn, kk));
            out.dfdy(3 * a + i, 3 * bn + kk) += w * kuu;
            out.dfdydot(3 * a + i, 3 * bn + kk) += w * ce * Jv * b(a, i) * bv(bn, kk);
          }
        }
      }
      for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 3; ++i) out.dfdy(3 * a + i, 30 + c) -= w * g.Np(c) * J * b(a, i);
    }
    // Darcy flux and flux perturbation share one form: J (F⁻ᵀ∇₀q)·(F⁻ᵀ∇₀g), q = k p + β ṗ.
    const Vec3 gq = k * gp + beta_f * gpdot;
    for (int c = 0; c < 4; ++c) {
      const double ecgq = e.row(c).dot(gq);
      for (int bn = 0; bn < 10; ++bn) {
        const double bec = b.row(bn).dot(e.row(c));
        const double bgq = b.row(bn).dot(gq);
        for (int kk = 0; kk < 3; ++kk) {
          const double flux = J * (b(bn, kk) * ecgq - gq(kk) * bec - e(c, kk) * bgq);
          out.dfdy(30 + c, 3 * bn + kk) += w * (g.Np(c) * dJdot(bn, kk) + flux);
          out.dfdydot(30 + c, 3 * bn + kk) += w * g.Np(c) * Jv * bv(bn, kk);
        }
      }
      for (int d = 0; d < 4; ++d) {
        const double ee = J * e.row(c).dot(e.row(d));
        out.dfdy(30 + c, 30 + d) += w * k * ee;
        out.dfdydot(30 + c, 30 + d) += w * beta_f * ee;
      }
    }
    // k = k(J): the Darcy term J k (e_c·∇ₓp) gains J (e_c·∇ₓp) dk/dJ ∂J/∂u_bk, ∂J/∂u_bk = J b_bk;
    // the GLS term c_e(J) J̇ b_ai gains dc_e/dJ J̇ b_ai J b_bk, dc_e/dJ = −c_e (dk/dJ)/k.
    const double dk_dJ = permeability.permeability_derivative(J);
    if (dk_dJ != 0.0) {
      if (ce != 0.0) {
        const double s = -w * ce * (dk_dJ / k) * J * Jdot;
        for (int a = 0; a < 10; ++a)
          for (int i = 0; i < 3; ++i)
            for (int bn = 0; bn < 10; ++bn)
              for (int kk = 0; kk < 3; ++kk)
                out.dfdy(3 * a + i, 3 * bn + kk) += s * b(a, i) * b(bn, kk);
      }
      for (int c = 0; c < 4; ++c) {
        const double s = w * J * J * dk_dJ * e.row(c).dot(gp);
        for (int bn = 0; bn < 10; ++bn)
          for (int kk = 0; kk < 3; ++kk) out.dfdy(30 + c, 3 * bn + kk) += s * b(bn, kk);
      }
    }
  }
}

}  // namespace biphasic
