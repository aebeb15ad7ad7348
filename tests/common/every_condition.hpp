// A box problem with every kind of condition a part of a partitioned mesh must get right (a
// ramped displacement, symmetry planes, a drained face, a traction, a normal traction and a
// flux on faces that meet the others, GLS), and a random state of it. Shared by the one-process
// and the MPI tests of the distributed assembly.
#pragma once

#include <random>
#include <vector>

#include "biphasic/io/config.hpp"
#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic::test {

inline Config every_condition() {
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(0.3, 0.6, 1e-2);
  cfg.stabilisation.type = "gls";
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {2.0, 1.0}}};
  cfg.bcs = {{BcType::Displacement, "z1", 2, -0.05, {}, "ramp"},
             {BcType::Displacement, "z0", 2, 0.0, {}, ""},
             {BcType::Symmetry, "x0", 0, 0.0, {}, ""},
             {BcType::Symmetry, "y0", 0, 0.0, {}, ""},
             {BcType::Pressure, "x1", 0, 0.0, {}, ""},
             {BcType::Traction, "y1", 0, 0.0, {0.01, 0.02, -0.03}, "ramp"},
             {BcType::NormalTraction, "x1", 0, 0.04, {}, "ramp"},
             {BcType::Flux, "y1", 0, 2e-3, {}, "ramp"}};
  cfg.time.t_end = 2.0;
  return cfg;
}

/// The same on a section rectangle (generate_section_rectangle's curves axis, lateral, bottom,
/// top) of a two-dimensional model: a ramped axial displacement, the axis held by symmetry in
/// plane strain (by the model itself when axisymmetric), a drained lateral side under a traction
/// and a normal traction, a flux through the top, GLS.
inline Config every_section_condition(ModelKind model) {
  Config cfg = every_condition();
  cfg.model = model;
  cfg.bcs = {{BcType::Displacement, "top", 1, -0.05, {}, "ramp"},
             {BcType::Displacement, "bottom", 1, 0.0, {}, ""},
             {BcType::Pressure, "lateral", 0, 0.0, {}, ""},
             {BcType::Traction, "lateral", 0, 0.0, {0.01, 0.02, 0.0}, "ramp"},
             {BcType::NormalTraction, "lateral", 0, 0.04, {}, "ramp"},
             {BcType::Flux, "top", 0, 2e-3, {}, "ramp"}};
  if (model == ModelKind::PlaneStrain)
    cfg.bcs.push_back({BcType::Symmetry, "axis", 0, 0.0, {}, ""});
  return cfg;
}

/// A random state of `problem` (a BiphasicProblem or SectionProblem; u ~ 0.02 mm, p ~ 0.05 MPa,
/// rates a tenth of those per second) with its Dirichlet values set at time t; the same for the
/// same seed.
template <class Problem>
void random_state(const Problem& problem, double t, unsigned seed, std::vector<double>& y,
                  std::vector<double>& ydot) {
  const auto n = static_cast<std::size_t>(problem.size());
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  y.resize(n);
  ydot.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool u = static_cast<Index>(i) < problem.num_u();
    y[i] = (u ? 0.02 : 0.05) * d(gen);
    ydot[i] = (u ? 0.002 : 0.005) * d(gen);
  }
  problem.apply_dirichlet(t, y.data(), ydot.data());
}

}  // namespace biphasic::test
