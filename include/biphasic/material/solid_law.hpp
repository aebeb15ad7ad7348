// What the element kernel asks of a solid law of the skeleton (docs/model_layer.md).
//
// A solid law is a small value type with
//   p_wave_modulus()   the small-strain P-wave (oedometric) modulus H_A, λ + 2μ for an isotropic
//                      law [MPa]: the stiffness scale of row scaling, the flux perturbation
//                      β = h²/(4 H_A) and the pressure Schur approximation;
//   response(F, J)     the stress state at one point, J = det F > 0 given, which
//     .with_pore_pressure(pJ)  adds the pore-pressure part −pJ F⁻ᵀ of the mixture stress,
//     .first_piola(F, F⁻ᵀ)    gives the first Piola–Kirchhoff stress P [MPa], and
//     .stiffness(b, G, a, i, b', k)  the tangent contracted with shape gradients,
//          K = ∇₀N_a,J (∂P_iJ/∂F_kL) ∇₀N_b',L [MPa mm⁻²], in terms of the spatial gradients
//          b_a = F⁻ᵀ∇₀N_a (rows of b) and the reference products G_ab' = ∇₀N_a·∇₀N_b'.
// The kernel is a template over the law, so these calls inline; nothing is virtual.
#pragma once

#include <Eigen/Core>
#include <concepts>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

using ShapeGradients = Eigen::Matrix<double, 10, 3>;  ///< one row per P2 node
using ShapeProducts = Eigen::Matrix<double, 10, 10>;  ///< G_ab = ∇₀N_a·∇₀N_b

template <class Response>
concept SolidResponse = requires(const Response& r, const Mat3& F, const ShapeGradients& b,
                                 const ShapeProducts& G, int n) {
  { r.with_pore_pressure(1.0) } -> std::convertible_to<Response>;
  { r.first_piola(F, F) } -> std::convertible_to<Mat3>;
  { r.stiffness(b, G, n, n, n, n) } -> std::convertible_to<double>;
};

template <class Law>
concept SolidLaw = requires(const Law& law, const Mat3& F, double J) {
  { law.p_wave_modulus() } -> std::convertible_to<double>;
  requires SolidResponse<decltype(law.response(F, J))>;
};

}  // namespace biphasic
