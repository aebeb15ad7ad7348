// Binary .msh files (4.1 and 2.2) whose one volume holds a 4-node and a 10-node tetrahedron:
// gmsh keeps one element type per entity and corrupted its heap reading them, so the reader must
// refuse them first; and a writer of small binary 2.2 files for other defects. Shared by the
// mesh reader's tests and the end-to-end ones.
#pragma once

#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace biphasic::mixed_order_msh {

// The nodes of mixed_orders_v*.msh: a unit tet's corners, its six edge nodes (midpoints +
// (1,1,1)/16) and a stray corner (1,1,1) for the 4-node tet.
inline const std::vector<std::array<double, 3>> kMixedNodes{{0, 0, 0},
                                                            {1, 0, 0},
                                                            {0, 1, 0},
                                                            {0, 0, 1},
                                                            {0.5625, 0.0625, 0.0625},
                                                            {0.5625, 0.5625, 0.0625},
                                                            {0.0625, 0.5625, 0.0625},
                                                            {0.0625, 0.0625, 0.5625},
                                                            {0.0625, 0.5625, 0.5625},
                                                            {0.5625, 0.0625, 0.5625},
                                                            {1, 1, 1}};

/// Writes `value` as its raw bytes (little-endian on this machine, as gmsh writes them).
template <class T>
void put(std::ofstream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

// The content of mixed_orders_v41.msh (a 4-node and a 10-node tet in volume 1) in binary 4.1.
inline void write_mixed_binary_v41(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "$MeshFormat\n4.1 1 8\n";
  put<int>(out, 1);
  out << "\n$EndMeshFormat\n$Entities\n";
  for (std::uint64_t n : {0, 0, 0, 1}) put(out, n);
  put<int>(out, 1);
  for (double x : {0.0, 0.0, 0.0, 1.0, 1.0, 1.0}) put(out, x);
  put<std::uint64_t>(out, 0);  // physical tags
  put<std::uint64_t>(out, 0);  // bounding surfaces
  out << "\n$EndEntities\n$Nodes\n";
  for (std::uint64_t n : {1, 11, 1, 11}) put(out, n);
  put<int>(out, 3), put<int>(out, 1), put<int>(out, 0), put<std::uint64_t>(out, 11);
  for (std::uint64_t tag = 1; tag <= 11; ++tag) put(out, tag);
  for (const auto& p : kMixedNodes)
    for (double x : p) put(out, x);
  out << "\n$EndNodes\n$Elements\n";
  for (std::uint64_t n : {2, 2, 1, 2}) put(out, n);
  put<int>(out, 3), put<int>(out, 1), put<int>(out, 4), put<std::uint64_t>(out, 1);
  for (std::uint64_t n : {1, 1, 2, 3, 4}) put(out, n);  // tag, 4 corners (the 4th: node 11)
  out.seekp(-8, std::ios::cur);
  put<std::uint64_t>(out, 11);
  put<int>(out, 3), put<int>(out, 1), put<int>(out, 11), put<std::uint64_t>(out, 1);
  for (std::uint64_t n : {2, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}) put(out, n);
  out << "\n$EndElements\n";
}

/// A binary 2.2 file: `nodes` tagged 1, 2, ... and an $Elements section of `num_elements`
/// elements whose blocks are the raw ints `element_ints` (per block: type, count, number of
/// tags, then per element its tag, tags and nodes).
inline void write_binary_v22(const std::string& path,
                             const std::vector<std::array<double, 3>>& nodes, int num_elements,
                             const std::vector<int>& element_ints) {
  std::ofstream out(path, std::ios::binary);
  out << "$MeshFormat\n2.2 1 8\n";
  put<int>(out, 1);
  out << "\n$EndMeshFormat\n$Nodes\n" << nodes.size() << "\n";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    put<int>(out, static_cast<int>(i + 1));
    for (double x : nodes[i]) put(out, x);
  }
  out << "\n$EndNodes\n$Elements\n" << num_elements << "\n";
  for (int n : element_ints) put(out, n);
  out << "\n$EndElements\n";
}

// The content of mixed_orders_v22.msh (a 10-node then a 4-node tet) in binary 2.2.
inline void write_mixed_binary_v22(const std::string& path) {
  write_binary_v22(path, kMixedNodes, 2,
                   {11, 1, 2, 1, 2, 3, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,  // type 11
                    4,  1, 2, 2, 2, 3, 2, 3, 4, 11});                  // type 4
}

}  // namespace biphasic::mixed_order_msh
