#include "biphasic/physics/element_stabilisation.hpp"

#include <algorithm>

namespace biphasic {

namespace {

bool all_zero(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
}

}  // namespace

void ElementStabilisation::resize(std::size_t elements) {
  for (auto* v : {&gls_c_, &gls_offset_, &flux_beta_, &flux_offset_, &flux_reference_})
    v->assign(elements, 0.0);
}

void ElementStabilisation::set(std::size_t e, const ElementCoefficients& c,
                               const MaterialLaws& laws) {
  gls_c_[e] = c.gls_c;
  gls_offset_[e] = c.gls_offset;
  flux_beta_[e] = c.flux_beta;
  flux_offset_[e] = c.flux_offset;
  flux_reference_[e] =
      c.flux_offset != 0.0
          ? std::max(0.0, c.flux_beta - c.flux_offset * laws.reference_permeability())
          : c.flux_beta;
}

void ElementStabilisation::finish() {
  // A term is present if some element has it in the undeformed state. An element whose clipped
  // coefficient is zero there keeps its raw values: with a k(J) that falls under compression the
  // kernel switches it on. A term no element has at J = 1 is dropped, so that a present term
  // always has a positive coefficient somewhere (gls_time_scale() > 0 for the consistent start).
  bool gls = false, flux = false;
  for (std::size_t e = 0; e < gls_c_.size(); ++e) {
    gls = gls || gls_c_[e] > gls_offset_[e];
    flux = flux || flux_reference_[e] > 0.0;
  }
  if (!gls) {
    gls_c_.clear();
    gls_offset_.clear();
  } else if (all_zero(gls_offset_)) {
    gls_offset_.clear();
  }
  if (!flux) {
    flux_beta_.clear();
    flux_offset_.clear();
    flux_reference_.clear();
  } else if (all_zero(flux_offset_)) {
    flux_offset_.clear();
  }
}

double ElementStabilisation::gls_coefficient(std::size_t e) const {
  if (gls_c_.empty()) return 0.0;
  if (gls_offset_.empty()) return gls_c_[e];
  return std::max(0.0, gls_c_[e] - gls_offset_[e]);
}

double ElementStabilisation::flux_perturbation(std::size_t e) const {
  return flux_reference_.empty() ? 0.0 : flux_reference_[e];
}

ElementCoefficients ElementStabilisation::coefficients(std::size_t e, double volume_rate_dt) const {
  ElementCoefficients c;
  c.volume_rate_dt = volume_rate_dt;
  if (!gls_c_.empty()) {
    c.gls_c = gls_c_[e];
    if (!gls_offset_.empty()) c.gls_offset = gls_offset_[e];
  }
  if (!flux_beta_.empty()) {
    c.flux_beta = flux_beta_[e];
    if (!flux_offset_.empty()) c.flux_offset = flux_offset_[e];
  }
  return c;
}

}  // namespace biphasic
