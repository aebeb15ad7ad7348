// The two backward-Euler volume rates: incremental J̇ = J F⁻ᵀ:∇₀(u − uₙ)/Δt and conservative
// J̇ = (J − Jₙ)/Δt. The conservative mass rows telescope to the volume change; over a run the
// fluid-volume balance ΔV + ∫Q − ∫S = 0 then holds to the Newton tolerance, while the
// incremental form leaves an O(Δt) imbalance.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "../common/box_mesh.hpp"
#include "biphasic/fe/quadrature.hpp"
#include "biphasic/fe/shape_functions.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/volume_balance.hpp"
#include "biphasic/time/bdf_integrator.hpp"
#include "element_fixture.hpp"

namespace biphasic {
namespace {

/// ∫Ω₀ J dX = ∫ dx of the element whose nodes sit at x = X + u [mm³], from the isoparametric
/// map of the deformed nodes alone (4-point rule, as the kernel).
double deformed_volume(const Eigen::Matrix<double, 10, 3>& X, const ElementVector& y) {
  Eigen::Matrix<double, 10, 3> x = X;
  for (int a = 0; a < 10; ++a) x.row(a) += y.segment<3>(3 * a).transpose();
  double volume = 0.0;
  for (const auto& q : tet_quadrature(4).points)
    volume += q.weight * (x.transpose() * p2_gradients(q.xi)).determinant();
  return volume;
}

/// Σₙ Δtₙ Σ_c R_p,c over a sequence of backward-Euler steps of one element [mm³].
double summed_mass_rows(const std::vector<PointGeometry>& geo, ElementParameters p,
                        const std::vector<ElementVector>& states, const std::vector<double>& dt,
                        bool conservative) {
  double sum = 0.0;
  for (std::size_t n = 1; n < states.size(); ++n) {
    p.volume_rate_dt = conservative ? dt[n - 1] : 0.0;
    const ElementVector ydot = (states[n] - states[n - 1]) / dt[n - 1];
    ElementOutput out;
    biphasic_element(geo, p, states[n], ydot, false, out);
    sum += dt[n - 1] * out.residual.tail<4>().sum();
  }
  return sum;
}

// Σ_c N^p_c = 1 removes the Darcy term from the sum of the mass rows, which is then ∫ J̇ dX;
// with J̇ = (J − Jₙ)/Δt the steps telescope to ∫(J_end − J_0) dX.
TEST(VolumeRate, ConservativeMassRowsTelescopeToTheVolumeChange) {
  const Eigen::Matrix<double, 10, 3> X = test::distorted_tet();
  std::vector<PointGeometry> geo;
  element_point_geometry(X, tet_quadrature(4), geo);
  ElementParameters p;
  p.material = {0.2, 0.5};
  p.permeability = 1e-2;
  p.gls_c = 2.5;  // the GLS term lives in the momentum rows: no effect on the balance
  std::vector<ElementVector> states(1);
  ElementVector rate;
  test::random_state(21, 0.06, states[0], rate);
  const std::vector<double> dt{0.3, 1.1, 2.0, 0.05, 0.7, 1.6};
  for (std::size_t n = 0; n < dt.size(); ++n) {
    ElementVector increment;
    test::random_state(30 + static_cast<unsigned>(n), 0.03, increment, rate);
    states.push_back(states.back() + increment);  // pressures change too
  }
  const double expected = deformed_volume(X, states.back()) - deformed_volume(X, states.front());
  ASSERT_GT(std::abs(expected), 1e-3);  // a real volume change [mm³]

  const double conservative = summed_mass_rows(geo, p, states, dt, true);
  EXPECT_LT(std::abs(conservative - expected), 1e-12 * std::abs(expected))
      << conservative << " vs " << expected;
  // The incremental form misses the second-order part of each step's volume change.
  const double incremental = summed_mass_rows(geo, p, states, dt, false);
  EXPECT_GT(std::abs(incremental - expected), 1e-4 * std::abs(expected))
      << incremental << " vs " << expected;
}

/// Final balance of an unconfined compression of a drained column under backward Euler.
struct ColumnRun {
  std::vector<VolumeBalanceRecord> steps;
  BiphasicProblem::FluidRates last_rates;
};

/// Column [0,1]² × [0,1.5] mm: bottom fixed in z and draining through a prescribed outward flux
/// q̄, top pushed down 10 % over 4 s, symmetry on x0 and y0, x1 and y1 drained (p = 0), a
/// uniform fluid source s; k = 1e-2 (consolidation time ≈ 2 s per mm²).
ColumnRun run_column(VolumeRate form, double dt, double flux, double source) {
  const Mesh mesh = test::box_mesh({2, 2, 3}, {1.0, 1.0, 1.5});
  Config config;
  config.material = MaterialConfig::neo_hookean(0.2, 0.5, 1e-2);
  config.stabilisation.type = "gls";
  config.time.t_end = 4.0;
  config.time.dt = dt;
  config.time.volume_rate = form;
  // Tight Newton tolerances: the conservative balance is limited by them.
  config.time.newton.rtol_displacement = 1e-12;
  config.time.newton.rtol_pressure = 1e-12;
  config.time.newton.atol_pressure = 1e-18;
  config.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {4.0, 1.0}}};
  auto bc = [&](BcType type, const char* name, int component, double value, const char* curve) {
    BoundaryCondition b;
    b.type = type;
    b.boundary = name;
    b.component = component;
    b.value = value;
    b.curve = curve;
    config.bcs.push_back(b);
  };
  bc(BcType::Displacement, "z0", 2, 0.0, "");
  bc(BcType::Displacement, "z1", 2, -0.15, "ramp");
  bc(BcType::Symmetry, "x0", 0, 0.0, "");
  bc(BcType::Symmetry, "y0", 0, 0.0, "");
  bc(BcType::Pressure, "x1", 0, 0.0, "");
  bc(BcType::Pressure, "y1", 0, 0.0, "");
  if (flux != 0.0) bc(BcType::Flux, "z0", 0, flux, "");
  BiphasicProblem problem(mesh, config);
  if (source != 0.0) problem.set_fluid_source([source](const Vec3&, double) { return source; });
  const auto integrator = make_time_integrator(problem, config.time, config.linear_solver, "");
  std::vector<double> y(problem.size(), 0.0);
  problem.apply_dirichlet(0.0, y.data(), nullptr);
  VolumeBalance balance(problem, y);
  ColumnRun run;
  integrator->run(0.0, y, [&](const StepInfo& info, const auto& ys, const auto& ydots) {
    balance.add_step(info.t, info.dt, ys, ydots);
    run.steps.push_back(balance.record());
    run.last_rates = problem.fluid_rates(info.t, ys.data(), ydots.data());
  });
  return run;
}

