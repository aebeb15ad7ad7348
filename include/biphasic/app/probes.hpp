// The probes of a run: the probe line (output.line_start → output.line_end, written to line.csv
// and measured for oscillations) and the named [[probe]] lines (probe_<name>.csv), sampled at
// the mesh nodes on the line or at evenly spaced points by interpolation (docs/probes.md).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "biphasic/fe/point_locator.hpp"
#include "biphasic/fe/section_locator.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/io/line_probe.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/study/measures.hpp"

namespace biphasic {

class SemidiscreteSystem;

/// Points of an interpolated probe when `points = 0` and the line does not run along the mesh.
inline constexpr int kDefaultProbePoints = 101;

/// A probe ready to sample.
struct Probe {
  std::string name;  ///< "line" for the probe line, else the [[probe]] name
  std::string key;   ///< where the case file defines it ("output.line_start", "probe[0]")
  std::string file;  ///< CSV file name in the output folder
  LineProbe samples;
  bool measured = false;  ///< the oscillation measures are taken on it (the probe line only)
};

/// `n` ≥ 2 evenly spaced points from a to b (both included), each located in its element
/// and weighted by the element's shape functions there: the 10 P2 functions N_a(ξ) for u, the
/// 4 P1 functions L_c(ξ) for p. Points within `tolerance` [mm] outside the body count as on
/// its surface. Throws std::out_of_range naming the first point outside, its number and how
/// many are outside.
LineProbe interpolating_probe(const Mesh& mesh, const PointLocator& locator, const Point& a,
                              const Point& b, int n, double tolerance);

/// The same on a section mesh: a and b are (x, y, 0) or (r, z, 0) [mm]; each point is located
/// in its triangle and weighted by the 6 P2 functions for u and the 3 P1 functions for p.
/// Samples have positions (x, y, 0). Throws as the three-dimensional one.
LineProbe interpolating_probe(const SectionMesh& mesh, const SectionPointLocator& locator,
                              const Point& a, const Point& b, int n, double tolerance);

/// The probes of `config` on `mesh`: the probe line when output.line is on, then every
/// [[probe]]. A probe with points = 0 samples the mesh nodes on its line when the line runs
/// along the mesh from end to end (runs_along_mesh), else kDefaultProbePoints points; with
/// points = n, n interpolated points. Throws CaseError naming the case file, the key, the probe
/// and the point for points outside the body (beyond 1e-6 of the mesh's bounding-box diagonal).
std::vector<Probe> build_probes(const Config& config, const Mesh& mesh);

/// `biphasic check`: builds the probes on the case's mesh, so that a probe point outside the
/// body is reported before a run. Returns a line per probe saying how it is sampled; throws
/// CaseError.
std::vector<std::string> check_probes(const Config& config, const Mesh& mesh);

/// The probes of `config` on the section mesh of a two-dimensional model, as build_probes:
/// points are given as (x, y, z) in the case file and must lie in the section plane, z = 0
/// (else CaseError naming the key, e.g. output.line_start or probe[0].end); the samples'
/// positions are (x, y, 0) or (r, z, 0). Their displacement() takes u with 3 entries per node:
/// the model's unknowns expanded by displacement_in_3d (field_writer.hpp).
std::vector<Probe> build_section_probes(const Config& config, const SectionMesh& mesh);

/// check_probes for a section mesh.
std::vector<std::string> check_section_probes(const Config& config, const SectionMesh& mesh);

/// Writes every probe's CSV at each output and takes the oscillation measures on the probe
/// line.
class ProbeRecorder {
 public:
  /// Opens (truncates) each probe's CSV in `output_dir`; the drained ends of the probe line
  /// come from the pressure conditions of `problem` (a BiphasicProblem or a SectionProblem).
  /// With `resume_t` (a restart), keeps each file's rows up to that time [s] and appends after
  /// them.
  ProbeRecorder(std::vector<Probe> probes, const SemidiscreteSystem& problem,
                const std::string& output_dir, std::optional<double> resume_t = std::nullopt);
  /// The same with the drained ends from the Dirichlet flags of the one-process layout
  /// (`constrained`, pressures from `first_pressure` on, one per vertex): a distributed run
  /// gathers them on its first process.
  ProbeRecorder(std::vector<Probe> probes, const std::vector<char>& constrained,
                Index first_pressure, const std::string& output_dir,
                std::optional<double> resume_t = std::nullopt);
  ~ProbeRecorder();

  /// The summary's "line" block (start, end, sampling, samples, drained ends; or that there is
  /// no probe line) and, with named probes, its "probes" list.
  void describe(nlohmann::json& summary) const;

  /// Writes a row per sample of every probe at time t [s]; returns the probe line's measures,
  /// or nothing without a probe line. `u` has 3 entries per node (a section model's expanded
  /// by displacement_in_3d), `p` one per vertex.
  std::optional<LineMeasures> write(double t, const std::vector<double>& u,
                                    const std::vector<double>& p);

 private:
  std::vector<Probe> probes_;
  std::vector<std::unique_ptr<LineCsvWriter>> writers_;
  DrainedEnds drained_ = DrainedEnds::None;
};

}  // namespace biphasic
