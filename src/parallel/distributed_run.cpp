#include "biphasic/parallel/distributed_run.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/app/field_output.hpp"
#include "biphasic/app/preflight.hpp"
#include "biphasic/app/probes.hpp"
#include "biphasic/app/restart_support.hpp"
#include "biphasic/app/run.hpp"
#include "biphasic/app/segment_counters.hpp"
#include "biphasic/io/atomic_file.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/io/checkpoint.hpp"
#include "biphasic/io/field_writer.hpp"
#include "biphasic/io/output_folder.hpp"
#include "biphasic/io/platen_csv.hpp"
#include "biphasic/io/reaction_csv.hpp"
#include "biphasic/parallel/collective_failure.hpp"
#include "biphasic/parallel/distributed_field_rows.hpp"
#include "biphasic/parallel/distributed_system.hpp"
#include "biphasic/parallel/mesh_broadcast.hpp"
#include "biphasic/parallel/petsc_check.hpp"
#include "biphasic/physics/field_recovery.hpp"
#include "biphasic/physics/section_field_recovery.hpp"
#include "biphasic/time/backward_euler.hpp"
#include "biphasic/time/bdf_integrator.hpp"

namespace biphasic {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Replaces the file by the JSON text, checked (io/atomic_file.hpp).
void write_json(const fs::path& path, const nlohmann::json& j) {
  write_file_atomically(path.string(), j.dump(2) + '\n');
}

/// Refuses, before any work, what does not run on several processes.
void check_supported(const Config& config) {
  if (config.linear_solver.type == LinearSolverType::Klu ||
      config.linear_solver.type == LinearSolverType::Umfpack)
    throw std::invalid_argument(kOneProcessSolvers);
}

/// BackwardEuler::resume_state() is this many scalars, the same on every process, followed by
/// whole vectors of the system's size: on several processes each holds its owned part of them.
/// BDF's state is empty.
constexpr std::size_t kResumeHeader = BackwardEuler::kResumeHeaderSize;

/// run_collectively, except that a CheckpointError on any process is thrown as one on every
/// process (the lowest such rank's message): a refused restart ends with exit status 1, as on
/// one process, and leaves the summary as it was.
void run_checking_checkpoint(MPI_Comm comm, const std::function<void()>& work) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::string refusal;
  bool refused = false;
  run_collectively(comm, [&] {
    try {
      work();
    } catch (const CheckpointError& e) {
      refused = true;
      refusal = e.what();
    }
  });
  const int mine = refused ? rank : size;
  int speaker = size;
  MPI_Allreduce(&mine, &speaker, 1, MPI_INT, MPI_MIN, comm);
  if (speaker == size) return;
  throw CheckpointError(broadcast_string(refusal, speaker, comm));
}

/// Peak resident memory of this process [GB].
double peak_memory_gb() {
  rusage r{};
  getrusage(RUSAGE_SELF, &r);
  return static_cast<double>(r.ru_maxrss) / (1024.0 * 1024.0);
}

/// Every process's value, on process 0 (elsewhere empty).
std::vector<double> gather(double x, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::vector<double> all(rank == 0 ? static_cast<std::size_t>(size) : 0);
  MPI_Gather(&x, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, 0, comm);
  return all;
}

}  // namespace

