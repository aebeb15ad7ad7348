#include "biphasic/parallel/mesh_broadcast.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace biphasic {

namespace {

/// Appends to and reads from a flat byte buffer.
class Buffer {
 public:
  template <class T>
  void put(const T& x) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&x);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    const auto* p = reinterpret_cast<const char*>(v.data());
    bytes.insert(bytes.end(), p, p + v.size() * sizeof(T));
  }
  void put(const std::string& s) { put(std::vector<char>(s.begin(), s.end())); }

  template <class T>
  void get(T& x) {
    take(&x, sizeof(T));
  }
  template <class T>
  void get(std::vector<T>& v) {
    std::uint64_t n = 0;
    get(n);
    v.resize(static_cast<std::size_t>(n));
    take(v.data(), v.size() * sizeof(T));
  }
  void get(std::string& s) {
    std::vector<char> c;
    get(c);
    s.assign(c.begin(), c.end());
  }

  std::vector<char> bytes;

 private:
  void take(void* out, std::size_t n) {
    if (at_ + n > bytes.size()) throw std::runtime_error("mesh broadcast: truncated buffer");
    std::memcpy(out, bytes.data() + at_, n);
    at_ += n;
  }
  std::size_t at_ = 0;
};

}  // namespace

void broadcast_mesh(Mesh& mesh, MPI_Comm comm, int root) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Buffer b;
  if (rank == root) {
    b.put(mesh.nodes);
    b.put(mesh.num_vertices);
    b.put(mesh.tets);
    b.put(static_cast<std::uint64_t>(mesh.boundaries.size()));
    for (const Boundary& s : mesh.boundaries) {
      b.put(s.name);
      b.put(s.faces);
    }
    b.put(static_cast<std::uint64_t>(mesh.node_sets.size()));
    for (const NodeSet& s : mesh.node_sets) {
      b.put(s.name);
      b.put(s.dimension);
      b.put(s.nodes);
    }
    b.put(mesh.file_tags);
    b.put(mesh.tet_region);
    b.put(static_cast<std::uint64_t>(mesh.region_names.size()));
    for (const std::string& name : mesh.region_names) b.put(name);
  }
  // Sizes beyond 2³¹ bytes go in chunks (MPI counts are int).
  std::uint64_t size = b.bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, root, comm);
  if (rank != root) b.bytes.resize(static_cast<std::size_t>(size));
  constexpr std::uint64_t kChunk = 1u << 30;
  for (std::uint64_t at = 0; at < size; at += kChunk)
    MPI_Bcast(b.bytes.data() + at, static_cast<int>(std::min(kChunk, size - at)), MPI_BYTE, root,
              comm);
  if (rank == root) return;
  Mesh m;
  b.get(m.nodes);
  b.get(m.num_vertices);
  b.get(m.tets);
  std::uint64_t count = 0;
  b.get(count);
  m.boundaries.resize(static_cast<std::size_t>(count));
  for (Boundary& s : m.boundaries) {
    b.get(s.name);
    b.get(s.faces);
  }
  b.get(count);
  m.node_sets.resize(static_cast<std::size_t>(count));
  for (NodeSet& s : m.node_sets) {
    b.get(s.name);
    b.get(s.dimension);
    b.get(s.nodes);
  }
  b.get(m.file_tags);
  b.get(m.tet_region);
  b.get(count);
  m.region_names.resize(static_cast<std::size_t>(count));
  for (std::string& name : m.region_names) b.get(name);
  mesh = std::move(m);
}

}  // namespace biphasic
