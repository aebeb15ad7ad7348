// The [stabilisation] section of a case file: which pressure stabilisation, and how its
// per-element coefficient is sized (stabilisations.hpp holds the choices).
#pragma once

#include <string>

namespace biphasic {

/// Element length h in the coefficients h²/(4k) and h²/(4 H_A): the paper uses the
/// circumsphere radius.
enum class ElementLength { Circumradius, ShortestEdge, LongestEdge, VolumeDiameter };

/// Quadrature of the GLS term: the element's rule (quadrature.points), or its centroid alone.
enum class GlsQuadrature { Full, OnePoint };

struct StabilisationConfig {
  std::string type = "none";  ///< stabilisation.type: a name of stabilisations.hpp
  ElementLength length = ElementLength::Circumradius;
  double scale = 1.0;  ///< multiplies c_e or β (1 = the published coefficients)
  GlsQuadrature gls_quadrature = GlsQuadrature::Full;
  /// r* of the need-following types: no stabilisation where k H_A Δt*/h² ≥ r* [-]
  double threshold = 0.25;
  /// Δt* [s] the need-following types are frozen at; 0 = time.dt
  double time_step = 0.0;
};

}  // namespace biphasic
