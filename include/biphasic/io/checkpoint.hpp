// The state a run needs to continue from an output time (biphasic run CASE --restart DIR).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace biphasic {

/// A checkpoint that cannot be used: missing, damaged (truncated, bad header, bad checksum) or
/// written by another case or mesh. Bad input: exit status 1.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What `checkpoint.bin` holds at one output time.
struct Checkpoint {
  static constexpr std::uint32_t kFormatVersion = 2;
  std::uint64_t case_hash = 0;  ///< case_fingerprint of the physical configuration and the mesh
  std::int64_t step = 0;        ///< output step index k (0: the initial state)
  double t = 0.0;               ///< output time [s]
  double last_dt = 0.0;         ///< length of the last (sub-)step before t [s] (0 at k = 0)
  std::vector<double> y;        ///< state: u [mm] then p [MPa]
  std::vector<double> ydot;     ///< rate ẏ at t [mm/s, MPa/s]
  std::string record;           ///< JSON text: what the summary and observers carry on
  /// What the time integrator needs beyond (t, y) to continue as if never stopped
  /// (TimeIntegrator::resume_state; empty for BDF and in version-1 files).
  std::vector<double> integrator_state;
};

/// Binary layout (native byte order, little-endian on x86-64):
///   16 bytes "BIPHASIC-CKPT" padded with zeros, u32 format version, u32 zero,
///   u64 case_hash, u64 n (unknowns), i64 step, f64 t, f64 last_dt, u64 record length,
///   u64 m (integrator state length), n f64 y, n f64 ydot, m f64 integrator state, the record
///   bytes, and u64 FNV-1a of all bytes before it. Version 1 (read too) has no m and no state.
/// Written atomically (temporary, checked write, fsync, rename): a crash leaves the previous
/// checkpoint. Throws std::runtime_error naming the file and the cause.
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

/// Reads and checks a checkpoint; throws CheckpointError naming the file and what is wrong.
Checkpoint read_checkpoint(const std::string& path);

/// 64-bit FNV-1a of `bytes`, continuing from `seed`.
std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed = 1469598103934665603ULL);

/// Keeps the header and the rows of a CSV file whose first field (a time [s]) is <= t_last,
/// replacing the file atomically: the rows a run wrote after its last checkpoint. Returns the
/// number of rows kept. Throws std::runtime_error if the file cannot be read or written.
std::size_t keep_csv_rows_until(const std::string& path, double t_last);

}  // namespace biphasic
