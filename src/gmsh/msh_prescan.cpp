// Structure checks on .msh files before gmsh's reader sees them (msh_prescan.hpp).
#include "msh_prescan.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace biphasic::detail {

namespace {

// Nodes per element of a gmsh element type; 0 if gmsh does not know the type.
int gmsh_nodes_per_element(int type) {
  const auto properties = gmsh_element_type(type);
  return properties ? properties->num_nodes : 0;
}

// Bytes of `in` after its read position, for a file of `file_size` bytes.
std::uintmax_t bytes_left(std::istream& in, std::uintmax_t file_size) {
  const auto at = in.tellg();
  return at < 0 || static_cast<std::uintmax_t>(at) > file_size
             ? 0
             : file_size - static_cast<std::uintmax_t>(at);
}

template <class T>
bool read_raw(std::istream& in, T& value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof(T)));
}

bool starts_with(const std::string& line, const char* prefix) { return line.rfind(prefix, 0) == 0; }

// The node tags of the $Nodes section read last (gmsh's 2.x reader forgets earlier sections).
class NodeTags {
 public:
  void clear() { tags_.clear(); }
  void add(std::int64_t tag) { tags_.push_back(tag); }
  void seal() { std::sort(tags_.begin(), tags_.end()); }
  bool contains(std::int64_t tag) const {
    return std::binary_search(tags_.begin(), tags_.end(), tag);
  }

 private:
  std::vector<std::int64_t> tags_;
};

[[noreturn]] void throw_missing_node(std::int64_t element, std::int64_t node) {
  throw std::runtime_error("element " + std::to_string(element) + " names node " +
                           std::to_string(node) +
                           ", which no $Nodes section before it defines (a truncated or "
                           "hand-edited file?)");
}

// In format 2.2, tags beyond an element's physical and elementary ones place it in mesh
// partitions; gmsh 4.8 crashes converting partition numbers it does not expect (negative or
// large ones, found by fuzzing), and a partitioned file is not an input of this program.
void check_unpartitioned(std::int64_t element, int num_tags) {
  if (num_tags <= 3) return;
  throw std::runtime_error("element " + std::to_string(element) + " has " +
                           std::to_string(num_tags) +
                           " tags, which place it in mesh partitions: partitioned .msh files are "
                           "not read; save the mesh whole (under mpirun the program partitions "
                           "it itself)");
}

// What a scan learned: the element types met; nullopt = the file is not understood.
using Scan = std::optional<std::set<int>>;

// Format 2.x, ASCII: every $Nodes and $Elements section, read token by token as gmsh reads it
// (section names matched by prefix, as gmsh matches them). A section that cannot be read is
// left where it fails and the scan goes on to the next section, as gmsh's reader goes on: a
// garbled $Elements section before a sound one must not hide the sound one's defects.
Scan scan_v2_ascii(std::istream& in) {
  std::set<int> types;
  NodeTags nodes;
  std::string line, coordinate;
  // Reads one section's entries; false where they cannot be read.
  const auto read_nodes = [&] {
    nodes.clear();
    std::uint64_t count = 0;
    if (!(in >> count)) return false;
    for (std::uint64_t i = 0; i < count; ++i) {
      std::int64_t tag = 0;
      if (!(in >> tag >> coordinate >> coordinate >> coordinate)) return false;
      nodes.add(tag);
    }
    return true;
  };
  const auto read_elements = [&] {
    std::uint64_t count = 0;
    if (!(in >> count)) return false;
    for (std::uint64_t i = 0; i < count; ++i) {
      std::int64_t tag = 0, ignored = 0;
      int type = 0, num_tags = 0;
      if (!(in >> tag >> type >> num_tags) || num_tags < 0) return false;
      check_unpartitioned(tag, num_tags);
      for (int k = 0; k < num_tags; ++k) {
        if (!(in >> ignored)) return false;
      }
      const int num_nodes = gmsh_nodes_per_element(type);
      if (num_nodes <= 0) return false;
      for (int k = 0; k < num_nodes; ++k) {
        std::int64_t node = 0;
        if (!(in >> node)) return false;
        if (!nodes.contains(node)) throw_missing_node(tag, node);
      }
      types.insert(type);
    }
    return true;
  };
  while (std::getline(in, line)) {
    bool read = true;
    if (starts_with(line, "$Nodes")) {
      read = read_nodes();
      nodes.seal();
    } else if (starts_with(line, "$Elements")) {
      read = read_elements();
    } else {
      continue;
    }
    if (!read) in.clear();  // on to the next section header
    std::getline(in, line);
  }
  return types;
}

