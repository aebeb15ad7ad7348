// platens.csv: the displacement and force of each rigid platen at every output time.
#pragma once

#include <fstream>
#include <string>

namespace biphasic {

/// Long-format CSV `t,platen,displacement,force` (t in s, the platen's displacement along its
/// component in mm, the prescribed force P(t) it exerts on the body in N), one row per platen
/// and output time at round-trip precision. Every write is flushed and checked: a full disk
/// stops the run with std::runtime_error naming the file and the cause.
class PlatenCsv {
 public:
  /// Creates (or truncates) `path` and writes the header; with `append`, keeps the rows already
  /// in the file (a restarted run) and writes no header.
  explicit PlatenCsv(const std::string& path, bool append = false);

  void write(double t, const std::string& platen, double displacement, double force);

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace biphasic
