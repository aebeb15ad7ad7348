// The small system the linear-solver tests factorise or iterate on: a 3×2×2 box mesh, bottom
// fixed axially, two symmetry planes, drained top.
#pragma once

#include <random>
#include <vector>

#include "../common/box_mesh.hpp"
#include "biphasic/io/config.hpp"

namespace biphasic::test {

inline Mesh solver_box_mesh() { return box_mesh({3, 2, 2}, {1.5, 1.0, 1.0}); }

inline Config solver_box_config(Stabilisation stabilisation) {
  Config cfg;
  cfg.stabilisation.type = stabilisation;
  cfg.bcs = {{BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Symmetry, "x0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y0", 0, 0.0, {}, ""},
             {BcType::Pressure, "z1", 0, 0.0, {}, ""}};
  return cfg;
}

/// A reproducible solution vector, entries uniform in [−1, 1].
inline std::vector<double> random_unknowns(Index n) {
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = d(gen);
  return v;
}

}  // namespace biphasic::test