// Format 2.x, binary (little-endian, as gmsh writes it on this machine): a $Nodes section is an
// ASCII count and then (int tag, 3 doubles) per node; an $Elements section an ASCII count and
// then blocks of (type, count, number of tags) ints, each element (tag, tags, nodes) ints.
Scan scan_v2_binary(std::istream& in, std::uintmax_t file_size) {
  std::string line;
  std::getline(in, line);  // rest of the format line
  int one = 0;
  if (!read_raw(in, one) || one != 1) return std::nullopt;
  const auto left = [&] { return bytes_left(in, file_size); };
  std::set<int> types;
  NodeTags nodes;
  while (std::getline(in, line)) {
    if (starts_with(line, "$Nodes")) {
      nodes.clear();
      std::uint64_t count = 0;
      if (!(in >> count)) return std::nullopt;
      std::getline(in, line);
      constexpr std::uintmax_t bytes_each = sizeof(int) + 3 * sizeof(double);
      if (count > left() / bytes_each) return std::nullopt;
      for (std::uint64_t i = 0; i < count; ++i) {
        int tag = 0;
        std::array<double, 3> x{};
        if (!read_raw(in, tag) || !read_raw(in, x)) return std::nullopt;
        nodes.add(tag);
      }
      nodes.seal();
    } else if (starts_with(line, "$Elements")) {
      std::uint64_t count = 0;
      if (!(in >> count)) return std::nullopt;
      std::getline(in, line);
      std::vector<int> element;
      for (std::uint64_t seen = 0; seen < count;) {
        std::array<int, 3> header{};
        if (!read_raw(in, header)) return std::nullopt;
        const auto [type, in_block, num_tags] = header;
        const int num_nodes = gmsh_nodes_per_element(type);
        if (in_block <= 0 || num_tags < 0 || num_nodes <= 0) return std::nullopt;
        const std::size_t ints_each = 1u + static_cast<std::size_t>(num_tags) + num_nodes;
        if (static_cast<std::uintmax_t>(in_block) > left() / (ints_each * sizeof(int))) {
          return std::nullopt;
        }
        element.resize(ints_each);
        for (int e = 0; e < in_block; ++e) {
          if (!in.read(reinterpret_cast<char*>(element.data()),
                       static_cast<std::streamsize>(ints_each * sizeof(int)))) {
            return std::nullopt;
          }
          check_unpartitioned(element[0], num_tags);
          for (std::size_t k = ints_each - static_cast<std::size_t>(num_nodes); k < ints_each; ++k)
            if (!nodes.contains(element[k])) throw_missing_node(element[0], element[k]);
        }
        types.insert(type);
        seen += static_cast<std::uint64_t>(in_block);
      }
    }
  }
  return types;
}

// Format 4.1, ASCII: the element types of the $Elements section (gmsh's 4.1 reader reports
// missing nodes itself).
Scan scan_v41_ascii(std::istream& in) {
  std::string line;
  while (std::getline(in, line) && !starts_with(line, "$Elements")) {
  }
  if (!in) return std::nullopt;
  std::set<int> types;
  std::size_t blocks = 0, count = 0, min_tag = 0, max_tag = 0;
  if (!(in >> blocks >> count >> min_tag >> max_tag)) return std::nullopt;
  for (std::size_t b = 0; b < blocks; ++b) {
    int dim = 0, entity = 0, type = 0;
    std::size_t in_block = 0;
    if (!(in >> dim >> entity >> type >> in_block)) return std::nullopt;
    types.insert(type);
    std::getline(in, line);
    for (std::size_t i = 0; i < in_block; ++i) {
      if (!std::getline(in, line)) return std::nullopt;
    }
  }
  return types;
}

