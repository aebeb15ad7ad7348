// Steps shared by the MUMPS wrappers (sequential and parallel builds, double and single
// precision). MUMPS' C headers are the same for both builds (only mpi.h differs, and they do
// not include it). ICNTL/INFOG numbers are MUMPS' 1-based ones.
#pragma once

#include <dmumps_c.h>
#include <smumps_c.h>
#include <sys/statvfs.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "direct_solver.hpp"

namespace biphasic::detail {

/// MUMPS' C interface in double (d) and single (s) precision.
struct DoublePrecision {
  using Struc = DMUMPS_STRUC_C;
  using Real = double;
  static void call(Struc* id) { dmumps_c(id); }
};
struct SinglePrecision {
  using Struc = SMUMPS_STRUC_C;
  using Real = float;
  static void call(Struc* id) { smumps_c(id); }
};

/// A count MUMPS reports in an INFO/INFOG entry: the value itself, or if negative, minus the
/// count in millions.
inline double mumps_count(MUMPS_INT value) { return value >= 0 ? value : -1e6 * value; }

/// Out-of-core factors (ICNTL(22) = 1) when `directory` is not empty: MUMPS writes the factors
/// to files there (named biphasic_mumps*, deleted when the instance ends) as it computes them
/// and reads them back at each solve, keeping in memory only the fronts it is working on. The
/// case file checks that the directory exists, is writable, and that its name fits MUMPS' 255
/// characters. Call before the factorisation.
template <class Struc>
void mumps_factors_out_of_core(Struc& id, const std::string& directory) {
  if (directory.empty()) return;
  id.icntl[21] = 1;
  std::snprintf(id.ooc_tmpdir, sizeof id.ooc_tmpdir, "%s", directory.c_str());
  std::snprintf(id.ooc_prefix, sizeof id.ooc_prefix, "%s", "biphasic_mumps");
}

/// MUMPS' out-of-core failure (INFOG(1) = −90: a factor file could not be written or read, most
/// often because its disk is full) says nothing about the matrix: it throws, so that the run
/// stops with the cause instead of cutting its step back as for a singular matrix.
template <class Struc>
void throw_if_factor_files_failed(const Struc& id) {
  if (id.infog[0] == -90)
    throw std::runtime_error(std::string("MUMPS could not write or read its out-of-core factor "
                                         "files in ") +
                             id.ooc_tmpdir +
                             " (INFOG(1) = -90): is that disk full? "
                             "(linear_solver.out_of_core_directory)");
}

/// Bytes to keep free for this process's out-of-core factor files: the analysis' estimate,
/// INFO(3) factor entries (negative: millions) of `bytes_per_entry` each, and a fifth more
/// (mesh 1's files came to 3 % above the estimate).
template <class Struc>
double factor_file_bytes(const Struc& id, std::size_t bytes_per_entry) {
  return 1.2 * mumps_count(id.info[2]) * static_cast<double>(bytes_per_entry);
}

/// Throws unless `folder` has `bytes` free for this user. Checked after the analysis, before
/// any factor file is written: MUMPS reports a full disk (INFOG(1) = −90) in one process, but
/// in several its asynchronous writer can leave the processes waiting for each other for ever.
/// A folder whose free space cannot be read is left to MUMPS.
inline void require_free_space(const char* folder, double bytes) {
  struct statvfs fs {};
  if (statvfs(folder, &fs) != 0) return;
  const double free = static_cast<double>(fs.f_bavail) * static_cast<double>(fs.f_frsize);
  if (free >= bytes) return;
  char text[512];
  std::snprintf(text, sizeof text,
                "linear_solver.out_of_core: the factor files need about %.3g GB (MUMPS' estimate "
                "after its analysis, and a fifth more) in %s, which has %.3g GB free; free some "
                "or choose another folder (linear_solver.out_of_core_directory)",
                bytes / 1e9, folder, free / 1e9);
  throw std::runtime_error(text);
}

/// Analysis (JOB = 1) of `id`, timed and counted in `stats`; false if MUMPS fails.
template <class Struc, class Call>
bool mumps_analyse(Struc& id, Call call, LinearSolverStats& stats) {
  const auto t0 = Clock::now();
  id.job = 1;
  call(&id);
  stats.analysis_seconds += seconds_since(t0);
  ++stats.analyses;
  return id.infog[0] >= 0;
}

/// Numeric factorisation (JOB = 2) of `id`, timed and counted in `stats`, with the fill
/// nnz(L + U) / `nnz` recorded. Numerical pivoting can outgrow the analysis' estimate of the
/// work space (INFOG(1) = −9, or −8/−14 for the integer one): then ICNTL(14) grows to twice
/// itself plus 20 % and MUMPS factorises again, up to four times. False if MUMPS fails.
template <class Struc, class Call>
bool mumps_factorise(Struc& id, Call call, double nnz, LinearSolverStats& stats) {
  const auto t0 = Clock::now();
  id.job = 2;
  call(&id);
  auto short_of_room = [&] { return id.infog[0] == -8 || id.infog[0] == -9 || id.infog[0] == -14; };
  for (int retry = 0; retry < 4 && short_of_room(); ++retry) {
    id.icntl[13] = 2 * id.icntl[13] + 20;
    call(&id);
  }
  stats.factor_seconds += seconds_since(t0);
  ++stats.factorizations;
  throw_if_factor_files_failed(id);
  if (id.infog[0] < 0) return false;
  stats.fill = mumps_count(id.infog[28]) / nnz;  // INFOG(29): entries in the factors
  return true;
}

}  // namespace biphasic::detail