nlohmann::json run_distributed(const Config& config, const RunOptions& options, MPI_Comm comm) {
  const auto wall0 = Clock::now();
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  check_supported(config);
  const bool root = rank == 0;
  auto say = [&](const std::string& line) {
    if (root && !options.quiet) std::cout << line << std::endl;
  };

  // Process 0: the output folder, the first summary, the mesh. A restart reads its checkpoint
  // and the earlier summary, and checks the checkpoint against the case and the mesh, before
  // anything is written (as on one process).
  std::unique_ptr<OutputFolder> folder;
  fs::path out_dir, summary_path;
  nlohmann::json summary;
  // The whole mesh: tetrahedra, or the section of a two-dimensional model.
  const bool planar = is_two_dimensional(config.model);
  const Index d = planar ? 2 : 3;  // displacement components per node
  Mesh mesh;
  SectionMesh section;
  double mesh_seconds = 0.0;
  std::optional<Checkpoint> resume;          // on process 0
  std::vector<std::string> preflight_notes;  // on process 0
  std::uint64_t case_hash = 0;               // on process 0
  run_checking_checkpoint(comm, [&] {
    if (!root) return;
    if (options.restart && !fs::is_directory(options.output_dir))
      throw CheckpointError("nothing to restart: no folder " + options.output_dir);
    try {
      folder = std::make_unique<OutputFolder>(options.output_dir,
                                              options.restart     ? EarlierRun::Continue
                                              : options.overwrite ? EarlierRun::Overwrite
                                                                  : EarlierRun::Refuse);
    } catch (const OutputFolderError& e) {
      throw std::invalid_argument(e.what());  // found before any work, as in one process
    }
    out_dir = folder->path();
    summary_path = out_dir / "summary.json";
    if (options.restart) {
      resume = read_checkpoint((out_dir / kCheckpointName).string());
      summary = read_earlier_summary(summary_path);
      record_restart(summary, *resume, options.overrides);
    }
    start_summary(summary, config, options);
    summary.erase("error");
    if (!resume) write_json(summary_path, summary);
    const auto t0 = Clock::now();
    if (planar)
      section = build_case_section_mesh(config);
    else
      mesh = build_mesh(config, out_dir.string());
    mesh_seconds = seconds_since(t0);
    // The one-process fingerprint: the checkpoint does not depend on the process count.
    case_hash = planar ? case_fingerprint(config, section.nodes, section.triangles)
                       : case_fingerprint(config, mesh.nodes, mesh.tets);
    // The one-process checks before the first step (conflicting conditions, free rigid-body
    // modes, ...): bad input, refused with exit status 1 as in one process.
    try {
      preflight_notes = planar ? preflight_section(config, section) : preflight(config, mesh);
    } catch (const CaseError& e) {
      throw std::invalid_argument(e.report());
    }
    if (resume) {
      const std::string path = (out_dir / kCheckpointName).string();
      const std::size_t whole =
          planar ? static_cast<std::size_t>(2 * section.num_nodes() + section.num_vertices)
                 : static_cast<std::size_t>(3 * mesh.num_nodes() + mesh.num_vertices);
      accept_checkpoint(*resume, path, case_hash, whole, config.time);
      // The integrator's state must split into its header and whole vectors (or be empty).
      const std::size_t m = resume->integrator_state.size();
      if (m != 0 && (m < kResumeHeader || (m - kResumeHeader) % whole != 0 ||
                     (m - kResumeHeader) / whole > 3))
        throw CheckpointError("checkpoint " + path + " is damaged: an integrator state of " +
                              std::to_string(m) + " values does not fit " + std::to_string(whole) +
                              " unknowns");
    }
  });
  auto record_failure = [&](const char* status, const std::string& message) {
    if (!root) return;
    summary["status"] = status;
    summary["error"] = message;
    try {
      write_json(summary_path, summary);
    } catch (const std::exception&) {
    }
  };

  for (const std::string& note : preflight_notes) say(note);
  try {
    if (planar)
      broadcast_mesh(section, comm);
    else
      broadcast_mesh(mesh, comm);
    const Index num_nodes = planar ? section.num_nodes() : mesh.num_nodes();
    const Index num_vertices = planar ? section.num_vertices : mesh.num_vertices;
    const std::size_t num_elements = planar ? section.triangles.size() : mesh.tets.size();
    const auto setup0 = Clock::now();
    const std::unique_ptr<DistributedAssembly> assembly_ptr =
        planar ? std::make_unique<DistributedAssembly>(section, config, comm)
               : std::make_unique<DistributedAssembly>(mesh, config, comm);
    DistributedAssembly& assembly = *assembly_ptr;
    DistributedSystem system(assembly);
    std::unique_ptr<TimeIntegrator> integrator;
    run_collectively(comm, [&] {
      integrator = make_time_integrator(system, config.time, config.linear_solver,
                                        root ? out_dir.string() : std::string());
    });
    if (root) integrator->set_log(say);
    integrator->set_progress_interval(options.progress_interval);
    const PartitionedNumbering& numbering = assembly.numbering();
    const Index n_global = numbering.size();

    // Gathers of owned arrays into the rank-major whole on process 0.
    std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size));
    for (int r = 0; r < size; ++r) {
      const auto ri = static_cast<std::size_t>(r);
      counts[ri] = static_cast<int>(numbering.offset[ri + 1] - numbering.offset[ri]);
      displs[ri] = static_cast<int>(numbering.offset[ri]);
    }
    // Unknown i of the one-process layout is rank-major unknown whole_to_rank_major[i].
    const std::vector<Index> whole_to_rank_major =
        root ? rank_major_of_whole(num_vertices, numbering) : std::vector<Index>();
    // The Dirichlet flags of the whole system in the one-process layout (the probe line's
    // drained ends).
    std::vector<char> constrained_all(whole_to_rank_major.size());
    {
      std::vector<char> flags(root ? static_cast<std::size_t>(n_global) : 0);
      MPI_Gatherv(system.constrained().data(), static_cast<int>(system.size()), MPI_CHAR,
                  flags.data(), counts.data(), displs.data(), MPI_CHAR, 0, comm);
      for (std::size_t i = 0; i < whole_to_rank_major.size(); ++i)
        constrained_all[i] = flags[static_cast<std::size_t>(whole_to_rank_major[i])];
    }

    // States in the one-process layout (checkpoints, outputs) and back (collective).
    std::vector<double> partitioned(root ? static_cast<std::size_t>(n_global) : 0);
    // An owned array gathered on process 0 in the one-process layout (elsewhere empty).
    auto to_whole = [&](const double* owned) {
      MPI_Gatherv(owned, static_cast<int>(system.size()), MPI_DOUBLE, partitioned.data(),
                  counts.data(), displs.data(), MPI_DOUBLE, 0, comm);
      std::vector<double> whole(whole_to_rank_major.size());
      for (std::size_t i = 0; i < whole.size(); ++i)
        whole[i] = partitioned[static_cast<std::size_t>(whole_to_rank_major[i])];
      return whole;
    };
    // The inverse: each process's owned part of a whole array given on process 0.
    auto to_owned = [&](const double* whole) {
      for (std::size_t i = 0; i < whole_to_rank_major.size(); ++i)
        partitioned[static_cast<std::size_t>(whole_to_rank_major[i])] = whole[i];
      std::vector<double> owned(static_cast<std::size_t>(system.size()));
      MPI_Scatterv(partitioned.data(), counts.data(), displs.data(), MPI_DOUBLE, owned.data(),
                   static_cast<int>(owned.size()), MPI_DOUBLE, 0, comm);
      return owned;
    };
    // The integrator's resume state on process 0 as one process would hold it: the header,
    // then each of its vectors gathered.
    auto whole_resume_state = [&] {
      const std::vector<double> mine = integrator->resume_state();
      std::vector<double> whole;
      if (mine.empty()) return whole;  // BDF, on every process
      const auto n = static_cast<std::size_t>(system.size());
      run_collectively(comm, [&] {
        if (mine.size() < kResumeHeader || (mine.size() - kResumeHeader) % n != 0)
          throw std::logic_error("the integrator's resume state of " + std::to_string(mine.size()) +
                                 " values does not fit " + std::to_string(n) + " owned unknowns");
      });
      if (root) whole.assign(mine.begin(), mine.begin() + kResumeHeader);
      for (std::size_t at = kResumeHeader; at < mine.size(); at += n) {
        const std::vector<double> part = to_whole(mine.data() + at);
        whole.insert(whole.end(), part.begin(), part.end());
      }
      return whole;
    };
    // The inverse: this process's resume state from the whole one on process 0 (whose size
    // the checkpoint's check has confirmed).
    auto owned_resume_state = [&](const std::vector<double>& whole) {
      const auto n = static_cast<std::size_t>(n_global);
      long long shape[2] = {0, 0};  // header values, vectors
      if (root && !whole.empty()) {
        shape[0] = static_cast<long long>(kResumeHeader);
        shape[1] = static_cast<long long>((whole.size() - kResumeHeader) / n);
      }
      MPI_Bcast(shape, 2, MPI_LONG_LONG, 0, comm);
      std::vector<double> mine(static_cast<std::size_t>(shape[0]));
      if (root) std::copy_n(whole.begin(), mine.size(), mine.begin());
      MPI_Bcast(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, 0, comm);
      for (long long b = 0; b < shape[1]; ++b) {
        const std::vector<double> part = to_owned(
            root ? whole.data() + kResumeHeader + static_cast<std::size_t>(b) * n : nullptr);
        mine.insert(mine.end(), part.begin(), part.end());
      }
      return mine;
    };

    // A restart: every process takes its part of the checkpoint's state, and the integrator
    // continues from the checkpoint's time as if never stopped.
    std::vector<double> y(static_cast<std::size_t>(system.size()), 0.0);
    double t_start = 0.0;
    int step_offset = 0;  // output steps done before this run
    if (options.restart) {
      double where[2] = {0.0, 0.0};  // t, output step
      if (root) {
        where[0] = resume->t;
        where[1] = static_cast<double>(resume->step);
      }
      MPI_Bcast(where, 2, MPI_DOUBLE, 0, comm);
      t_start = where[0];
      step_offset = static_cast<int>(where[1]);
      y = to_owned(root ? resume->y.data() : nullptr);
      const std::vector<double> state =
          owned_resume_state(root ? resume->integrator_state : std::vector<double>());
      const std::string path =
          (fs::path(root ? out_dir.string() : options.output_dir) / kCheckpointName).string();
      run_checking_checkpoint(comm, [&] {
        try {
          integrator->set_resume_state(state);
        } catch (const std::invalid_argument& e) {
          throw CheckpointError("checkpoint " + path + " is damaged: " + e.what());
        }
      });
      if (root) {
        say(restart_note(*resume, path));
        write_json(summary_path, summary);
      }
    } else {
      system.apply_dirichlet(0.0, y.data(), nullptr);
    }
    // What the checkpoint carries on: per-step records, outputs, totals of the earlier segments.
    const nlohmann::json carried =
        root && resume ? nlohmann::json::parse(resume->record) : nlohmann::json::object();

    std::unique_ptr<ProbeRecorder> probes;
    std::unique_ptr<ReactionCsv> reaction_csv;
    std::unique_ptr<PlatenCsv> platen_csv;
    std::unique_ptr<FieldWriter> fields;
    const RigidPlatens& platens = assembly.platens().platens();  // the whole mesh's
    run_collectively(comm, [&] {
      if (!root) return;
      std::vector<Probe> lines;
      try {
        lines = planar ? build_section_probes(config, section) : build_probes(config, mesh);
      } catch (const CaseError& e) {  // a probe outside the body: bad input (exit status 1)
        throw std::invalid_argument(e.what());
      }
      // A restart drops what the earlier run wrote after its checkpoint, then appends.
      const std::optional<double> keep = resume ? std::optional<double>(resume->t) : std::nullopt;
      probes = std::make_unique<ProbeRecorder>(std::move(lines), constrained_all, d * num_nodes,
                                               out_dir.string(), keep);
      probes->describe(summary);
      if (!config.output.reactions.empty()) {
        const std::string path = (out_dir / "reactions.csv").string();
        if (keep) keep_csv_rows_until(path, *keep);
        reaction_csv = std::make_unique<ReactionCsv>(path, keep.has_value());
      }
      if (!platens.empty()) {  // as one process records them, unknowns in its layout
        const std::string path = (out_dir / "platens.csv").string();
        if (keep) keep_csv_rows_until(path, *keep);
        platen_csv = std::make_unique<PlatenCsv>(path, keep.has_value());
        summary["platens"] = platens_description(platens);
      }
    });

    // One fields.h5, written by all processes together (parallel HDF5): each writes a block of
    // the rows, and scatters bring its rows' values from the processes that own them.
    const SubdomainMap& sub = assembly.subdomain();
    const FieldLayout layout = field_layout(config.output.fields);
    std::vector<int> owned_tets;  // local indices of the owned elements
    for (std::size_t e = 0; e < sub.element_owned.size(); ++e)
      if (sub.element_owned[e]) owned_tets.push_back(static_cast<int>(e));
    std::unique_ptr<DistributedFieldRows> field_rows;
    if (!config.output.fields.empty()) {
      const std::string dir = broadcast_string(out_dir.string(), 0, comm);
      // A restart continues the file from the checkpoint's time (known on every process).
      const std::optional<double> keep =
          options.restart ? std::optional<double>(t_start) : std::nullopt;
      std::vector<Index> owned_cells(owned_tets.size());
      for (std::size_t k = 0; k < owned_tets.size(); ++k)
        owned_cells[k] = sub.global_element[static_cast<std::size_t>(owned_tets[k])];
      run_collectively(comm, [&] {
        field_rows = std::make_unique<DistributedFieldRows>(
            comm, numbering, num_vertices,
            planar ? edge_node_vertices(section) : edge_node_vertices(mesh),
            static_cast<Index>(num_elements), owned_cells);
        const FieldFileShare& share = field_rows->share();
        fields = planar ? std::make_unique<FieldWriter>(dir, "fields", section, layout, share, keep)
                        : std::make_unique<FieldWriter>(dir, "fields", mesh, layout, share, keep);
      });
    }
    const double setup_seconds = seconds_since(setup0);

    // The partition, per process.
    double owned_elements = 0.0;
    for (char c : sub.element_owned) owned_elements += c ? 1.0 : 0.0;
    const std::vector<double> elements = gather(owned_elements, comm);
    const std::vector<double> local_elements =
        gather(static_cast<double>(sub.global_element.size()), comm);
    const std::vector<double> owned_unknowns = gather(static_cast<double>(system.size()), comm);
    if (root) {
      summary["mesh"] = {{"nodes", num_nodes},
                         {"vertices", num_vertices},
                         {planar ? "triangles" : "tetrahedra", num_elements},
                         {"unknowns", n_global}};
      summary["model"] = to_string(config.model);
      summary["parallel"] = {{"processes", size},
                             {"partitioner", "METIS_PartMeshDual on process 0"},
                             {"owned_elements", elements},
                             {"elements_with_ghosts", local_elements},
                             {"owned_unknowns", owned_unknowns}};
      summary["steps"] = carried.value("steps", nlohmann::json::array());
      summary["outputs"] = carried.value("outputs", nlohmann::json::array());
    }

    // Cell fields: each process recovers its own elements' values, then its rows of the file
    // are scattered to it.
    auto cell_rows = [&](const std::vector<double>& local) {
      std::vector<std::vector<double>> mine;
      run_collectively(comm, [&] {
        CellFields recovered = planar
                                   ? recover_section_cell_fields(*assembly.section(), local.data())
                                   : recover_cell_fields(*assembly.body(), local.data());
        mine = selected_cell_values(config.output.fields, recovered);
      });
      std::vector<std::vector<double>> rows(mine.size());
      for (std::size_t q = 0; q < mine.size(); ++q) {
        const int width = layout.cells[q].components;
        std::vector<double> owned(owned_tets.size() * static_cast<std::size_t>(width));
        for (std::size_t k = 0; k < owned_tets.size(); ++k)
          std::copy_n(&mine[q][static_cast<std::size_t>(owned_tets[k] * width)], width,
                      &owned[k * static_cast<std::size_t>(width)]);
        rows[q] = field_rows->cell_rows(owned, width);
      }
      return rows;
    };

    // Gathers an owned state into the one-process layout on process 0, u (d per node) and p
    // apart, and for a section u with three components per node (the third 0) for the probes.
    auto to_serial = [&](const std::vector<double>& owned, std::vector<double>& u,
                         std::vector<double>& p, std::vector<double>& u3) {
      const std::vector<double> whole = to_whole(owned.data());
      if (!root) return;
      const auto num_u = static_cast<std::ptrdiff_t>(d * num_nodes);
      u.assign(whole.begin(), whole.begin() + num_u);
      p.assign(whole.begin() + num_u, whole.end());
      if (d == 2) u3 = displacement_in_3d(u);
    };
    // Reactions: each process's share from its own elements, summed on process 0.
    Vec owned_view = nullptr;
    petsc_check(VecCreateMPIWithArray(comm, 1, static_cast<PetscInt>(system.size()),
                                      static_cast<PetscInt>(n_global), nullptr, &owned_view),
                "VecCreateMPIWithArray");
    std::vector<double> y_local, ydot_local, u, p, u3;
    auto local_state = [&](const std::vector<double>& owned, std::vector<double>& local) {
      petsc_check(VecPlaceArray(owned_view, owned.data()), "VecPlaceArray");
      assembly.to_local(owned_view, local);
      VecResetArray(owned_view);
    };
    auto write_output = [&](double t, const std::vector<double>& ys,
                            const std::vector<double>& ydots) {
      to_serial(ys, u, p, u3);
      if (fields) {
        std::vector<std::vector<double>> cells;
        if (!layout.cells.empty()) {
          local_state(ys, y_local);
          cells = cell_rows(y_local);
        }
        std::vector<double> u_rows, p_node_rows, p_vertex_rows;
        field_rows->node_rows(ys.data(), u_rows, p_node_rows, p_vertex_rows);
        run_collectively(comm,
                         [&] { fields->write_rows(t, u_rows, p_node_rows, p_vertex_rows, cells); });
      }
      nlohmann::json o{{"t", t}};
      std::optional<LineMeasures> m;
      if (!config.output.reactions.empty()) {
        local_state(ys, y_local);
        local_state(ydots, ydot_local);
        std::vector<std::array<double, 3>> forces;
        run_collectively(comm, [&] {
          forces = assembly.local_problem().reactions(config.output.reactions, t, y_local.data(),
                                                      ydot_local.data());
        });
        std::vector<double> flat(3 * forces.size()), total(flat.size());
        for (std::size_t b = 0; b < forces.size(); ++b)
          for (int c = 0; c < 3; ++c)
            flat[3 * b + static_cast<std::size_t>(c)] = forces[b][static_cast<std::size_t>(c)];
        MPI_Reduce(flat.data(), total.data(), static_cast<int>(flat.size()), MPI_DOUBLE, MPI_SUM, 0,
                   comm);
        if (root) {
          for (std::size_t b = 0; b < forces.size(); ++b)
            for (int c = 0; c < 3; ++c)
              forces[b][static_cast<std::size_t>(c)] = total[3 * b + static_cast<std::size_t>(c)];
          const auto names = BiphasicProblem::reaction_labels(config.output.reactions);
          o["reactions"] = write_reactions(*reaction_csv, t, names, forces);
        }
      }
      run_collectively(comm, [&] {
        if (!root) return;
        m = probes->write(t, d == 3 ? u : u3, p);
        // u: the displacements in the one-process layout, where the platens' unknowns point.
        if (platen_csv) o["platens"] = write_platens(*platen_csv, platens, t, u.data());
        if (m) o.update(measures_json(*m));  // the entry a one-process run records
        summary["outputs"].push_back(o);
      });
      return m;
    };

    auto record_counters = [&] {
      const AssemblyStats& as = system.stats();
      const LinearSolverStats& ls = integrator->linear_solver_stats();
      const IntegratorStats& is = integrator->stats();
      const std::vector<double> wall = gather(seconds_since(wall0), comm);
      const std::vector<double> memory = gather(peak_memory_gb(), comm);
      const std::vector<double> assembly_seconds =
          gather(as.residual_seconds + as.jacobian_seconds, comm);
      const std::vector<double> factor_seconds = gather(ls.factor_seconds, comm);
      if (!root) return;
      summary["counters"] = {{"steps", is.steps},
                             {"newton_iterations", is.newton_iterations},
                             {"nonlinear_failures", is.nonlinear_failures},
                             {"cutbacks", is.cutbacks.size()},
                             {"residual_evaluations", as.residual_evaluations},
                             {"jacobian_evaluations", as.jacobian_evaluations},
                             {"factorizations", ls.factorizations},
                             {"linear_solves", ls.solves},
                             {"krylov_iterations", ls.krylov_iterations},
                             {"max_krylov_iterations", ls.max_krylov_iterations},
                             {"amg_cycles", ls.amg_cycles},
                             {"symbolic_analyses", ls.analyses},
                             {"refinement_steps", ls.refinement_steps},
                             {"precision_fallbacks", ls.precision_fallbacks},
                             {"shift_corrected_solves", ls.shift_corrected_solves},
                             {"shift_correction_iterations", ls.shift_correction_iterations},
                             {"shift_correction_failures", ls.shift_correction_failures}};
      // The parallel MUMPS' factor entries over nnz(J), as in one process (0: no factors).
      if (ls.fill > 0.0) summary["counters"]["fill_ratio"] = ls.fill;
      summary["timings"] = {{"wall", wall[0]},
                            {"mesh", mesh_seconds},
                            {"setup", setup_seconds},
                            {"residual_assembly", as.residual_seconds},
                            {"jacobian_assembly", as.jacobian_seconds},
                            {"factorization", ls.factor_seconds},
                            {"linear_solve", ls.solve_seconds}};
      summary["parallel"]["wall_seconds"] = wall;
      summary["parallel"]["peak_memory_gb"] = memory;
      summary["parallel"]["assembly_seconds"] = assembly_seconds;
      summary["parallel"]["factorization_seconds"] = factor_seconds;
      if (config.time.integrator == Integrator::BackwardEuler) {
        nlohmann::json cuts = nlohmann::json::array();
        for (const Cutback& c : is.cutbacks)
          cuts.push_back({{"step", c.step}, {"t", c.t}, {"dt", c.dt}, {"reason", c.reason}});
        summary["cutbacks"] = cuts;
      }
      // After a restart: the totals the checkpoint carried plus this segment's work.
      for (const char* key : {"counters", "timings", "cutbacks"})
        if (carried.contains(key) && summary.contains(key))
          summary[key] = combine_segments(carried[key], summary[key]);
    };

    // The checkpoint (process 0 writes it), in the one-process layout: state, rate, time, output
    // step, the integrator's resume state, and what the summary carries on (collective).
    const std::string checkpoint_path = (out_dir / kCheckpointName).string();
    auto write_restart_point = [&](int step, double t, double last_dt,
                                   const std::vector<double>& ys,
                                   const std::vector<double>& ydots) {
      std::vector<double> y_whole = to_whole(ys.data());
      std::vector<double> ydot_whole = to_whole(ydots.data());
      std::vector<double> state = whole_resume_state();
      nlohmann::json record;
      if (root) record = {{"steps", summary["steps"]}, {"outputs", summary["outputs"]}};
      record_counters();  // totals up to this output, earlier segments included
      run_collectively(comm, [&] {
        if (!root) return;
        for (const char* key : {"counters", "timings", "cutbacks"})
          if (summary.contains(key)) record[key] = summary[key];
        write_checkpoint(checkpoint_path,
                         Checkpoint{case_hash, step, t, last_dt, std::move(y_whole),
                                    std::move(ydot_whole), record.dump(), std::move(state)});
      });
    };

    if (!options.restart) {
      const std::vector<double> ydot0(y.size(), 0.0);
      write_output(0.0, y, ydot0);
      write_restart_point(0, 0.0, 0.0, y, ydot0);
    }
    const int every = std::max(1, config.output.every);
    const int planned = integrator->planned_outputs();
    auto observer = [&](const StepInfo& segment_info, const std::vector<double>& ys,
                        const std::vector<double>& ydots) {
      StepInfo info = segment_info;
      info.step += step_offset;
      const bool output_now = info.step % every == 0 || info.step == planned;
      std::string mid;
      std::optional<LineMeasures> m;
      if (output_now) m = write_output(info.t, ys, ydots);
      if (m) {
        char buf[128];
        std::snprintf(buf, sizeof buf, "  p_mid %.4e MPa  overshoot %+.3f  oscillation %.3f",
                      m->p_mid, m->defined ? m->overshoot : 0.0, m->defined ? m->oscillation : 0.0);
        mid = buf;
      }
      if (root) {
        nlohmann::json rec = step_record(info);
        if (m) rec["p_mid"] = m->p_mid;
        summary["steps"].push_back(rec);
      }
      if (output_now) write_restart_point(info.step, info.t, info.dt, ys, ydots);
      char line[256];
      if (uses_ida(config.time.integrator))
        std::snprintf(line, sizeof line,
                      "output %4d/%d  t %9.4g s  steps %4d  order %d  h %8.3g s  newton %3d  "
                      "|R_u| %.2e N  |R_p| %.2e mm3/s",
                      info.step, planned, info.t, info.internal_steps, info.order, info.dt,
                      info.newton_iterations, info.residual_u, info.residual_p);
      else
        std::snprintf(line, sizeof line,
                      "step %4d/%d  t %9.4g s  dt %8.3g s  newton %2d  jac %d  |R_u| %.2e N  "
                      "|R_p| %.2e mm3/s",
                      info.step, planned, info.t, info.dt, info.newton_iterations, info.setups,
                      info.residual_u, info.residual_p);
      say(line + mid);
    };
    // A restart from a checkpoint at t_end has nothing left to do.
    if (t_start < config.time.t_end - 1e-9 * config.time.dt) integrator->run(t_start, y, observer);
    VecDestroy(&owned_view);
    record_counters();
    if (root) {
      summary["status"] = "completed";
      write_json(summary_path, summary);
      std::ostringstream s;
      s << "done on " << size << " processes: " << summary["counters"]["steps"] << " steps, "
        << summary["counters"]["newton_iterations"] << " Newton iterations; wall "
        << summary["timings"]["wall"].get<double>() << " s; output in " << out_dir.string();
      say(s.str());
    }
  } catch (const CheckpointError&) {
    throw;  // refused before anything was written
  } catch (const std::invalid_argument& e) {
    record_failure("invalid", e.what());  // input found bad after the folder was made
    throw;
  } catch (const std::exception& e) {
    record_failure("failed", e.what());
    throw;
  }
  return summary;
}

}  // namespace biphasic
