#include "biphasic/assembly/colouring.hpp"

#include <bitset>
#include <stdexcept>

namespace biphasic {

std::vector<std::vector<Index>> colour_elements(const Mesh& mesh) {
  constexpr std::size_t kMaxColours = 512;
  std::vector<std::bitset<kMaxColours>> used(mesh.nodes.size());
  std::vector<std::vector<Index>> colours;
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    std::bitset<kMaxColours> taken;
    for (Index n : mesh.tets[e]) taken |= used[n];
    std::size_t c = 0;
    while (c < kMaxColours && taken[c]) ++c;
    if (c == kMaxColours) throw std::runtime_error("element colouring needs more than 512 colours");
    if (c == colours.size()) colours.emplace_back();
    colours[c].push_back(static_cast<Index>(e));
    for (Index n : mesh.tets[e]) used[n].set(c);
  }
  return colours;
}

}  // namespace biphasic