// Format 4.1, binary: blocks, count, min tag, max tag (size_t); per block dim, entity, type
// (int), count (size_t), then count × (tag + nodes) size_t, skipped.
Scan scan_v41_binary(std::istream& in, std::uintmax_t file_size) {
  std::string line;
  std::getline(in, line);  // rest of the format line
  int one = 0;
  if (!read_raw(in, one) || one != 1) return std::nullopt;
  while (std::getline(in, line) && !starts_with(line, "$Elements")) {
  }
  if (!in) return std::nullopt;
  const auto left = [&] { return bytes_left(in, file_size); };
  std::set<int> types;
  std::array<std::uint64_t, 4> header{};
  if (!read_raw(in, header)) return std::nullopt;
  for (std::uint64_t b = 0; b < header[0]; ++b) {
    std::array<int, 3> block{};
    std::uint64_t in_block = 0;
    if (!read_raw(in, block) || !read_raw(in, in_block)) return std::nullopt;
    const int nodes = gmsh_nodes_per_element(block[2]);
    if (nodes <= 0) return std::nullopt;
    const std::uintmax_t bytes_each = (1u + static_cast<std::uintmax_t>(nodes)) * 8u;
    if (in_block > left() / bytes_each) return std::nullopt;
    types.insert(block[2]);
    in.seekg(static_cast<std::streamoff>(bytes_each * in_block), std::ios::cur);
  }
  return types;
}

// Rejects a $PhysicalNames entry whose dimension is not 0-3: gmsh 4.8's 4.x reader files the
// name under that dimension and then walks a corrupted map (a segmentation fault found by
// fuzzing). The section is text in every format, so the file is read as text; entries are read
// token by token as gmsh reads them, and the scan of a section stops at the first token that is
// not an entry (gmsh reports those itself).
void check_physical_names(std::istream& in) {
  std::string line;
  while (std::getline(in, line)) {
    if (!starts_with(line, "$PhysicalNames")) continue;
    std::uint64_t count = 0;
    if (!(in >> count)) {
      in.clear();
      continue;
    }
    for (std::uint64_t i = 0; i < count; ++i) {
      long long dim = 0, tag = 0;
      if (!(in >> dim >> tag)) break;
      std::getline(in, line);  // the quoted name
      if (dim < 0 || dim > 3) {
        const auto first = line.find_first_not_of(" \t"), last = line.find_last_not_of(" \t\r");
        const std::string name =
            first == std::string::npos ? "" : line.substr(first, last - first + 1);
        throw std::runtime_error("$PhysicalNames entry " + std::to_string(i + 1) + " (" +
                                 std::to_string(dim) + " " + std::to_string(tag) + " " + name +
                                 ") has dimension " + std::to_string(dim) +
                                 "; a physical group has dimension 0, 1, 2 or 3");
      }
    }
    in.clear();
  }
}

// Rejects files whose tetrahedra and triangles do not all have the same order.
void check_single_order(const std::set<int>& types) {
  const bool tet4 = types.count(kGmshTet4) > 0, tet10 = types.count(kGmshTet10) > 0;
  const bool tri3 = types.count(kGmshTri3) > 0, tri6 = types.count(kGmshTri6) > 0;
  if (tet4 && tet10) {
    throw std::runtime_error("mixed element orders: both 4-node and 10-node tetrahedra");
  }
  if (tri3 && tri6) {
    throw std::runtime_error("mixed element orders: both 3-node and 6-node triangles");
  }
  if ((tet4 && tri6) || (tet10 && tri3)) {
    throw std::runtime_error(std::string("mixed element orders: ") + (tet4 ? "4" : "10") +
                             "-node tetrahedra with " + (tri3 ? "3" : "6") + "-node triangles");
  }
}

}  // namespace

std::optional<GmshElementType> gmsh_element_type(int type) {
  GmshElementType properties;
  int dim = 0, order = 0, num_primary = 0;
  std::vector<double> local;
  try {
    gmsh::model::mesh::getElementProperties(type, properties.name, dim, order, properties.num_nodes,
                                            local, num_primary);
  } catch (...) {
    return std::nullopt;
  }
  return properties;
}

void prescan_msh(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if (ec) return;
  {
    std::ifstream names(path, std::ios::binary);
    check_physical_names(names);
  }
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && !starts_with(line, "$MeshFormat")) {
  }
  std::string version;
  int file_type = -1, data_size = 0;
  if (!(in >> version >> file_type >> data_size)) return;
  const bool v2 = starts_with(version, "2");
  if (!v2 && version != "4.1") return;
  Scan types;
  if (file_type == 1) {
    if (data_size != sizeof(std::uint64_t)) return;
    types = v2 ? scan_v2_binary(in, file_size) : scan_v41_binary(in, file_size);
  } else if (file_type == 0) {
    types = v2 ? scan_v2_ascii(in) : scan_v41_ascii(in);
  }
  if (types) check_single_order(*types);
}

}  // namespace biphasic::detail
