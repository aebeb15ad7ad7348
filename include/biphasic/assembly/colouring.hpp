// Element colouring for race-free parallel assembly: elements of one colour share no node,
// so their contributions can be added concurrently into shared vectors and matrices.
#pragma once

#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// Elements grouped by colour (greedy, first colour free on all of the element's nodes).
std::vector<std::vector<Index>> colour_elements(const Mesh& mesh);

}  // namespace biphasic
