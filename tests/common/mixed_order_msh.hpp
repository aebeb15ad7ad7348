// Binary .msh files (4.1 and 2.2) whose one volume holds a 4-node and a 10-node tetrahedron:
// gmsh keeps one element type per entity and corrupted its heap reading them, so the reader must
// refuse them first. Shared by the mesh reader's tests and the end-to-end ones.
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

// The content of mixed_orders_v22.msh (a 10-node then a 4-node tet) in binary 2.2.
inline void write_mixed_binary_v22(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "$MeshFormat\n2.2 1 8\n";
  put<int>(out, 1);
  out << "\n$EndMeshFormat\n$Nodes\n11\n";
  for (int tag = 1; tag <= 11; ++tag) {
    put<int>(out, tag);
    for (double x : kMixedNodes[static_cast<std::size_t>(tag - 1)]) put(out, x);
  }
  out << "\n$EndNodes\n$Elements\n2\n";
  for (int n : {11, 1, 2, 1, 2, 3, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}) put(out, n);  // type 11
  for (int n : {4, 1, 2, 2, 2, 3, 2, 3, 4, 11}) put(out, n);                     // type 4
  out << "\n$EndElements\n";
}

}  // namespace biphasic::mixed_order_msh
