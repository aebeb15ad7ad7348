// Case file with --set overrides: the input is TOML text, optionally followed by a NUL byte
// and newline-separated "key=value" overrides. Any input is either a Config or a CaseError
// (listing problems); on success the size estimate of the size guard must be computable.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "biphasic/io/case_file.hpp"
#include "biphasic/io/size_guard.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find('\0');
  const std::string text = input.substr(0, split);
  std::vector<std::string> overrides;
  if (split != std::string::npos) {
    std::istringstream lines(input.substr(split + 1));
    for (std::string line; std::getline(lines, line);) overrides.push_back(line);
  }
  try {
    const biphasic::Config config =
        biphasic::parse_case(text, "fuzz.toml", overrides, "/nonexistent-fuzz-dir");
    volatile double sink = biphasic::estimate_size(config).unknowns;
    (void)sink;
  } catch (const biphasic::CaseError&) {
  }
  return 0;
}
