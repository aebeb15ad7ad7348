#include "biphasic/app/run.hpp"

#include <SuiteSparse_config.h>
#include <gmsh.h>
#include <hdf5.h>
#include <klu.h>
#include <metis.h>
#include <sundials/sundials_config.h>

#include <toml++/toml.h>
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "biphasic/app/field_output.hpp"
#include "biphasic/app/preflight.hpp"
#include "biphasic/app/probes.hpp"
#include "biphasic/app/restart_support.hpp"
#include "biphasic/app/segment_counters.hpp"
#include "biphasic/io/atomic_file.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/io/line_probe.hpp"
#include "biphasic/io/output_folder.hpp"
#include "biphasic/io/platen_csv.hpp"
#include "biphasic/io/reaction_csv.hpp"
#include "biphasic/mesh/mesh_cache.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/section_problem.hpp"
#include "biphasic/physics/volume_balance.hpp"
#include "biphasic/study/measures.hpp"
#include "biphasic/study/oscillation_advisor.hpp"
#include "biphasic/time/backward_euler.hpp"
#include "biphasic/time/bdf_integrator.hpp"

namespace biphasic {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Replaces the file by the JSON text, checked; a reader never sees half a file.
void write_json_atomically(const fs::path& path, const nlohmann::json& j) {
  write_file_atomically(path.string(), j.dump(2) + '\n');
}

}  // namespace

Mesh build_mesh(const Config& config, const std::string& output_dir, bool* from_cache) {
  // The case-file check confines write_msh to the output folder (relative, no '..').
  auto in_output_dir = [&](std::string path) {
    if (!path.empty() && fs::path(path).is_relative()) {
      path = (fs::path(output_dir) / path).string();
      fs::create_directories(fs::path(path).parent_path());
    }
    return path;
  };
  // Generated meshes: from the cache unless a .msh file of the generated mesh is asked for.
  auto generated = [&](const auto& spec, const auto& generate) {
    if (!spec.write_msh.empty()) return generate(spec);
    CachedMesh cached =
        cached_mesh(mesh_cache_directory(), mesh_description(spec), [&] { return generate(spec); });
    if (from_cache) *from_cache = cached.from_cache;
    return std::move(cached.mesh);
  };
  if (from_cache) *from_cache = false;
  switch (config.mesh.source) {
    case MeshSource::File:
      return read_gmsh(config.mesh.file);
    case MeshSource::Column:
      return generate_column(config.mesh.column);
    case MeshSource::Section:
      throw std::logic_error("build_mesh: a section mesh is built by build_case_section_mesh");
    case MeshSource::SphereOctant: {
      SphereOctantSpec spec = config.mesh.sphere_octant;
      spec.write_msh = in_output_dir(config.mesh.cylinder.write_msh);
      return generated(spec, generate_sphere_octant);
    }
    case MeshSource::QuarterCylinder:
      break;
  }
  QuarterCylinderSpec spec = config.mesh.cylinder;
  spec.write_msh = in_output_dir(spec.write_msh);
  return generated(spec, generate_quarter_cylinder);
}

std::string dependency_versions() {
  std::ostringstream s;
  s << "SUNDIALS " << SUNDIALS_VERSION << ", SuiteSparse " << SUITESPARSE_MAIN_VERSION << '.'
    << SUITESPARSE_SUB_VERSION << '.' << SUITESPARSE_SUBSUB_VERSION << " (KLU " << KLU_MAIN_VERSION
    << '.' << KLU_SUB_VERSION << '.' << KLU_SUBSUB_VERSION << "), METIS " << METIS_VER_MAJOR << '.'
    << METIS_VER_MINOR << '.' << METIS_VER_SUBMINOR << ", gmsh " << GMSH_API_VERSION << ", HDF5 "
    << H5_VERS_MAJOR << '.' << H5_VERS_MINOR << '.' << H5_VERS_RELEASE << ", Eigen "
    << EIGEN_WORLD_VERSION << '.' << EIGEN_MAJOR_VERSION << '.' << EIGEN_MINOR_VERSION
    << ", toml++ " << TOML_LIB_MAJOR << '.' << TOML_LIB_MINOR << '.' << TOML_LIB_PATCH;
  return s.str();
}

