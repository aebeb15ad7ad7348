// File layout (native byte order, all counts std::uint64_t, indices std::int64_t):
//   "biphasic-mesh\n" (14 bytes), format version (u32), byte-order mark 0x01020304 (u32),
//   description (count + bytes), nodes (count, then x y z doubles), num_vertices,
//   tetrahedra (count, then 10 indices each), boundaries (count, then per boundary: name
//   (count + bytes), faces (count, then 6 indices each)), regions (count of names, then each
//   name (count + bytes); count of per-tet entries, then one i32 each), FNV-1a 64 checksum of
//   all before it. Version 2 added the regions; an entry of another version is a miss and is
//   regenerated and overwritten.
#include "biphasic/mesh/mesh_cache.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "gmsh_backend.hpp"

namespace biphasic {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[] = "biphasic-mesh\n";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;
constexpr std::uint32_t kFormatVersion = 2;
constexpr std::uint32_t kByteOrderMark = 0x01020304u;
/// Largest cache file read back [bytes]; anything larger is treated as a miss (and not stored).
constexpr std::uintmax_t kMaxCacheFileBytes = std::uintmax_t{2} << 30;

/// FNV-1a, 64 bits.
std::uint64_t fnv1a(const char* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex_float(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    const char* p = reinterpret_cast<const char*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void put_bytes(const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    put_bytes(s.data(), s.size());
  }
  std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
};

/// Bounds-checked reading; every failure makes the whole read fail.
class Reader {
 public:
  Reader(const char* data, std::size_t size) : data_(data), size_(size) {}
  template <class T>
  bool get(T& value) {
    return get_bytes(&value, sizeof(T));
  }
  bool get_bytes(void* out, std::size_t size) {
    if (size > size_ - pos_) return false;
    if (size == 0) return true;  // `out` may be the null data() of an empty vector
    std::memcpy(out, data_ + pos_, size);
    pos_ += size;
    return true;
  }
  /// A count of items of `item_size` bytes each that fit in what is left.
  bool get_count(std::uint64_t& n, std::size_t item_size) {
    return get(n) && n <= (size_ - pos_) / item_size;
  }
  bool get_string(std::string& s) {
    std::uint64_t n = 0;
    if (!get_count(n, 1)) return false;
    s.assign(data_ + pos_, n);
    pos_ += n;
    return true;
  }
  std::size_t position() const { return pos_; }

 private:
  const char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

std::vector<char> serialise(const std::string& description, const Mesh& mesh) {
  Writer w;
  w.put_bytes(kMagic, kMagicSize);
  w.put(kFormatVersion);
  w.put(kByteOrderMark);
  w.put_string(description);
  w.put<std::uint64_t>(mesh.nodes.size());
  w.put_bytes(mesh.nodes.data(), mesh.nodes.size() * sizeof(Point));
  w.put<std::int64_t>(mesh.num_vertices);
  w.put<std::uint64_t>(mesh.tets.size());
  w.put_bytes(mesh.tets.data(), mesh.tets.size() * sizeof(Tet10));
  w.put<std::uint64_t>(mesh.boundaries.size());
  for (const Boundary& b : mesh.boundaries) {
    w.put_string(b.name);
    w.put<std::uint64_t>(b.faces.size());
    w.put_bytes(b.faces.data(), b.faces.size() * sizeof(Tri6));
  }
  w.put<std::uint64_t>(mesh.region_names.size());
  for (const std::string& name : mesh.region_names) w.put_string(name);
  w.put<std::uint64_t>(mesh.tet_region.size());
  w.put_bytes(mesh.tet_region.data(), mesh.tet_region.size() * sizeof(int));
  std::vector<char>& bytes = w.bytes();
  const std::uint64_t checksum = fnv1a(bytes.data(), bytes.size());
  w.put(checksum);
  return std::move(bytes);
}

std::optional<Mesh> deserialise(const std::vector<char>& bytes, const std::string& description) {
  if (bytes.size() < kMagicSize + sizeof(std::uint64_t)) return std::nullopt;
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, bytes.data() + body, sizeof checksum);
  if (std::memcmp(bytes.data(), kMagic, kMagicSize) != 0 || fnv1a(bytes.data(), body) != checksum)
    return std::nullopt;
  Reader r(bytes.data() + kMagicSize, body - kMagicSize);
  std::uint32_t version = 0, mark = 0;
  std::string stored;
  if (!r.get(version) || version != kFormatVersion || !r.get(mark) || mark != kByteOrderMark ||
      !r.get_string(stored) || stored != description)
    return std::nullopt;
  Mesh mesh;
  std::uint64_t n = 0;
  if (!r.get_count(n, sizeof(Point))) return std::nullopt;
  mesh.nodes.resize(n);
  if (!r.get_bytes(mesh.nodes.data(), n * sizeof(Point))) return std::nullopt;
  if (!r.get(mesh.num_vertices) || !r.get_count(n, sizeof(Tet10))) return std::nullopt;
  mesh.tets.resize(n);
  if (!r.get_bytes(mesh.tets.data(), n * sizeof(Tet10))) return std::nullopt;
  if (!r.get_count(n, 1)) return std::nullopt;
  mesh.boundaries.resize(n);
  for (Boundary& b : mesh.boundaries) {
    if (!r.get_string(b.name) || !r.get_count(n, sizeof(Tri6))) return std::nullopt;
    b.faces.resize(n);
    if (!r.get_bytes(b.faces.data(), n * sizeof(Tri6))) return std::nullopt;
  }
  if (!r.get_count(n, sizeof(std::uint64_t))) return std::nullopt;
  mesh.region_names.resize(n);
  for (std::string& name : mesh.region_names)
    if (!r.get_string(name)) return std::nullopt;
  if (!r.get_count(n, sizeof(int))) return std::nullopt;
  mesh.tet_region.resize(n);
  if (!r.get_bytes(mesh.tet_region.data(), n * sizeof(int))) return std::nullopt;
  if (r.position() != body - kMagicSize) return std::nullopt;
  return mesh;
}

/// Why a decoded entry cannot be used as a mesh (an index out of range, inconsistent counts,
/// a coordinate that is not finite, a degenerate tet, ...), or nullopt if it is a valid Mesh.
/// A matching checksum only shows the file is what some writer wrote, not that it is sound.
std::optional<std::string> invalid_entry(const Mesh& mesh) {
  if (mesh.tets.empty()) return "no tetrahedra";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    for (const double x : mesh.nodes[i])
      if (!std::isfinite(x)) return "node " + std::to_string(i) + " has a non-finite coordinate";
  try {
    check_mesh(mesh);  // every index in range, corners before edge nodes, faces on tets, volumes
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

/// The bytes of `path` if it is a regular file (not a symbolic link, FIFO, device, ...) of at
/// most kMaxCacheFileBytes; nullopt otherwise. Never blocks on a special file.
std::optional<std::vector<char>> read_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (ec || status.type() != fs::file_type::regular) return std::nullopt;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size > kMaxCacheFileBytes) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::vector<char> bytes(static_cast<std::size_t>(size));
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size || in.peek() != EOF) return std::nullopt;
  return bytes;
}

/// Writes to a temporary file beside `path` and renames it over `path`; false on failure.
bool write_atomically(const fs::path& path, const std::vector<char>& bytes) {
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  std::random_device seed;
  const fs::path temporary =
      path.string() + ".tmp." + std::to_string(getpid()) + '.' + std::to_string(seed());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) {
      out.close();
      fs::remove(temporary, ec);
      return false;
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) fs::remove(temporary, ec);
  return !ec;
}

}  // namespace

