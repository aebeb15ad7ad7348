// reactions.csv: the reaction force of each named boundary at every output time.
#pragma once

#include <array>
#include <fstream>
#include <string>
#include <vector>

namespace biphasic {

/// Long-format CSV `t,boundary,Fx,Fy,Fz` (t in s, F in N), one row per boundary and output time
/// at round-trip precision. Every write is flushed and checked: a full disk stops the run with
/// std::runtime_error naming the file and the cause.
class ReactionCsv {
 public:
  /// Creates (or truncates) `path` and writes the header; with `append`, keeps the rows already
  /// in the file (a restarted run) and writes no header.
  explicit ReactionCsv(const std::string& path, bool append = false);

  void write(double t, const std::vector<std::string>& names,
             const std::vector<std::array<double, 3>>& forces);

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace biphasic
