// Rigid platens under a prescribed total force (docs/rigid_platen.md).
//
// A platen is a named boundary whose nodes move together along one axis e_c; the force it exerts
// on the body along e_c is prescribed, P(t) = value · curve(t) [N]. No unknown is added: one of
// the platen's displacement unknowns, u_m (an edge node's), carries the platen's displacement w,
// and the rows of the system are
//
//   tie rows      s · (u_i − u_m) = 0                       every other platen unknown i
//   force row     Σ_{i ∈ platen} F_i(t, y, ẏ) − P(t) = 0    row m
//
// where F_i is the momentum residual of row i (internal force minus applied loads, the GLS term
// included) and s the Dirichlet row scale [N/mm]. The force row is the platen's equilibrium:
// the reaction of the platen (what output.reactions reports) equals P(t). The tie rows are
// algebraic like Dirichlet rows (their unknowns are flagged constrained()), and the force row is
// a sum of momentum rows, algebraic as they are: the DAE keeps its index and the consistent start
// treats the force row as one more momentum row. The pattern gains the couplings of the master
// node with every node next to the platen (NodeCoupling), ordered last.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "biphasic/assembly/sparsity.hpp"
#include "biphasic/io/config.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// One rigid platen: its condition, unknowns and force.
struct RigidPlaten {
  std::size_t condition = 0;         ///< index of its [[boundary]] entry
  std::string boundary;              ///< boundary name
  int component = 0;                 ///< axis it moves along (0, 1, 2 = x, y, z; r, z in 2-D)
  double value = 0.0;                ///< force scale [N]
  const LoadCurve* curve = nullptr;  ///< null = constant 1
  Index master_node = 0;             ///< the node whose unknown carries w
  Index master = 0;                  ///< that unknown (force row)
  std::vector<Index> dofs;           ///< every platen unknown along e_c, master included, sorted
  std::vector<Index> neighbourhood;  ///< nodes sharing an element with a platen node, sorted
  double area = 0.0;  ///< reference area of the platen [mm²] (2-D: full circle or per mm)
};

class RigidPlatens {
 public:
  RigidPlatens() = default;
  /// The rigid_platen conditions of `config` on a tetrahedral mesh (3 components per node), or
  /// on a section mesh (2 components; `axisymmetric` weighs areas by 2πR). `curves` must
  /// outlive this object. Throws std::runtime_error naming the condition for an unknown
  /// boundary or curve, a node set, a boundary without edge nodes, or two platens sharing a node.
  RigidPlatens(const Mesh& mesh, const Config& config,
               const std::map<std::string, LoadCurve>& curves);
  RigidPlatens(const SectionMesh& mesh, bool axisymmetric, const Config& config,
               const std::map<std::string, LoadCurve>& curves);

  bool empty() const { return platens_.empty(); }
  const std::vector<RigidPlaten>& platens() const { return platens_; }
  /// The pattern couplings the platens need (master node ↔ neighbourhood).
  std::vector<NodeCoupling> couplings() const;

  /// Throws std::runtime_error naming the platen's condition and the node if `held` (one flag
  /// per unknown, `components` displacement unknowns per node) flags a platen unknown.
  void check_free(const std::vector<char>& held, int components,
                  const std::vector<BoundaryCondition>& bcs) const;
  /// Ties the platens into a problem once its Dirichlet rows are known (`held` flags their
  /// unknowns): checks that no platen unknown is held (else std::runtime_error naming the
  /// platen's condition and the node), binds the positions in `pattern` (built with couplings();
  /// s = tie-row scale [N/mm]), adds each platen's unknowns to held_rows[its boundary] (its
  /// reaction rows), and returns the constrained() flags: held or tied (every platen unknown but
  /// the master).
  std::vector<char> tie(const std::vector<char>& held, const SparsityPattern& pattern,
                        double row_scale, const std::vector<BoundaryCondition>& bcs,
                        std::map<std::string, std::vector<Index>>& held_rows);
  /// The (displacement [mm], pressure [MPa]) scales the platen forces imply: the largest
  /// |P(t)| over [0, t_end] per platen area as a stress, and that stress over the oedometric
  /// modulus HA [MPa] times the body's extent along the platen's component [mm]. Raises `scales`.
  void raise_solution_scales(const Config& config, double HA, const double* extent,
                             std::pair<double, double>& scales) const;
  /// P(t) of platen k [N].
  double force(std::size_t k, double t) const;
  /// The platen rows of F from the assembled momentum residual (F holds F_i on every row).
  void residual(double t, const double* y, double* F) const;
  /// ∂F/∂t on the platen rows from the assembled ∂F_i/∂t (applied loads only).
  void time_derivative(double t, double* dFdt) const;
  /// The platen rows of dF/dy + c_j dF/dẏ (and of dF/dẏ, if given) from the assembled
  /// element rows: the tie rows' entries are summed into the force row, then replaced by s and −s.
  void jacobian(double* values, double* rate_values) const;
  /// Sets the tied unknowns of y (and ẏ, if given) to their platen's master value.
  void apply(double* y, double* ydot) const;

 private:
  /// Positions in `pattern`; s = tie-row scale [N/mm].
  void bind(const SparsityPattern& pattern, double row_scale);
  struct Positions {
    std::vector<std::pair<Index, Index>> into_master;  ///< (entry of a tie row, force-row entry)
    std::vector<Index> tie_diagonal, tie_master;       ///< (i, i) and (i, m) per tie row
  };
  std::vector<RigidPlaten> platens_;
  std::vector<Positions> positions_;
  double row_scale_ = 1.0;
};

}  // namespace biphasic
