// The stabilising coefficients of every element of a problem (tetrahedra or triangles): what the
// chosen stabilisation (stabilisation/stabilisations.hpp) gives each element, kept for the
// kernel, and their values in the undeformed state for the rest of the solver (the consistent
// start, the iterative solver's Schur approximation, diagnostics).
#pragma once

#include <cstddef>
#include <vector>

#include "biphasic/material/material_laws.hpp"
#include "biphasic/physics/biphasic_element.hpp"

namespace biphasic {

class ElementStabilisation {
 public:
  /// Room for `elements` elements without stabilisation.
  void resize(std::size_t elements);
  /// Element e's coefficients, for its material `laws` (k(1) gives β at J = 1).
  void set(std::size_t e, const ElementCoefficients& c, const MaterialLaws& laws);
  /// Called once every element is set: a term that no element has at J = 1 is dropped, so that
  /// has_gls() and has_flux_perturbation() say whether the residual has it. Elements of a present
  /// term keep their raw values, so that a strain-dependent k(J) can switch a clipped
  /// need-following coefficient on.
  void finish();

  bool has_gls() const { return !gls_c_.empty(); }
  bool has_flux_perturbation() const { return !flux_beta_.empty(); }
  /// c_e of element e at J = 1, max(0, c_e,ref − offset) [MPa s] (0 without GLS).
  double gls_coefficient(std::size_t e) const;
  /// β of element e at J = 1, max(0, β_ref − offset k(1)) [mm⁴ N⁻¹] (0 without it).
  double flux_perturbation(std::size_t e) const;
  /// The kernel's coefficients of element e, with the volume-rate step `volume_rate_dt` [s].
  ElementCoefficients coefficients(std::size_t e, double volume_rate_dt) const;

 private:
  std::vector<double> gls_c_, gls_offset_, flux_beta_, flux_offset_;
  std::vector<double> flux_reference_;  ///< β at J = 1 per element
};

}  // namespace biphasic
