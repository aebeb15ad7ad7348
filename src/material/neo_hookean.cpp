#include "biphasic/material/neo_hookean.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace biphasic {

LawDescription NeoHookean::describe() {
  LawDescription d;
  d.name = "neo_hookean";
  d.summary =
      "compressible Neo-Hookean, Psi = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2, the "
      "paper's law";
  d.parameters = {
      {"lambda", 0.2, ParameterBounds::any(), "MPa",
       "Lamé constant lambda; lambda + 2/3 mu must be > 0."},
      {"mu", 0.5, ParameterBounds::above(0.0), "MPa", "Shear modulus mu."},
  };
  d.check = [](const ParameterSource& p,
               const std::string& prefix) -> std::optional<ParameterProblem> {
    const double bulk_like = p("lambda") + 2.0 / 3.0 * p("mu");
    if (bulk_like > 0.0) return std::nullopt;
    std::array<char, 32> shown{};
    std::snprintf(shown.data(), shown.size(), "%.6g", bulk_like);
    return ParameterProblem{"lambda", prefix + "lambda + 2/3 " + prefix + "mu must be > 0 (here " +
                                          shown.data() + " MPa)"};
  };
  return d;
}

double checked_jacobian(const Mat3& F) {
  const double J = F.determinant();
  if (!(J > 0.0)) {
    throw std::domain_error("deformation gradient with det F = " + std::to_string(J) +
                            " (element inverted)");
  }
  return J;
}

double NeoHookean::energy(const Mat3& F) const {
  const double lnJ = std::log(checked_jacobian(F));
  return 0.5 * mu * ((F.transpose() * F).trace() - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
}

Mat3 NeoHookean::first_piola(const Mat3& F) const {
  const double lnJ = std::log(checked_jacobian(F));
  const Mat3 FinvT = F.inverse().transpose();
  return mu * (F - FinvT) + lambda * lnJ * FinvT;
}

Mat3 NeoHookean::tangent_apply(const Mat3& F, const Mat3& H) const {
  const double J = checked_jacobian(F);
  const Mat3 FinvT = F.inverse().transpose();
  const Tangent t = tangent(J);
  // Σ_kL A_iJkL H_kL = c₁ H_iJ + c₂ (F⁻ᵀ:H) F⁻ᵀ_iJ − c₃ (F⁻ᵀ Hᵀ F⁻ᵀ)_iJ
  return t.c1 * H + t.c2 * (FinvT.cwiseProduct(H).sum()) * FinvT -
         t.c3 * FinvT * H.transpose() * FinvT;
}

}  // namespace biphasic
