#include "biphasic/material/neo_hookean.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>

namespace biphasic {

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