constexpr double kFlux = 2e-3;    // mm/s out of the bottom face (1 mm²)
constexpr double kSource = 1e-3;  // 1/s over 1.5 mm³

TEST(VolumeBalance, ConservativeFormHoldsToTheNewtonTolerance) {
  for (double dt : {0.5, 0.25}) {
    const ColumnRun run = run_column(VolumeRate::Conservative, dt, kFlux, kSource);
    ASSERT_EQ(run.steps.size(), static_cast<std::size_t>(std::lround(4.0 / dt)));
    for (const VolumeBalanceRecord& r : run.steps)
      EXPECT_LE(r.relative_imbalance(), 1e-8) << "dt " << dt << " dV " << r.volume_change;
    // Signs and units: the column loses volume, fluid leaves (Q > 0), the prescribed outflow
    // is q̄ · area and the source s · volume.
    const VolumeBalanceRecord& end = run.steps.back();
    EXPECT_LT(end.volume_change, -1e-2);
    EXPECT_GT(end.outflow_integrated, 1e-2);
    EXPECT_NEAR(run.last_rates.prescribed, kFlux * 1.0, 1e-15);
    EXPECT_NEAR(run.last_rates.source, kSource * 1.5, 1e-15);
    EXPECT_NEAR(end.source_integrated, kSource * 1.5 * 4.0, 1e-14);
    EXPECT_GT(run.last_rates.drained, 0.0);
  }
}

TEST(VolumeBalance, IncrementalImbalanceIsFirstOrderInTheStep) {
  const double coarse =
      run_column(VolumeRate::Incremental, 0.5, kFlux, kSource).steps.back().relative_imbalance();
  const double fine =
      run_column(VolumeRate::Incremental, 0.25, kFlux, kSource).steps.back().relative_imbalance();
  EXPECT_GT(fine, 1e-3);  // far above the Newton tolerance
  EXPECT_NEAR(coarse / fine, 2.0, 0.2) << coarse << " " << fine;
}

TEST(VolumeBalance, BdfRefusesTheConservativeForm) {
  const Mesh mesh = test::box_mesh({1, 1, 1}, {1.0, 1.0, 1.0});
  Config config;
  config.time.integrator = Integrator::Bdf;
  config.time.volume_rate = VolumeRate::Conservative;
  BiphasicProblem problem(mesh, config);
  EXPECT_THROW(make_time_integrator(problem, config.time, config.linear_solver, ""),
               std::invalid_argument);
  EXPECT_THROW(problem.set_conservative_volume_rate(-1.0), std::invalid_argument);
}

}  // namespace
}  // namespace biphasic
