// Ramp confined compression (Mow et al. 1980; FEBio's verification case: h = 1 mm, ε₀ = 10 %
// over 100 s, μ = 0.5 MPa, λ = 0, k = 1e-3) on both two-dimensional models: a column whose side
// walls hold the lateral displacement (plane strain: x = 0 and x = w; axisymmetric: the wall
// r = w, the axis holding itself) is one-dimensional, so the platen stress must match the
// finite-strain one-dimensional reference of biphasic_analytic, as the three-dimensional column
// does (tests/verification/test_confined_compression.cpp: 5e-3 on 20 graded layers).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include "biphasic/analytic/confined_compression.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/section_problem.hpp"
#include "biphasic/time/bdf_integrator.hpp"

namespace biphasic {
namespace {

const std::vector<double> kTimes{10, 25, 50, 75, 100, 150, 200, 300, 500, 1000};  // [s]

/// Largest |σ_h − σ_ref| / |σ_ref| over kTimes, and the largest imbalance of the top and bottom
/// reactions relative to the top's.
std::pair<double, double> confined_errors(SectionModel model) {
  SectionRectangleSpec spec;
  spec.width = 0.1;
  spec.height = 1.0;
  spec.nr = 1;
  spec.nz = 20;
  spec.grading_curves = {"top"};
  spec.grading_ratio = 10.0;
  const SectionMesh mesh = generate_section_rectangle(spec);

  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(0.0, 0.5, 1e-3);
  cfg.stabilisation.type = "none";
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {100.0, 1.0}}};
  cfg.bcs.push_back({BcType::Displacement, "top", 1, -0.1, {}, "ramp"});
  cfg.bcs.push_back({BcType::Pressure, "top", 0, 0.0, {}, ""});
  cfg.bcs.push_back({BcType::Displacement, "bottom", 1, 0.0, {}, ""});
  cfg.bcs.push_back({BcType::Symmetry, "lateral", 0, 0.0, {}, ""});
  if (model == SectionModel::PlaneStrain)
    cfg.bcs.push_back({BcType::Symmetry, "axis", 0, 0.0, {}, ""});
  cfg.time.integrator = Integrator::Bdf;
  cfg.time.t_end = 1000.0;
  cfg.time.dt = 5.0;
  cfg.time.bdf.rtol = 1e-6;
  SectionProblem problem(mesh, model, cfg);
  const double area =
      model == SectionModel::Axisymmetric ? std::numbers::pi * spec.width * spec.width : spec.width;

  std::vector<double> times, stresses;
  double imbalance = 0.0;
  BdfIntegrator integrator(problem, cfg.time, cfg.linear_solver);
  std::vector<double> y(static_cast<std::size_t>(problem.size()), 0.0);
  integrator.run(
      0.0, y,
      [&](const StepInfo& info, const std::vector<double>& ys, const std::vector<double>& ydots) {
        if (std::none_of(kTimes.begin(), kTimes.end(),
                         [&](double t) { return std::abs(t - info.t) < 1e-9 * t; }))
          return;
        const auto r = problem.reactions({"top", "bottom"}, info.t, ys.data(), ydots.data());
        times.push_back(info.t);
        stresses.push_back(r[0][1] / area);
        imbalance = std::max(imbalance, std::abs(r[0][1] + r[1][1]) / std::abs(r[0][1]));
      });
  analytic::ConfinedRamp ramp;  // the defaults are FEBio's case, as configured above
  const std::vector<double> reference = analytic::confined_ramp_stress_neo_hookean(ramp, times);
  EXPECT_EQ(times.size(), kTimes.size());
  double error = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    error = std::max(error, std::abs(stresses[i] - reference[i]) / std::abs(reference[i]));
    std::cout << to_string(model) << " t = " << times[i] << " s: " << stresses[i] << " MPa, "
              << "reference " << reference[i] << " MPa\n";
  }
  return {error, imbalance};
}

// The platen stress within 2e-3 of the one-dimensional finite-strain reference at every
// tabulated time (measured: 7.7e-4 plane strain, 7.5e-4 axisymmetric), the platens in balance.
TEST(SectionConfined, PlaneStrainColumnMatchesTheOneDimensionalReference) {
  const auto [error, imbalance] = confined_errors(SectionModel::PlaneStrain);
  std::cout << "plane strain: largest relative error " << error << '\n';
  EXPECT_LT(error, 2e-3);
  EXPECT_LT(imbalance, 1e-6);
}

TEST(SectionConfined, AxisymmetricColumnMatchesTheOneDimensionalReference) {
  const auto [error, imbalance] = confined_errors(SectionModel::Axisymmetric);
  std::cout << "axisymmetric: largest relative error " << error << '\n';
  EXPECT_LT(error, 2e-3);
  EXPECT_LT(imbalance, 1e-6);
}

}  // namespace
}  // namespace biphasic
