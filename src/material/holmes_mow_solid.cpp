#include "biphasic/material/holmes_mow_solid.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "biphasic/material/neo_hookean.hpp"  // checked_jacobian

namespace biphasic {

LawDescription HolmesMowSolid::describe() {
  LawDescription d;
  d.name = "holmes_mow";
  d.summary =
      "Holmes & Mow 1990 as FEBio implements it, W = H_A/(4 beta) (exp(Q) - 1), stress free "
      "at F = I";
  d.parameters = {
      {"youngs_modulus", 1.0, ParameterBounds::above(0.0), "MPa",
       "Young's modulus E (small-strain limit)."},
      {"poissons_ratio", 0.2, ParameterBounds::between_open(-1.0, 0.5), "",
       "Poisson's ratio nu (small-strain limit)."},
      {"beta", 0.0, ParameterBounds::at_least(0.0), "",
       "Exponential stiffening coefficient beta, W = H_A/(4 beta) "
       "(exp(Q) - 1); beta = 0 is the limit W = q/4 (no stiffening)."},
  };
  return d;
}

namespace {

/// The left Cauchy–Green tensor b = FFᵀ with its invariants, and q, e^Q of the law.
struct Invariants {
  Mat3 b, b2;
  double I1, q, Q, eQ;
};

Invariants invariants(const HolmesMowSolid& law, const Mat3& F, double J) {
  const double lam = law.lambda(), mu = law.mu(), Ha = law.p_wave_modulus();
  Invariants v;
  v.b = F * F.transpose();
  v.b2 = v.b * v.b;
  v.I1 = v.b.trace();
  const double I2 = 0.5 * (v.I1 * v.I1 - v.b2.trace());
  v.q = (2.0 * mu - lam) * (v.I1 - 3.0) + lam * (I2 - 3.0) - Ha * 2.0 * std::log(J);
  v.Q = law.beta * v.q / Ha;
  v.eQ = std::exp(v.Q);
  return v;
}

/// τ = ½ e^Q [(2μ + λ(I₁ − 1)) b − λ b² − H_A 1].
Mat3 kirchhoff(const HolmesMowSolid& law, const Invariants& v) {
  const double lam = law.lambda(), mu = law.mu(), Ha = law.p_wave_modulus();
  return 0.5 * v.eQ * ((2.0 * mu + lam * (v.I1 - 1.0)) * v.b - lam * v.b2 - Ha * Mat3::Identity());
}

}  // namespace

double HolmesMowSolid::energy(const Mat3& F) const {
  const Invariants v = invariants(*this, F, checked_jacobian(F));
  if (beta == 0.0) return 0.25 * v.q;
  return p_wave_modulus() / (4.0 * beta) * std::expm1(v.Q);
}

Mat3 HolmesMowSolid::first_piola(const Mat3& F) const {
  const Invariants v = invariants(*this, F, checked_jacobian(F));
  return kirchhoff(*this, v) * F.inverse().transpose();
}

HolmesMowSolid::Response HolmesMowSolid::response(const Mat3& F, double J) const {
  const Invariants v = invariants(*this, F, J);
  const double lam = lambda(), Ha = p_wave_modulus();
  Response r;
  r.tau = kirchhoff(*this, v);
  const double gamma = 4.0 * beta / (Ha * v.eQ);
  const double el = v.eQ * lam, eh = 0.5 * v.eQ * Ha;
  const Mat3& b = v.b;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      Mat3& D = r.D[static_cast<std::size_t>(3 * i + k)];
      // γ τ_ij τ_kl + e^Q λ (b_ij b_kl − ½ b_ik b_jl − ½ b_il b_jk)
      D = gamma * r.tau.row(i).transpose() * r.tau.row(k) +
          el * (b.row(i).transpose() * b.row(k) - 0.5 * b(i, k) * b -
                0.5 * b.row(k).transpose() * b.row(i));
      // ½ e^Q H_A (δ_ik δ_jl + δ_il δ_jk) + δ_ik τ_jl
      D(k, i) += eh;
      if (i == k) D += eh * Mat3::Identity() + r.tau;
    }
  return r;
}

HolmesMowSolid::Response HolmesMowSolid::Response::with_pore_pressure(double pJ) const {
  Response r = *this;
  r.tau.diagonal().array() -= pJ;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      Mat3& Dik = r.D[static_cast<std::size_t>(3 * i + k)];
      Dik(i, k) -= pJ;
      Dik(k, i) += pJ;
    }
  return r;
}

}  // namespace biphasic
