#include "biphasic/study/paper_scene.hpp"

namespace biphasic {

Config paper_reference_config(double lc, double permeability, bool gls) {
  Config cfg;
  cfg.title = "reference loading";
  cfg.mesh.cylinder.lc = lc;
  cfg.material = MaterialConfig::neo_hookean(0.2, 0.5, permeability);
  cfg.stabilisation.type = gls ? "gls" : "none";
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {32.0, 1.0}}};
  cfg.bcs = {{BcType::Displacement, "top", 2, -0.08, {}, "ramp"},
             {BcType::Displacement, "bottom", 2, 0.0, {}, ""},
             {BcType::Symmetry, "symmetry_x", 0, 0.0, {}, ""},
             {BcType::Symmetry, "symmetry_y", 0, 0.0, {}, ""},
             {BcType::Pressure, "top", 0, 0.0, {}, ""},
             {BcType::Pressure, "bottom", 0, 0.0, {}, ""}};
  cfg.time.t_end = 32.0;
  cfg.time.dt = 6.4;
  return cfg;
}

}  // namespace biphasic
