// Out-of-core MUMPS factors on disk, as the tests of linear_solver.out_of_core count them.
#pragma once

#include <filesystem>
#include <string>

namespace biphasic::test {

/// Files in `folder` whose names start with the prefix the project gives MUMPS' out-of-core
/// factor files (mumps_steps.hpp: "biphasic_mumps").
inline int mumps_factor_files(const std::filesystem::path& folder) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().filename().string().rfind("biphasic_mumps", 0) == 0) ++count;
  return count;
}

}  // namespace biphasic::test
