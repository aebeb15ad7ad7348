// The unknowns of one part of a partitioned mesh against the unknowns of the whole
// (docs/parallel.md): where each local unknown sits in the rank-major numbering, which local
// rows the part adds to the whole system, and the matrix entries it contributes.
#pragma once

#include <vector>

#include "biphasic/assembly/sparsity.hpp"
#include "biphasic/mesh/partition.hpp"

namespace biphasic {

class SubdomainDofs {
 public:
  /// `pattern` and `constrained` are those of the part's problem on the part's mesh (a
  /// Subdomain's or a SectionSubdomain's).
  SubdomainDofs(const SubdomainMap& sub, const PartitionedNumbering& numbering,
                const SparsityPattern& pattern, const std::vector<char>& constrained);

  /// Number of local unknowns (the part's problem's size()).
  Index size() const { return static_cast<Index>(global_.size()); }
  /// The unknown of the whole system that local unknown i is.
  Index global(Index i) const { return global_[static_cast<std::size_t>(i)]; }
  const std::vector<Index>& global() const { return global_; }
  /// Local unknowns owned by this part, in the order of the whole system's numbering: entry k
  /// is unknown first_owned() + k of the whole system.
  const std::vector<Index>& owned() const { return owned_; }
  Index first_owned() const { return first_owned_; }
  /// Row i of the part's residual or Jacobian is added to the whole system: it is a row of a
  /// node an owned element touches, and, if constrained (a Dirichlet row, which every part that
  /// has it writes alike), this part owns it.
  bool contributes(Index i) const { return contributes_[static_cast<std::size_t>(i)] != 0; }

  /// Column j of the part's matrix belongs to a node an owned element touches: the other
  /// columns couple only through ghost elements and stay zero.
  bool touched(Index j) const { return touched_[static_cast<std::size_t>(j)] != 0; }
  /// Entry (i, j) of the part's matrix is added to the whole system's: row i contributes and
  /// column j is touched.
  bool contributes(Index i, Index j) const { return contributes(i) && touched(j); }

 private:
  std::vector<Index> global_, owned_;
  std::vector<char> contributes_, touched_;
  Index first_owned_ = 0;
};

}  // namespace biphasic
