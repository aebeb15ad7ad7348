// Benchmarks of the building blocks on the paper's quarter cylinder (k = 1e-3, GLS, Δt = 6.4 s):
// residual and Jacobian assembly, and per linear solver the analysis, factorisation,
// refactorisation and solve. Each (mesh, solver) pair runs in its own child process so that
// its peak memory (ru_maxrss) is its own. Prints a Markdown table; --csv FILE also writes CSV.
//
// usage: biphasic_bench [--lc 1.3,0.98,...] [--solvers klu,umfpack,mumps,mumps_double,iterative]
// [--repeat N] [--csv FILE]
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "biphasic/linsolve/linear_solver.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/study/paper_scene.hpp"

namespace {

using namespace biphasic;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double peak_rss_gb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / (1024.0 * 1024.0);  // ru_maxrss in KiB
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

/// One (mesh, solver) measurement; returns a CSV line.
std::string measure(double lc, const std::string& solver_name, int repeat) {
  const LinearSolverType solver = solver_name == "klu"         ? LinearSolverType::Klu
                                  : solver_name == "umfpack"   ? LinearSolverType::Umfpack
                                  : solver_name == "iterative" ? LinearSolverType::Iterative
                                                               : LinearSolverType::Mumps;
  Config cfg = paper_reference_config(lc);
  cfg.linear_solver.type = solver;
  cfg.linear_solver.ordering = Ordering::Metis;
  cfg.linear_solver.precision =
      solver_name == "mumps_double" ? FactorPrecision::Double : FactorPrecision::Mixed;
  const Mesh mesh = generate_quarter_cylinder(cfg.mesh.cylinder);
  BiphasicProblem problem(mesh, cfg);
  const Index n = problem.size();
  // A deformed state near the end of the reference loading.
  std::vector<double> y(n, 0.0), ydot(n, 0.0), F(n);
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (Index i = 0; i < n; ++i) y[i] = (i < problem.num_u() ? 1e-3 : 1e-3) * d(gen);
  problem.apply_dirichlet(32.0, y.data(), ydot.data());

  std::vector<double> t_res, t_jac;
  SUNContext ctx;
  SUNContext_Create(nullptr, &ctx);
  SUNMatrix A = problem.pattern().new_matrix(ctx);
  for (int r = 0; r < repeat; ++r) {
    auto t0 = Clock::now();
    problem.residual(32.0, y.data(), ydot.data(), F.data());
    t_res.push_back(seconds_since(t0));
    t0 = Clock::now();
    problem.jacobian(32.0, y.data(), ydot.data(), 1.0 / 6.4, SUNSparseMatrix_Data(A));
    t_jac.push_back(seconds_since(t0));
  }

  LinearSolverStats stats;
  auto t0 = Clock::now();
  FillOrder order = fill_order(cfg.linear_solver, problem.pattern());
  const double ordering_seconds = seconds_since(t0);  // counted as part of the analysis
  const double cj = 1.0 / 6.4;
  const SaddlePointStructure saddle = problem.saddle_point_structure([cj] {
    return std::pair{cj, cj};
  });
  LinearSolverPtr ls =
      make_linear_solver(cfg.linear_solver, ctx, &stats, std::move(order), &saddle);
  N_Vector x = N_VNew_Serial(n, ctx), b = N_VNew_Serial(n, ctx);
  std::copy(F.begin(), F.end(), N_VGetArrayPointer(b));
  SUNLinSolInitialize(ls.get());
  t0 = Clock::now();
  if (SUNLinSolSetup(ls.get(), A) != 0) throw std::runtime_error("factorisation failed");
  const double first_setup = seconds_since(t0);
  t0 = Clock::now();
  SUNLinSolSetup(ls.get(), A);
  const double second_setup = seconds_since(t0);
  std::vector<double> t_solve;
  for (int r = 0; r < std::max(3, repeat); ++r) {
    t0 = Clock::now();
    SUNLinSolSolve(ls.get(), A, x, b, 0.0);
    t_solve.push_back(seconds_since(t0));
  }
  N_VDestroy(x);
  N_VDestroy(b);
  ls.reset();
  SUNMatDestroy(A);
  SUNContext_Free(&ctx);

  std::ostringstream line;
  line << lc << ',' << n << ',' << problem.pattern().nnz() << ',' << solver_name << ','
       << median(t_res) << ',' << median(t_jac) << ',' << ordering_seconds + stats.analysis_seconds
       << ',' << first_setup - stats.analysis_seconds << ',' << second_setup << ','
       << median(t_solve) << ',' << stats.fill << ',' << peak_rss_gb();
  return line.str();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> lcs{"1.3", "0.98"}, solvers{"klu", "umfpack", "mumps"};
  int repeat = 5;
  std::string csv_path;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--lc")
      lcs = split(next());
    else if (a == "--solvers")
      solvers = split(next());
    else if (a == "--repeat")
      repeat = std::stoi(next());
    else if (a == "--csv")
      csv_path = next();
    else {
      std::cerr << "usage: biphasic_bench [--lc 1.3,0.98] [--solvers "
                   "klu,umfpack,mumps,mumps_double,iterative] "
                   "[--repeat N] [--csv FILE]\n";
      return a == "--help" ? 0 : 1;
    }
  }
  const std::string header =
      "lc_mm,unknowns,nonzeros,solver,residual_s,jacobian_s,analysis_s,factorization_s,"
      "refactorization_s,solve_s,fill,peak_rss_gb";
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    csv << header << '\n';
  }
  std::printf(
      "| lc [mm] | unknowns | nnz | solver | residual [s] | Jacobian [s] | analysis [s] | "
      "factorisation [s] | refactorisation [s] | solve [s] | fill | peak memory [GB] |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& lc : lcs) {
    for (const std::string& solver : solvers) {
      int fds[2];
      if (pipe(fds) != 0) return 2;
      const pid_t pid = fork();
      if (pid == 0) {
        close(fds[0]);
        std::string line;
        try {
          line = measure(std::stod(lc), solver, repeat);
        } catch (const std::exception& e) {
          line = "error: " + std::string(e.what());
        }
        line += '\n';
        if (write(fds[1], line.data(), line.size()) < 0) _exit(3);
        _exit(0);
      }
      close(fds[1]);
      std::string line;
      char buf[512];
      for (ssize_t k; (k = read(fds[0], buf, sizeof buf)) > 0;)
        line.append(buf, static_cast<std::size_t>(k));
      close(fds[0]);
      int status = 0;
      waitpid(pid, &status, 0);
      if (!line.empty() && line.back() == '\n') line.pop_back();
      if (line.rfind("error", 0) == 0 || line.empty()) {
        std::printf("| %s | – | – | %s | %s |\n", lc.c_str(), solver.c_str(),
                    line.empty() ? "crashed" : line.c_str());
        continue;
      }
      if (csv) csv << line << std::endl;
      std::vector<std::string> f = split(line);
      std::printf("| %s | %s | %s | %s | %.4f | %.4f | %.3f | %.3f | %.3f | %.4f | %.1f | %.2f |\n",
                  f[0].c_str(), f[1].c_str(), f[2].c_str(), f[3].c_str(), std::stod(f[4]),
                  std::stod(f[5]), std::stod(f[6]), std::stod(f[7]), std::stod(f[8]),
                  std::stod(f[9]), std::stod(f[10]), std::stod(f[11]));
      std::fflush(stdout);
    }
  }
  return 0;
}