fs::path mesh_cache_directory() {
  if (const char* env = std::getenv("BIPHASIC_MESH_CACHE")) {
    const std::string value(env);
    if (value.empty() || value == "off") return {};
    return fs::path(value);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return fs::path(xdg) / "biphasic" / "meshes";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "biphasic" / "meshes";
  return {};
}

std::string mesh_description(const QuarterCylinderSpec& spec) {
  std::ostringstream s;
  s << "quarter_cylinder radius=" << hex_float(spec.radius) << " height=" << hex_float(spec.height)
    << " lc=" << hex_float(spec.lc) << " grading_faces=" << join(spec.grading_faces)
    << " grading_ratio=" << hex_float(spec.grading_ratio)
    << " grading_distance=" << hex_float(spec.grading_distance) << " layers=" << spec.layers
    << " layer_grading_faces=" << join(spec.layer_grading_faces)
    << " layer_grading_ratio=" << hex_float(spec.layer_grading_ratio) << "; "
    << detail::gmsh_backend_identity();
  return s.str();
}

std::string mesh_description(const SphereOctantSpec& spec) {
  std::ostringstream s;
  s << "sphere_octant radius=" << hex_float(spec.radius) << " lc=" << hex_float(spec.lc)
    << " grading_ratio=" << hex_float(spec.grading_ratio)
    << " grading_distance=" << hex_float(spec.grading_distance) << "; "
    << detail::gmsh_backend_identity();
  return s.str();
}

CachedMesh cached_mesh(const fs::path& directory, const std::string& description,
                       const std::function<Mesh()>& generate) {
  if (directory.empty()) return {generate(), false};
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.mesh",
                static_cast<unsigned long long>(fnv1a(description.data(), description.size())));
  const fs::path path = directory / name;
  if (const auto bytes = read_file(path)) {
    if (auto mesh = deserialise(*bytes, description)) {
      const auto problem = invalid_entry(*mesh);
      if (!problem) return {std::move(*mesh), true};
      std::fprintf(stderr, "note: mesh cache entry '%s' is not a valid mesh (%s); regenerating\n",
                   path.c_str(), problem->c_str());
    }
  }
  CachedMesh result{generate(), false};
  const std::vector<char> bytes = serialise(description, result.mesh);
  if (bytes.size() <= kMaxCacheFileBytes) write_atomically(path, bytes);
  return result;
}

}  // namespace biphasic
