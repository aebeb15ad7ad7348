// Mesh cache loader: the input is the body of a cache entry (everything after the
// description: nodes, tets, boundaries) with a valid header and checksum added, so that the
// fuzzer reaches the decoding and validation of entries that pass the checksum. Whatever the
// bytes, cached_mesh must return a valid mesh (from the cache or regenerated), never crash.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_cache.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace {

namespace fs = std::filesystem;

std::uint64_t fnv1a(const std::vector<char>& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

template <class T>
void put(std::vector<char>& bytes, const T& value) {
  const char* p = reinterpret_cast<const char*>(&value);
  bytes.insert(bytes.end(), p, p + sizeof(T));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fs::path dir =
      fs::temp_directory_path() / ("biphasic_fuzz_cache_" + std::to_string(::getpid()));
  static const std::string description = "fuzz column";
  static const biphasic::Mesh column = biphasic::generate_column({});
  static fs::path entry;
  if (entry.empty()) {  // learn the entry's file name from one store
    fs::remove_all(dir);
    biphasic::cached_mesh(dir, description, [] { return column; });
    entry = fs::directory_iterator(dir)->path();
  }
  std::vector<char> bytes;
  const char magic[] = "biphasic-mesh\n";
  bytes.insert(bytes.end(), magic, magic + sizeof magic - 1);
  put<std::uint32_t>(bytes, 1);
  put<std::uint32_t>(bytes, 0x01020304u);
  put<std::uint64_t>(bytes, description.size());
  bytes.insert(bytes.end(), description.begin(), description.end());
  bytes.insert(bytes.end(), reinterpret_cast<const char*>(data),
               reinterpret_cast<const char*>(data) + size);
  put(bytes, fnv1a(bytes));
  std::ofstream(entry, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const biphasic::CachedMesh got = biphasic::cached_mesh(dir, description, [] { return column; });
  biphasic::check_mesh(got.mesh);  // throws (and so crashes the fuzzer) on an invalid mesh
  return 0;
}