namespace {

/// Everything of run_case after the output folder is ready: mesh, problem, integrator, outputs.
/// Fills `summary` and writes it at outputs and at the end; the caller records failures.
void solve_into(const Config& config, const RunOptions& options, const fs::path& out_dir,
                nlohmann::json& summary, Clock::time_point wall0, const Checkpoint* resume) {
  std::ostream& log = std::cout;
  auto say = [&](const std::string& line) {
    if (!options.quiet) log << line << std::endl;
  };
  const fs::path summary_path = out_dir / "summary.json";

  say("biphasic " + std::string(BIPHASIC_VERSION) + ": " +
      (config.title.empty() ? config.case_file : config.title));
  // The mesh and the problem: tetrahedra, or a two-dimensional section.
  const bool planar = is_two_dimensional(config.model);
  auto t0 = Clock::now();
  bool mesh_from_cache = false;
  std::unique_ptr<Mesh> mesh3;
  std::unique_ptr<SectionMesh> mesh2;
  if (planar)
    mesh2 = std::make_unique<SectionMesh>(build_case_section_mesh(config));
  else
    mesh3 = std::make_unique<Mesh>(build_case_mesh(config, out_dir.string(), &mesh_from_cache));
  const double mesh_seconds = seconds_since(t0);
  for (const std::string& note :
       planar ? preflight_section(config, *mesh2) : preflight(config, *mesh3))
    say(note);
  std::vector<Probe> probes =
      planar ? build_section_probes(config, *mesh2) : build_probes(config, *mesh3);

  t0 = Clock::now();
  std::unique_ptr<BiphasicModel> problem_ptr;
  if (planar)
    problem_ptr = std::make_unique<SectionProblem>(*mesh2, section_model(config.model), config);
  else
    problem_ptr = std::make_unique<BiphasicProblem>(*mesh3, config);
  BiphasicModel& problem = *problem_ptr;
  const std::unique_ptr<TimeIntegrator> integrator_ptr =
      make_time_integrator(problem, config.time, config.linear_solver, out_dir.string());
  TimeIntegrator& integrator = *integrator_ptr;
  integrator.set_log(say);
  integrator.set_progress_interval(options.progress_interval);
  const double setup_seconds = seconds_since(t0);
  const fs::path checkpoint_path = out_dir / kCheckpointName;
  const std::uint64_t case_hash = planar ? case_fingerprint(config, mesh2->nodes, mesh2->triangles)
                                         : case_fingerprint(config, mesh3->nodes, mesh3->tets);
  if (resume) {
    accept_checkpoint(*resume, checkpoint_path.string(), case_hash, problem.size(), config.time);
    try {
      integrator.set_resume_state(resume->integrator_state);
    } catch (const std::invalid_argument& e) {
      throw CheckpointError("checkpoint " + checkpoint_path.string() + " is damaged: " + e.what());
    }
    say(restart_note(*resume, checkpoint_path.string()));
    write_json_atomically(summary_path, summary);
  }
  const Index num_nodes = planar ? mesh2->num_nodes() : mesh3->num_nodes();
  const Index num_vertices = planar ? mesh2->num_vertices : mesh3->num_vertices;
  summary["mesh"] = {{"nodes", num_nodes},
                     {"vertices", num_vertices},
                     {planar ? "triangles" : "tetrahedra", problem.num_elements()},
                     {"unknowns", problem.size()},
                     {"displacement_unknowns", problem.num_u()},
                     {"pressure_unknowns", problem.size() - problem.num_u()},
                     {"jacobian_nonzeros", problem.pattern().nnz()}};
  {
    // The body's bounding box [mm] (z = 0 for a section): what strains are measured against.
    const auto [lo, hi] = planar ? bounding_box(*mesh2) : bounding_box(*mesh3);
    summary["mesh"]["bounds"] = {{"min", lo}, {"max", hi}};
  }
  summary["model"] = to_string(config.model);
  {
    std::ostringstream s;
    s << "mesh: " << num_nodes << " nodes (" << num_vertices << " vertices), "
      << problem.num_elements()
      << (planar ? " triangles (" + to_string(config.model) + ")" : " tetrahedra") << ", "
      << problem.size() << " unknowns, " << problem.pattern().nnz() << " Jacobian nonzeros ("
      << mesh_seconds << " s" << (mesh_from_cache ? ", from the mesh cache" : "") << ")";
    say(s.str());
  }
  if (config.linear_solver.type == LinearSolverType::Iterative && problem.has_gls()) {
    // The GLS term adds c_j c_e ∫ div f div δu to the displacement block: a grad–div penalty
    // that algebraic multigrid handles poorly once it outweighs the solid's λ + 2μ.
    // Largest c_e / H_A over the elements, each with its own material's H_A.
    double ratio = 0.0;
    for (Index e = 0; e < problem.num_elements(); ++e)
      ratio = std::max(
          ratio, problem.gls_coefficient(e) / config.time.dt / problem.laws_of(e).p_wave_modulus());
    summary["gls_penalty_ratio"] = ratio;
    const bool bdf = uses_ida(config.time.integrator);
    if (ratio > 5.0 || bdf) {
      std::ostringstream s;
      s << "note: the GLS term c_j c_e outweighs the solid's lambda + 2 mu in the displacement "
           "block ("
        << (bdf ? "c_j = 1/h grows without bound on BDF's first steps"
                : "ratio up to " + std::to_string(ratio) + " at this dt")
        << "); the iterative solver's multigrid converges slowly or not at all there: a direct "
           "solver or flux_perturbation stabilisation is the better choice";
      say(s.str());
    }
  }

  // First-step oscillation regime at each drained face (r = c dt / h² against its threshold).
  if (planar) {
    summary["advisor"] = {{"note", "not available for two-dimensional models"}};
  } else {
    const OscillationAdvice advice = advise_oscillation(*mesh3, config);
    summary["advisor"] = to_json(advice);
    for (const std::string& line : advice_lines(advice)) say(line);
  }

  // Observers: probes, fields, per-step records. A restart first drops what the earlier run
  // wrote after its checkpoint, then appends.
  const bool append = resume != nullptr;
  ProbeRecorder probe_csv(std::move(probes), problem, out_dir.string(),
                          append ? std::optional<double>(resume->t) : std::nullopt);
  // The field files, written through the output of the model's mesh.
  std::function<void(double, const std::vector<double>&)> write_fields;
  if (!config.output.fields.empty()) {
    const std::optional<double> keep = append ? std::optional<double>(resume->t) : std::nullopt;
    if (planar) {
      auto out = std::make_shared<SectionFieldOutput>(config.output.fields, out_dir.string(),
                                                      *mesh2, keep);
      const auto& section = static_cast<const SectionProblem&>(problem);
      write_fields = [out, &section](double t, const std::vector<double>& y) {
        out->write(section, t, y);
      };
    } else {
      auto out =
          std::make_shared<FieldOutput>(config.output.fields, out_dir.string(), *mesh3, keep);
      const auto& body = static_cast<const BiphasicProblem&>(problem);
      write_fields = [out, &body](double t, const std::vector<double>& y) {
        out->write(body, t, y);
      };
    }
  }
  std::unique_ptr<ReactionCsv> reaction_csv;
  if (!config.output.reactions.empty()) {
    const std::string path = (out_dir / "reactions.csv").string();
    if (append) keep_csv_rows_until(path, resume->t);
    reaction_csv = std::make_unique<ReactionCsv>(path, append);
  }
  std::unique_ptr<PlatenCsv> platen_csv;
  const RigidPlatens& platens = problem.platens();
  if (!platens.empty()) {
    const std::string path = (out_dir / "platens.csv").string();
    if (append) keep_csv_rows_until(path, resume->t);
    platen_csv = std::make_unique<PlatenCsv>(path, append);
    summary["platens"] = platens_description(platens);
  }
  probe_csv.describe(summary);
  const nlohmann::json carried =
      resume ? nlohmann::json::parse(resume->record) : nlohmann::json::object();
  summary["steps"] = carried.value("steps", nlohmann::json::array());
  summary["outputs"] = carried.value("outputs", nlohmann::json::array());

  // Fluid-volume balance (backward Euler only: BDF's observer sees the outputs, not its steps).
  std::unique_ptr<VolumeBalance> balance;
  std::vector<double> u, p;
  // The probes read u with three components per node; a section's third is 0.
  const int components = problem.pattern().components();
  auto split = [&](const std::vector<double>& y) {
    u.assign(y.begin(), y.begin() + problem.num_u());
    if (components == 2) u = displacement_in_3d(u);
    p.assign(y.begin() + problem.num_u(), y.end());
  };
  auto write_output = [&](double t, const std::vector<double>& y, const std::vector<double>& ydot) {
    split(y);
    const std::optional<LineMeasures> m = probe_csv.write(t, u, p);
    if (write_fields) write_fields(t, y);
    nlohmann::json o = m ? measures_json(*m) : nlohmann::json::object();
    o["t"] = t;
    if (reaction_csv) {
      const auto names = BiphasicProblem::reaction_labels(config.output.reactions);
      const auto forces = problem.reactions(config.output.reactions, t, y.data(), ydot.data());
      o["reactions"] = write_reactions(*reaction_csv, t, names, forces);
    }
    if (platen_csv) o["platens"] = write_platens(*platen_csv, platens, t, y.data());
    if (balance) {
      const VolumeBalanceRecord& vb = balance->record();
      const double imbalance = vb.relative_imbalance();
      o["volume_balance"] = {
          {"volume_change", vb.volume_change},
          {"outflow_integrated", vb.outflow_integrated},
          {"source_integrated", vb.source_integrated},
          {"relative_imbalance",
           std::isnan(imbalance) ? nlohmann::json(nullptr) : nlohmann::json(imbalance)}};
    }
    summary["outputs"].push_back(o);
    return m;
  };

  auto record_counters = [&](double wall) {
    const AssemblyStats& as = problem.stats();
    const LinearSolverStats& ls = integrator.linear_solver_stats();
    const IntegratorStats& is = integrator.stats();
    summary["counters"] = {{"steps", is.steps},
                           {"newton_iterations", is.newton_iterations},
                           {"nonlinear_failures", is.nonlinear_failures},
                           {"residual_evaluations", as.residual_evaluations},
                           {"jacobian_evaluations", as.jacobian_evaluations},
                           {"symbolic_analyses", ls.analyses},
                           {"factorizations", ls.factorizations},
                           {"refactorizations", ls.refactorizations},
                           {"linear_solves", ls.solves},
                           {"krylov_iterations", ls.krylov_iterations},
                           {"max_krylov_iterations", ls.max_krylov_iterations},
                           {"amg_cycles", ls.amg_cycles},
                           {"refinement_steps", ls.refinement_steps},
                           {"precision_fallbacks", ls.precision_fallbacks},
                           {"shift_corrected_solves", ls.shift_corrected_solves},
                           {"shift_correction_iterations", ls.shift_correction_iterations},
                           {"shift_correction_failures", ls.shift_correction_failures},
                           {"fill_ratio", ls.fill}};
    if (config.time.integrator == Integrator::BackwardEuler) {
      summary["counters"]["cutbacks"] = is.cutbacks.size();
      nlohmann::json cuts = nlohmann::json::array();
      for (const Cutback& c : is.cutbacks)
        cuts.push_back({{"step", c.step}, {"t", c.t}, {"dt", c.dt}, {"reason", c.reason}});
      summary["cutbacks"] = cuts;
    }
    if (uses_ida(config.time.integrator)) {
      summary["counters"]["error_test_failures"] = is.error_test_failures;
      summary["counters"]["restarts"] = is.restarts;
      const auto [atol_u, atol_p] = absolute_tolerances(problem, config.time.bdf);
      summary["counters"]["absolute_tolerances"] = {{"displacement", atol_u}, {"pressure", atol_p}};
      nlohmann::json starts = nlohmann::json::array();
      for (const auto& st : is.starts)
        starts.push_back({{"t", st.t},
                          {"residual_u", st.residual_u},
                          {"residual_p", st.residual_p},
                          {"pressure_solved", st.pressure_solved}});
      summary["counters"]["consistent_starts"] = starts;
      summary["counters"]["steps_per_order"] = is.order_counts;
      if (!is.step_sizes.empty()) {
        // Linear time (nth_element, not a sort): this runs at every checkpoint.
        std::vector<double> h = is.step_sizes;
        const auto median = h.begin() + static_cast<std::ptrdiff_t>(h.size() / 2);
        std::nth_element(h.begin(), median, h.end());
        const auto [min, max] = std::minmax_element(h.begin(), h.end());
        summary["counters"]["step_size"] = {{"min", *min}, {"median", *median}, {"max", *max}};
      }
    }
    const double assembly = as.residual_seconds + as.jacobian_seconds;
    const double linear = ls.analysis_seconds + ls.factor_seconds + ls.solve_seconds;
    summary["timings"] = {{"wall", wall},
                          {"mesh", mesh_seconds},
                          {"setup", setup_seconds},
                          {"residual_assembly", as.residual_seconds},
                          {"jacobian_assembly", as.jacobian_seconds},
                          {"symbolic_analysis", ls.analysis_seconds},
                          {"factorization", ls.factor_seconds},
                          {"linear_solve", ls.solve_seconds},
                          {"other", wall - mesh_seconds - setup_seconds - assembly - linear}};
    // After a restart: the totals the checkpoint carried plus this segment's work.
    for (const char* key : {"counters", "timings", "cutbacks"})
      if (carried.contains(key) && summary.contains(key))
        summary[key] = combine_segments(carried[key], summary[key]);
  };

  std::vector<double> y(problem.size(), 0.0);
  problem.apply_dirichlet(0.0, y.data(), nullptr);
  if (auto* be = dynamic_cast<BackwardEuler*>(&integrator)) {
    balance = std::make_unique<VolumeBalance>(problem, y);  // ΔV from the state at t = 0
    if (resume && carried.contains("volume_balance")) {
      const nlohmann::json& vb = carried["volume_balance"];
      balance->resume({vb.at("volume_change").get<double>(),
                       vb.at("outflow_integrated").get<double>(),
                       vb.at("source_integrated").get<double>()});
    }
    // Step by step, so that sub-steps after a cut-back each count with their own Δt.
    be->set_sub_step_hook(
        [&balance](double t, double dt, const std::vector<double>& ys,
                   const std::vector<double>& ydots) { balance->add_step(t, dt, ys, ydots); });
  }
  // The checkpoint: state, rate, time, output step, and what the summary carries on.
  auto write_restart_point = [&](int step, double t, double last_dt, const std::vector<double>& ys,
                                 const std::vector<double>& ydots) {
    nlohmann::json record{{"steps", summary["steps"]}, {"outputs", summary["outputs"]}};
    record_counters(seconds_since(wall0));  // totals up to this output, earlier segments included
    for (const char* key : {"counters", "timings", "cutbacks"})
      if (summary.contains(key)) record[key] = summary[key];
    if (balance) {
      const VolumeBalanceRecord& vb = balance->record();
      record["volume_balance"] = {{"volume_change", vb.volume_change},
                                  {"outflow_integrated", vb.outflow_integrated},
                                  {"source_integrated", vb.source_integrated}};
    }
    write_checkpoint(checkpoint_path.string(),
                     Checkpoint{case_hash, step, t, last_dt, ys, ydots, record.dump(),
                                integrator.resume_state()});
  };
  double t_start = 0.0;
  int step_offset = 0;  // output steps done before this run (a restart)
  if (resume) {
    y = resume->y;
    t_start = resume->t;
    step_offset = static_cast<int>(resume->step);
  } else {
    const std::vector<double> ydot0(y.size(), 0.0);
    write_output(t_start, y, ydot0);
    write_restart_point(0, t_start, 0.0, y, ydot0);
  }
  const int every = std::max(1, config.output.every);
  const int planned = integrator.planned_outputs();

  constexpr double kSummaryInterval = 1.0;  // s of wall time between summary refreshes
  auto last_summary = Clock::now();
  auto observer = [&](const StepInfo& segment_info, const std::vector<double>& ys,
                      const std::vector<double>& ydots) {
    StepInfo info = segment_info;
    info.step += step_offset;
    nlohmann::json rec = step_record(info);
    const bool output_now = info.step % every == 0 || info.step == planned;
    std::string mid;
    if (output_now) {
      if (const std::optional<LineMeasures> m = write_output(info.t, ys, ydots)) {
        rec["p_mid"] = m->p_mid;
        char buf[128];
        std::snprintf(buf, sizeof buf, "  p_mid %.4e MPa  overshoot %+.3f  oscillation %.3f",
                      m->p_mid, m->defined ? m->overshoot : 0.0, m->defined ? m->oscillation : 0.0);
        mid = buf;
      }
    }
    summary["steps"].push_back(rec);
    if (output_now) write_restart_point(info.step, info.t, info.dt, ys, ydots);
    // Rewriting the whole summary after every step costs time quadratic in the steps (12 s of a
    // 16 s run of 2000 steps); refresh it at outputs, at most once per second, and at the end.
    if (output_now && seconds_since(last_summary) >= kSummaryInterval) {
      record_counters(seconds_since(wall0));
      write_json_atomically(summary_path, summary);
      last_summary = Clock::now();
    }
    char line[256];
    if (uses_ida(config.time.integrator)) {
      std::snprintf(line, sizeof line,
                    "output %4d/%d  t %9.4g s  steps %4d  order %d  h %8.3g s  newton %3d  "
                    "|R_u| %.2e N  |R_p| %.2e mm3/s",
                    info.step, planned, info.t, info.internal_steps, info.order, info.dt,
                    info.newton_iterations, info.residual_u, info.residual_p);
    } else {
      std::snprintf(line, sizeof line,
                    "step %4d/%d  t %9.4g s  dt %8.3g s  newton %2d  jac %d  |R_u| %.2e N  "
                    "|R_p| %.2e mm3/s",
                    info.step, planned, info.t, info.dt, info.newton_iterations, info.setups,
                    info.residual_u, info.residual_p);
    }
    std::string sub;
    if (config.time.integrator == Integrator::BackwardEuler && info.sub_steps > 1)
      sub = "  sub-steps " + std::to_string(info.sub_steps);
    say(line + sub + mid);
  };

  try {
    // A restart from a checkpoint at t_end has nothing left to do.
    if (t_start < config.time.t_end - 1e-9 * config.time.dt) integrator.run(t_start, y, observer);
  } catch (const std::exception&) {
    record_counters(seconds_since(wall0));
    throw;
  }
  summary["status"] = "completed";
  record_counters(seconds_since(wall0));
  write_json_atomically(summary_path, summary);
  {
    const auto& c = summary["counters"];
    std::ostringstream s;
    s << "done: " << c["steps"] << " steps, " << c["newton_iterations"] << " Newton iterations, "
      << c["residual_evaluations"] << " residuals, " << c["jacobian_evaluations"] << " Jacobians, "
      << c["factorizations"] << " factorisations; wall " << summary["timings"]["wall"].get<double>()
      << " s; output in " << out_dir.string();
    say(s.str());
  }
}

}  // namespace

