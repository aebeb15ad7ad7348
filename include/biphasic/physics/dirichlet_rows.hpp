// The Dirichlet rows of a semidiscrete problem: the unknowns held by displacement, symmetry and
// pressure conditions, each by one condition; their rows read s·(y_i − ḡ_i(t)) = 0.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/io/config.hpp"

namespace biphasic {

/// A Dirichlet row: unknown `dof` held at value · curve(t), or at a prescribed field's value
/// at `node` (a node for displacements, a vertex for pressures).
struct DirichletRow {
  Index dof;
  double value;
  const LoadCurve* curve;  ///< null = constant
  Index node;
  int field;  ///< a displacement component (≥ 0), kPressureField, or kHeldAtZero
};
inline constexpr int kHeldAtZero = -1;     ///< symmetry (or the axis): held at 0
inline constexpr int kPressureField = -2;  ///< a pressure condition

/// The Dirichlet rows of a problem, each unknown held by one condition (its owner): a second
/// condition on the same unknown must hold it alike (same value and curve).
class DirichletRows {
 public:
  explicit DirichletRows(Index size) : constrained_(static_cast<std::size_t>(size), 0) {}
  /// Holds row.dof for condition `owner`; throws std::runtime_error "<label(owner)> conflicts
  /// with <label(earlier owner)> on the same unknown (<where>)" if another condition holds it
  /// differently.
  void add(std::size_t owner, const DirichletRow& row,
           const std::function<std::string(std::size_t)>& label, const std::string& where) {
    const auto [it, inserted] = owner_.emplace(row.dof, owner);
    if (!inserted) {
      const DirichletRow& d = rows_[index_.at(row.dof)];
      if (d.value == row.value && d.curve == row.curve) return;
      throw std::runtime_error(label(owner) + " conflicts with " + label(it->second) +
                               " on the same unknown (" + where + ")");
    }
    index_[row.dof] = rows_.size();
    rows_.push_back(row);
    constrained_[static_cast<std::size_t>(row.dof)] = 1;
  }
  std::vector<DirichletRow>& rows() { return rows_; }
  std::vector<char>& constrained() { return constrained_; }

 private:
  std::vector<DirichletRow> rows_;
  std::vector<char> constrained_;
  std::map<Index, std::size_t> owner_;  ///< held unknown → its condition
  std::map<Index, std::size_t> index_;  ///< held unknown → its row
};

}  // namespace biphasic
