// cases/verification/mms/mms.toml: the case parses and runs end to end, and its formulas are the
// loads of its exact solution (the errors fall at the orders of the discretisation).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "biphasic/app/run.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/study/field_error.hpp"
#include "biphasic/time/bdf_integrator.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;

const std::string kCase = std::string(BIPHASIC_SOURCE_DIR) + "/cases/verification/mms/mms.toml";

/// The case's exact solution (README.md beside it).
Vec3 exact_u(const Vec3& X, double t) { return {0.1 * t * X(0), 0.0, 0.0}; }
double exact_p(const Vec3& X, double t) {
  const double pi = std::numbers::pi;
  return 0.05 * t * std::sin(pi * X(0)) * std::sin(pi * X(1)) * std::sin(pi * X(2));
}

/// Overrides for n × n × n cells and, if `one_step`, a single backward-Euler step to t = 1 (exact
/// in time here: J = 1 + 0.1 t is linear in t and p has no rate in the equations).
std::vector<std::string> overrides(int n, bool one_step) {
  const std::string s = std::to_string(n);
  std::vector<std::string> out{"mesh.column.nx=" + s, "mesh.column.ny=" + s, "mesh.column.nz=" + s};
  if (one_step) out.push_back("time.dt=1.0");
  return out;
}

TEST(MmsCase, ParsesAndRuns) {
  const Config cfg = read_case_file(kCase, overrides(2, false));
  EXPECT_EQ(cfg.mesh.source, MeshSource::Column);
  EXPECT_FALSE(cfg.loads.fluid_source.is_zero());
  const fs::path out =
      fs::temp_directory_path() / ("biphasic_mms_case_" + std::to_string(::getpid()));
  RunOptions options;
  options.output_dir = out.string();
  options.quiet = true;
  const nlohmann::json summary = run_case(cfg, options);
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_TRUE(fs::exists(out / "line.csv"));
  fs::remove_all(out);
}

FieldErrors solve(int n) {
  const Config cfg = read_case_file(kCase, overrides(n, true));
  const Mesh mesh = generate_column(cfg.mesh.column);
  BiphasicProblem problem(mesh, cfg);
  std::unique_ptr<TimeIntegrator> integrator =
      make_time_integrator(problem, cfg.time, cfg.linear_solver, "");
  std::vector<double> y(problem.size(), 0.0);
  integrator->run(0.0, y, nullptr);
  return l2_errors(problem, y.data(), exact_u, exact_p, cfg.time.t_end);
}

TEST(MmsCase, FormulasMakeTheFieldsExact) {
  // n = 2 has a single free pressure vertex: start at 4.
  const FieldErrors coarse = solve(4), fine = solve(8);
  const double rate_p = std::log2(coarse.pressure / fine.pressure);
  const double rate_u = std::log2(coarse.displacement / fine.displacement);
  std::cout << "n = 4: |e_u| " << coarse.displacement << ", |e_p| " << coarse.pressure
            << "\nn = 8: |e_u| " << fine.displacement << ", |e_p| " << fine.pressure << "\nrates "
            << rate_u << ", " << rate_p << "\n";
  // A wrong sign or factor in a formula would leave an O(1) inconsistency: the errors would stop
  // falling. Measured: rates 1.88 (p) and 1.79 (u, driven by the pressure error here since P2
  // holds the exact u), still short of the asymptotic 2 on these coarse meshes.
  EXPECT_GT(rate_p, 1.75);
  EXPECT_GT(rate_u, 1.7);
  EXPECT_LT(fine.pressure, 0.08 * fine.pressure_norm);
  EXPECT_LT(fine.displacement, 3e-3 * fine.displacement_norm);
}

}  // namespace
}  // namespace biphasic
