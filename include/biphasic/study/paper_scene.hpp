// The paper's numerical example as a configuration (docs/paper_reference.md): quarter cylinder
// R = 18 mm, H = 8 mm, λ = 0.2 MPa, μ = 0.5 MPa, top moved down at 2.5 µm/s to 1 % strain
// (t = 32 s) in steps of 6.4 s, drained top and bottom, frictionless platens, sealed lateral face.
#pragma once

#include "biphasic/io/config.hpp"

namespace biphasic {

/// The reference loading on a uniform mesh of characteristic length lc [mm], permeability k
/// [mm⁴ N⁻¹ s⁻¹], with or without GLS. The same scene as cases/paper/*.toml.
Config paper_reference_config(double lc, double permeability = 1e-3, bool gls = true);

}  // namespace biphasic
