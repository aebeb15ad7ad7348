// Runs the manufactured solution of mms_solution.hpp on a sequence of unit-cube meshes and
// tabulates the L² errors and observed rates (shared by the default and the slow test).
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/study/field_error.hpp"
#include "biphasic/time/bdf_integrator.hpp"
#include "mms_solution.hpp"

namespace biphasic::mms {

/// How the semidiscrete problem is integrated. Tightening rtol from 1e-6 to 1e-8 changes the
/// errors on the finest default mesh by at most 2e-4 of themselves (docs/verification_mms.md),
/// and the factorisation count stays small with delta_cj = 0.9 and a first step of 0.01 s.
struct StudyOptions {
  int quadrature_points = 4;   ///< element rule: the paper's (degree 2)
  double rtol = 1e-6;          ///< IDA's relative tolerance
  double t_end = 1.0;          ///< [s]
  double delta_cj = 0.9;       ///< IDA's refactorisation threshold
  double initial_step = 0.01;  ///< [s]
};

struct MeshResult {
  int n = 0;       ///< cells per side
  double h = 0.0;  ///< cell size 1/n [mm]
  Index unknowns = 0;
  FieldErrors errors;
  long steps = 0;           ///< IDA steps
  long factorizations = 0;  ///< of the Jacobian
  double seconds = 0.0;     ///< whole solve, errors included
};

/// The unit cube in n × n × n cells with u and p prescribed from the exact fields on all six
/// faces, the exact body force and fluid source, integrated by BDF (IDA) from the exact state
/// y = 0 at t = 0 to t_end; errors at t_end.
inline MeshResult solve_on_cube(int n, const StudyOptions& options,
                                const ManufacturedSolution& exact = ManufacturedSolution{}) {
  const auto t0 = std::chrono::steady_clock::now();
  ColumnSpec spec;
  spec.nx = spec.ny = spec.nz = n;
  const Mesh mesh = generate_column(spec);

  const Parameters& m = exact.parameters();
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(m.lambda, m.mu, m.k);
  cfg.quadrature_points = options.quadrature_points;
  cfg.stabilisation.type = "none";
  for (const char* face : {"bottom", "top", "x0", "x1", "y0", "y1"}) {
    for (int c = 0; c < 3; ++c) cfg.bcs.push_back({BcType::Displacement, face, c, 0.0, {}, ""});
    cfg.bcs.push_back({BcType::Pressure, face, 0, 0.0, {}, ""});
  }
  cfg.time.integrator = Integrator::Bdf;
  cfg.time.t_end = options.t_end;
  cfg.time.dt = options.t_end;
  cfg.time.bdf.rtol = options.rtol;
  cfg.time.bdf.delta_cj = options.delta_cj;
  cfg.time.bdf.initial_step = options.initial_step;
  cfg.time.bdf.atol_displacement = 1e-2 * options.rtol * m.amplitude;  // 1 % of the scale
  cfg.time.bdf.atol_pressure = 1e-2 * options.rtol * m.pressure;

  BiphasicProblem problem(mesh, cfg);
  problem.set_body_force([&](const Vec3& X, double t) { return exact.body_force(X, t); });
  problem.set_fluid_source([&](const Vec3& X, double t) { return exact.fluid_source(X, t); });
  problem.set_dirichlet_fields([&](const Vec3& X, double t) { return exact.u(X, t); },
                               [&](const Vec3& X, double t) { return exact.p(X, t); },
                               [&](const Vec3& X, double t) { return exact.u_rate(X, t); },
                               [&](const Vec3& X, double t) { return exact.p_rate(X, t); });
  BdfIntegrator integrator(problem, cfg.time, cfg.linear_solver);
  std::vector<double> y(problem.size(), 0.0);
  integrator.run(0.0, y, nullptr);

  MeshResult r;
  r.n = n;
  r.h = 1.0 / n;
  r.unknowns = problem.size();
  r.errors = l2_errors(
      problem, y.data(), [&](const Vec3& X, double t) { return exact.u(X, t); },
      [&](const Vec3& X, double t) { return exact.p(X, t); }, options.t_end);
  r.steps = integrator.stats().steps;
  r.factorizations = integrator.linear_solver_stats().factorizations;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

/// log(e_{i−1}/e_i) / log(h_{i−1}/h_i) for i ≥ 1 (index 0: NaN).
inline std::vector<double> observed_rates(const std::vector<MeshResult>& runs, bool displacement) {
  std::vector<double> out(runs.size(), std::nan(""));
  for (std::size_t i = 1; i < runs.size(); ++i) {
    const double e0 = displacement ? runs[i - 1].errors.displacement : runs[i - 1].errors.pressure;
    const double e1 = displacement ? runs[i].errors.displacement : runs[i].errors.pressure;
    out[i] = std::log(e0 / e1) / std::log(runs[i - 1].h / runs[i].h);
  }
  return out;
}

/// The error table as CSV: into $BIPHASIC_VERIFICATION_OUT/mms/<file_name> when that variable
/// is set, and always to the test log.
inline void report(const std::vector<MeshResult>& runs, const std::string& file_name) {
  const std::vector<double> ru = observed_rates(runs, true), rp = observed_rates(runs, false);
  std::ostringstream csv;
  csv << "n,h,unknowns,error_u_l2,error_p_l2,rate_u,rate_p,norm_u_l2,norm_p_l2,steps,"
         "factorizations,seconds\n";
  csv << std::setprecision(6);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const MeshResult& r = runs[i];
    csv << r.n << ',' << r.h << ',' << r.unknowns << ',' << r.errors.displacement << ','
        << r.errors.pressure << ',';
    if (i > 0)
      csv << ru[i] << ',' << rp[i];
    else
      csv << ',';
    csv << ',' << r.errors.displacement_norm << ',' << r.errors.pressure_norm << ',' << r.steps
        << ',' << r.factorizations << ',' << r.seconds << '\n';
  }
  std::cout << csv.str();
  if (const char* dir = std::getenv("BIPHASIC_VERIFICATION_OUT")) {
    const std::filesystem::path folder = std::filesystem::path(dir) / "mms";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / file_name) << csv.str();
  }
}

}  // namespace biphasic::mms
