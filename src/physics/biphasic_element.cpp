#include "biphasic/physics/biphasic_element.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace biphasic {

void biphasic_element(const std::vector<PointGeometry>& geometry, const ElementParameters& params,
                      const ElementVector& y, const ElementVector& ydot, bool with_jacobian,
                      ElementOutput& out) {
  using Mat10x3 = Eigen::Matrix<double, 10, 3>;
  using Mat4x3 = Eigen::Matrix<double, 4, 3>;
  const double mu = params.material.mu;
  const double lambda = params.material.lambda;
  const double k = params.permeability;
  const double ce = params.gls_c;
  const double beta_f = params.flux_beta;
  const double dt_c = params.volume_rate_dt;
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
    const Mat10x3 b = g.dN * Finv;  // b_a = F⁻ᵀ∇₀N_a = ∇ₓN_a
    const Mat4x3 e = g.dNp * Finv;  // e_c = ∇ₓN^p_c
    const double pq = g.Np.dot(p);
    const Vec3 gp = e.transpose() * p;        // ∇ₓp
    const Vec3 gpdot = e.transpose() * pdot;  // ∇ₓṗ
    const Mat3 L = Fdot * Finv;               // velocity gradient
    const double divv = L.trace();
    // Conservative form: the previous state uₙ = u − Δt u̇, Jₙ = det Fₙ, bₙ = F⁻ᵀₙ∇₀N.
    double Jn = 0.0;
    Mat10x3 bn_prev;
    if (conservative) {
      const Mat3 Fn = Mat3::Identity() + (u - dt_c * v) * g.dN;
      Jn = checked_jacobian(Fn);
      if (with_jacobian) bn_prev = g.dN * Fn.inverse();
    }
    const double Jdot = conservative ? (J - Jn) / dt_c : J * divv;
    const double beta = lambda * std::log(J) - mu - pq * J;
    const Mat3 P = mu * F + beta * FinvT;  // P_eff − pJF⁻ᵀ
    const double w = g.weight;

    // Momentum (+ GLS) rows.
    const Mat10x3 Ru = g.dN * P.transpose() + (ce * Jdot) * b;
    for (int a = 0; a < 10; ++a)
      for (int i = 0; i < 3; ++i) out.residual(3 * a + i) += w * Ru(a, i);
    // Mass rows.
    for (int c = 0; c < 4; ++c)
      out.residual(30 + c) += w * (g.Np(c) * Jdot + J * e.row(c).dot(k * gp + beta_f * gpdot));

    if (!with_jacobian) continue;

    const Eigen::Matrix<double, 10, 10> G = g.dN * g.dN.transpose();
    // ∂J̇/∂u_bk at fixed u̇: incremental J (div v · b_bk − (Lᵀ b_b)_k), (b L)_bk = (Lᵀ b_b)_k;
    // conservative (J b_bk − Jₙ bₙ_bk)/Δt.
    Mat10x3 dJdot;
    if (conservative)
      dJdot = (J * b - Jn * bn_prev) / dt_c;
    else
      dJdot = J * (divv * b - b * L);
    // ∂J̇/∂u̇_bk = Jv bv_bk: J b (incremental), Jₙ bₙ (conservative).
    const double Jv = conservative ? Jn : J;
    const Mat10x3& bv = conservative ? bn_prev : b;
    const double cp = lambda - pq * J;

    for (int a = 0; a < 10; ++a) {
      for (int bn = 0; bn < 10; ++bn) {
        for (int i = 0; i < 3; ++i) {
          for (int kk = 0; kk < 3; ++kk) {
            double kuu = cp * b(a, i) * b(bn, kk) - beta * b(bn, i) * b(a, kk);
            if (i == kk) kuu += mu * G(a, bn);
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
  }
}

}  // namespace biphasic