void start_summary(nlohmann::json& summary, const Config& config, const RunOptions& options) {
  summary["status"] = "running";
  summary["case_file"] = config.case_file;
  summary["overrides"] = options.overrides;
  summary["version"] = BIPHASIC_VERSION;
  summary["dependencies"] = dependency_versions();
  summary["configuration"] = config_to_json(config);
}

nlohmann::json run_case(const Config& config, const RunOptions& options) {
  const auto wall0 = Clock::now();
  if (options.restart && !fs::is_directory(options.output_dir))
    throw CheckpointError("nothing to restart: no folder " + options.output_dir);
  const OutputFolder folder(options.output_dir, options.restart     ? EarlierRun::Continue
                                                : options.overwrite ? EarlierRun::Overwrite
                                                                    : EarlierRun::Refuse);
  const fs::path& out_dir = folder.path();
  const fs::path summary_path = out_dir / "summary.json";

  // A restart reads its checkpoint and the earlier summary before anything is written.
  std::optional<Checkpoint> resume;
  nlohmann::json summary;
  if (options.restart) {
    resume = read_checkpoint((out_dir / kCheckpointName).string());
    summary = read_earlier_summary(summary_path);
    record_restart(summary, *resume, options.overrides);
  }
  start_summary(summary, config, options);
  summary.erase("error");
  if (!resume) write_json_atomically(summary_path, summary);

  // From here on every way out leaves a final status in summary.json.
  auto record_failure = [&](const char* status, const nlohmann::json& error) {
    summary["status"] = status;
    summary["error"] = error;
    try {
      write_json_atomically(summary_path, summary);
    } catch (const std::exception& write_error) {
      throw std::runtime_error(error.dump() +
                               "; moreover the summary could not record it: " + write_error.what());
    }
  };
  try {
    solve_into(config, options, out_dir, summary, wall0, resume ? &*resume : nullptr);
  } catch (const CheckpointError&) {
    throw;  // refused before anything was written
  } catch (const CaseError& e) {
    record_failure("invalid", e.problems());
    throw;
  } catch (const std::exception& e) {
    record_failure("failed", e.what());
    throw;
  }
  return summary;
}

}  // namespace biphasic
