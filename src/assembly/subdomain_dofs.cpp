#include "biphasic/assembly/subdomain_dofs.hpp"

#include <stdexcept>
#include <string>

namespace biphasic {

SubdomainDofs::SubdomainDofs(const SubdomainMap& sub, const PartitionedNumbering& numbering,
                             const SparsityPattern& pattern, const std::vector<char>& constrained) {
  const Index n = pattern.size();
  const Index d = numbering.components;
  if (pattern.components() != d ||
      pattern.num_nodes() != static_cast<Index>(sub.global_node.size()) ||
      static_cast<Index>(constrained.size()) != n)
    throw std::invalid_argument("subdomain unknowns: the pattern is not that of the part's mesh");
  const Index num_u = pattern.num_u();
  global_.resize(static_cast<std::size_t>(n));
  contributes_.assign(static_cast<std::size_t>(n), 0);
  touched_.assign(static_cast<std::size_t>(n), 0);
  // Local unknown → node: u rows d·m + c, p rows by vertex.
  auto node_of = [&](Index i) { return i < num_u ? i / d : i - num_u; };
  for (Index i = 0; i < n; ++i) {
    const auto m = static_cast<std::size_t>(node_of(i));
    const auto g = static_cast<std::size_t>(sub.global_node[m]);
    global_[static_cast<std::size_t>(i)] =
        i < num_u ? numbering.u_base[g] + i % d : numbering.p_index[g];
    touched_[static_cast<std::size_t>(i)] = sub.node_touched[m];
    const bool owned = sub.node_owned[m] != 0;
    contributes_[static_cast<std::size_t>(i)] =
        sub.node_touched[m] && (owned || !constrained[static_cast<std::size_t>(i)]) ? 1 : 0;
  }
  // Owned unknowns in the whole system's order: u of owned nodes, then p of owned vertices.
  for (int pass = 0; pass < 2; ++pass)
    for (Index i = pass == 0 ? 0 : num_u; i < (pass == 0 ? num_u : n); ++i)
      if (sub.node_owned[static_cast<std::size_t>(node_of(i))]) owned_.push_back(i);
  first_owned_ = numbering.offset[static_cast<std::size_t>(sub.part)];
  for (std::size_t k = 0; k < owned_.size(); ++k)
    if (global_[static_cast<std::size_t>(owned_[k])] != first_owned_ + static_cast<Index>(k))
      throw std::logic_error("subdomain unknowns: owned unknown " + std::to_string(k) +
                             " of part " + std::to_string(sub.part) + " out of order");
}

}  // namespace biphasic
