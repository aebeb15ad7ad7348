// The [stabilisation] section of a case file: which pressure stabilisation, and how its
// per-element coefficient is sized (stabilisations.hpp holds the choices).
#pragma once

#include <string>

namespace biphasic {

/// Element length h in the coefficients h²/(4k) and h²/(4 H_A): the paper uses the
/// circumsphere radius.
enum class ElementLength { Circumradius, ShortestEdge, LongestEdge, VolumeDiameter };

struct StabilisationConfig {
  std::string type = "none";  ///< stabilisation.type: a name of stabilisations.hpp
  ElementLength length = ElementLength::Circumradius;
  double scale = 1.0;  ///< multiplies c_e or β (1 = the published coefficients)
};

}  // namespace biphasic
