// gmsh .msh reader (ASCII and binary, formats 2.2 and 4.1): the input is written to a file and
// read, as a tetrahedral mesh and as a section mesh; any file is either a valid Mesh (check_mesh
// passes) or a std::runtime_error, and likewise a valid SectionMesh (check_section_mesh) or one.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/mesh/section_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = (std::filesystem::temp_directory_path() /
                                   ("biphasic_fuzz_" + std::to_string(::getpid()) + ".msh"))
                                      .string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const biphasic::Mesh mesh = biphasic::read_gmsh(path);
    biphasic::check_mesh(mesh);  // must hold for whatever read_gmsh returns
  } catch (const std::runtime_error&) {
  }
  try {
    const biphasic::SectionMesh section = biphasic::read_gmsh_section(path);
    biphasic::check_section_mesh(section);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
