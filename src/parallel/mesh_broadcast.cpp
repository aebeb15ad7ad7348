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

/// A flat byte buffer that either writes (`reading` false) or reads the values passed to io():
/// one description of a mesh's layout serves both directions.
class Buffer {
 public:
  explicit Buffer(bool reading) : reading_(reading) {}

  template <class T>
  void io(T& x) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (reading_)
      take(&x, sizeof(T));
    else
      append(&x, sizeof(T));
  }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void io(std::vector<T>& v) {
    std::uint64_t n = v.size();
    io(n);
    if (reading_) {
      v.resize(static_cast<std::size_t>(n));
      take(v.data(), v.size() * sizeof(T));
    } else {
      append(v.data(), v.size() * sizeof(T));
    }
  }
  void io(std::string& s) {
    std::vector<char> c(s.begin(), s.end());
    io(c);
    s.assign(c.begin(), c.end());
  }
  void io(NodeSet& s) {
    io(s.name);
    io(s.dimension);
    io(s.nodes);
  }
  void io(Boundary& b) {
    io(b.name);
    io(b.faces);
  }
  void io(SectionBoundary& b) {
    io(b.name);
    io(b.segments);
  }
  /// A vector of structured values, each through its own io().
  template <class T>
  requires(!std::is_trivially_copyable_v<T>) void io(std::vector<T>& v) {
    std::uint64_t n = v.size();
    io(n);
    v.resize(static_cast<std::size_t>(n));
    for (T& x : v) io(x);
  }

  std::vector<char> bytes;

 private:
  void append(const void* p, std::size_t n) {
    const auto* c = static_cast<const char*>(p);
    bytes.insert(bytes.end(), c, c + n);
  }
  void take(void* out, std::size_t n) {
    if (at_ + n > bytes.size()) throw std::runtime_error("mesh broadcast: truncated buffer");
    std::memcpy(out, bytes.data() + at_, n);
    at_ += n;
  }
  bool reading_;
  std::size_t at_ = 0;
};

void describe(Buffer& b, Mesh& m) {
  b.io(m.nodes);
  b.io(m.num_vertices);
  b.io(m.tets);
  b.io(m.boundaries);
  b.io(m.node_sets);
  b.io(m.file_tags);
  b.io(m.tet_region);
  b.io(m.region_names);
}

void describe(Buffer& b, SectionMesh& m) {
  b.io(m.nodes);
  b.io(m.num_vertices);
  b.io(m.triangles);
  b.io(m.boundaries);
  b.io(m.node_sets);
  b.io(m.file_tags);
  b.io(m.triangle_region);
  b.io(m.region_names);
}

template <class AnyMesh>
void broadcast_any(AnyMesh& mesh, MPI_Comm comm, int root) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Buffer b(rank != root);
  if (rank == root) describe(b, mesh);
  // Sizes beyond 2³¹ bytes go in chunks (MPI counts are int).
  std::uint64_t size = b.bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, root, comm);
  if (rank != root) b.bytes.resize(static_cast<std::size_t>(size));
  constexpr std::uint64_t kChunk = 1u << 30;
  for (std::uint64_t at = 0; at < size; at += kChunk)
    MPI_Bcast(b.bytes.data() + at, static_cast<int>(std::min(kChunk, size - at)), MPI_BYTE, root,
              comm);
  if (rank == root) return;
  AnyMesh m;
  describe(b, m);
  mesh = std::move(m);
}

}  // namespace

void broadcast_mesh(Mesh& mesh, MPI_Comm comm, int root) { broadcast_any(mesh, comm, root); }
void broadcast_mesh(SectionMesh& mesh, MPI_Comm comm, int root) { broadcast_any(mesh, comm, root); }

}  // namespace biphasic
