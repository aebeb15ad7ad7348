#include "biphasic/analytic/holmes_mow_uniaxial.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "numerics.hpp"

namespace biphasic::analytic {

namespace {

struct Lame {
  double lambda, mu, Ha;
};

Lame lame(const HolmesMowParameters& m) {
  const double lambda = m.E * m.nu / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu));
  const double mu = 0.5 * m.E / (1.0 + m.nu);
  return {lambda, mu, lambda + 2.0 * mu};
}

}  // namespace

double holmes_mow_nominal_stress(const HolmesMowParameters& m, double stretch_z,
                                 double stretch_lateral) {
  const auto [lambda, mu, Ha] = lame(m);
  const double a = stretch_z * stretch_z, x = stretch_lateral * stretch_lateral;
  const double I1 = a + 2.0 * x, I2 = 2.0 * a * x + x * x, I3 = a * x * x;
  const double Q = m.beta / Ha * ((2.0 * mu - lambda) * (I1 - 3.0) + lambda * (I2 - 3.0)) -
                   m.beta * std::log(I3);
  const double tau =
      0.5 * std::exp(Q) * ((2.0 * mu + lambda * (I1 - 1.0)) * a - lambda * a * a - Ha);
  return tau / stretch_z;
}

double holmes_mow_uniaxial_lateral_stretch(const HolmesMowParameters& m, double stretch_z) {
  if (!(stretch_z > 0.0))
    throw std::invalid_argument("holmes_mow_uniaxial_lateral_stretch: stretch " +
                                std::to_string(stretch_z) + " <= 0");
  const auto [lambda, mu, Ha] = lame(m);
  const double s = 2.0 * mu + lambda * (stretch_z * stretch_z - 1.0);
  // h(x) = λ x² + s x − H_A, h(0) = −H_A < 0: bracket the smallest positive root.
  auto h = [&](double x) { return (lambda * x + s) * x - Ha; };
  double hi = 1.0;
  if (lambda < 0.0) {
    hi = -s / (2.0 * lambda);  // the vertex of the downward parabola, where h is largest
    if (!(hi > 0.0) || h(hi) < 0.0)
      throw std::domain_error(
          "holmes_mow_uniaxial_lateral_stretch: no lateral stretch at axial "
          "stretch " +
          std::to_string(stretch_z));
  } else {
    while (h(hi) < 0.0) hi *= 2.0;
  }
  return std::sqrt(detail::brent_root(h, 0.0, hi));
}

double holmes_mow_uniaxial_stress(const HolmesMowParameters& m, double stretch_z) {
  return holmes_mow_nominal_stress(m, stretch_z, holmes_mow_uniaxial_lateral_stretch(m, stretch_z));
}

double holmes_mow_confined_stress(const HolmesMowParameters& m, double stretch_z) {
  const double Ha = lame(m).Ha, a = stretch_z * stretch_z;
  return 0.5 * Ha * (a - 1.0) / stretch_z * std::exp(m.beta * (a - 1.0)) *
         std::pow(stretch_z, -2.0 * m.beta);
}

}  // namespace biphasic::analytic
