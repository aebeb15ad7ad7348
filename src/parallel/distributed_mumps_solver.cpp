// The parallel MUMPS (Debian's libmumps, the build PETSc links) called through its C interface
// on distributed rows of the PETSc Jacobian. MUMPS' ICNTL/INFOG numbering is 1-based, as in its
// user guide.
#include "biphasic/parallel/distributed_mumps_solver.hpp"

#include <dmumps_c.h>
#include <nvector/nvector_parallel.h>
#include <smumps_c.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "../linsolve/direct_solver.hpp"
#include "../linsolve/mixed_precision.hpp"
#include "../linsolve/mumps_steps.hpp"
#include "biphasic/parallel/collective_failure.hpp"
#include "biphasic/parallel/petsc_check.hpp"
#include "biphasic/parallel/petsc_linear_solver.hpp"

namespace biphasic {

namespace {

using detail::DoublePrecision;
using detail::PrecisionBackoff;
using detail::RefinementTarget;
using detail::SinglePrecision;

/// This process's owned rows of the Jacobian in coordinate form (1-based global indices, as
/// MUMPS takes them), read from the PETSc matrix row by row. The values are kept in the
/// precision about to be factorised only (single-precision factors need no double copy: the
/// refinement residual reads PETSc's matrix).
struct OwnedRows {
  PetscInt first = 0, last = 0;  ///< the owned row range [first, last)
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> values;  ///< for double-precision factors (else empty)
  std::vector<float> single;   ///< for single-precision factors (else empty)

  /// Reads J's values, in single precision if `in_single` (else double); with `pattern`, its
  /// pattern too. Returns false if the pattern differs from the one read before (the caller
  /// then reads it again and analyses anew).
  bool read(Mat J, bool pattern, bool in_single) {
    petsc_check(MatGetOwnershipRange(J, &first, &last), "MatGetOwnershipRange");
    if (pattern) {
      irn.clear();
      jcn.clear();
    }
    values.clear();
    single.clear();
    // The other precision's array is released, not just emptied.
    if (in_single)
      std::vector<double>().swap(values);
    else
      std::vector<float>().swap(single);
    std::size_t k = 0;
    for (PetscInt row = first; row < last; ++row) {
      PetscInt count = 0;
      const PetscInt* cols = nullptr;
      const PetscScalar* vals = nullptr;
      petsc_check(MatGetRow(J, row, &count, &cols, &vals), "MatGetRow");
      bool same = true;
      for (PetscInt q = 0; q < count; ++q, ++k) {
        if (pattern) {
          irn.push_back(static_cast<MUMPS_INT>(row + 1));
          jcn.push_back(static_cast<MUMPS_INT>(cols[q] + 1));
        } else if (k >= jcn.size() || jcn[k] != static_cast<MUMPS_INT>(cols[q] + 1)) {
          same = false;
        }
        if (in_single)
          single.push_back(static_cast<float>(vals[q]));
        else
          values.push_back(vals[q]);
      }
      petsc_check(MatRestoreRow(J, row, &count, &cols, &vals), "MatRestoreRow");
      if (!same) return false;
    }
    return pattern || k == jcn.size();
  }
};

/// One MUMPS instance in precision P on a communicator: analysis on process 0 in the given
/// order (or PORD), numeric factorisations from the owned rows, solves with the right-hand side
/// on process 0.
template <class P>
class MumpsInstance {
 public:
  using Real = typename P::Real;

  /// `perm_in` (the solver's) must outlive the instance.
  MumpsInstance(MPI_Comm comm, const std::vector<MUMPS_INT>& perm_in,
                const std::string& out_of_core)
      : perm_in_(perm_in) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    host_ = rank == 0;
    id_.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
    id_.par = 1;  // process 0 takes part in the factorisation
    id_.sym = 0;  // unsymmetric
    id_.job = -1;
    P::call(&id_);
    if (infog(1) < 0)
      throw std::runtime_error("MUMPS failed to start (INFOG(1) = " + std::to_string(infog(1)) +
                               ")");
    icntl(1) = -1;  // no messages
    icntl(2) = -1;
    icntl(3) = -1;
    icntl(4) = 0;
    icntl(5) = 0;    // assembled matrix
    icntl(18) = 3;   // distributed by the caller: each process gives its owned rows
    icntl(28) = 1;   // sequential analysis on process 0
    icntl(20) = 0;   // dense right-hand side on process 0
    icntl(21) = 0;   // solution on process 0
    icntl(14) = 40;  // working-space relaxation [%]
    detail::mumps_factors_out_of_core(id_, out_of_core);
    if (!perm_in_.empty()) {
      icntl(7) = 1;  // the caller's order, on process 0
      if (host_) id_.perm_in = const_cast<MUMPS_INT*>(perm_in_.data());
    } else {
      icntl(7) = 4;  // PORD, the best order this build has of its own
    }
  }
  ~MumpsInstance() {
    id_.job = -2;
    P::call(&id_);
  }
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;

  /// Numeric factorisation of the owned rows `rows` (analysis first when `analyse`, or if not
  /// yet done). Collective; false (on every process) if MUMPS fails.
  bool factorise(const OwnedRows& rows, MUMPS_INT8 global_nnz, MUMPS_INT n, bool analyse,
                 LinearSolverStats& stats) {
    id_.n = n;
    id_.nnz_loc = static_cast<MUMPS_INT8>(rows.irn.size());
    id_.irn_loc = const_cast<MUMPS_INT*>(rows.irn.data());
    id_.jcn_loc = const_cast<MUMPS_INT*>(rows.jcn.data());
    // Read in place, in this instance's precision.
    if constexpr (std::is_same_v<Real, double>)
      id_.a_loc = const_cast<double*>(rows.values.data());
    else
      id_.a_loc = const_cast<float*>(rows.single.data());
    if (analyse || !analysed_) {
      if (!detail::mumps_analyse(id_, P::call, stats)) return false;
      analysed_ = true;
      if (icntl(22) == 1) require_room_for_factor_files();
    }
    return detail::mumps_factorise(id_, P::call, static_cast<double>(global_nnz), stats);
  }

  /// Out of core: each node's folder must hold the factor files of the processes it runs (the
  /// analysis' estimates summed over them); checked everywhere, thrown on every process if short
  /// on any node. Collective.
  void require_room_for_factor_files() {
    MPI_Comm comm = MPI_Comm_f2c(id_.comm_fortran);
    MPI_Comm node = MPI_COMM_NULL;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    double bytes = detail::factor_file_bytes(id_, sizeof(Real));
    MPI_Allreduce(MPI_IN_PLACE, &bytes, 1, MPI_DOUBLE, MPI_SUM, node);
    MPI_Comm_free(&node);
    run_collectively(comm, [&] { detail::require_free_space(id_.ooc_tmpdir, bytes); });
  }

  /// Solves in place: on process 0 `rhs` holds the n right-hand-side entries and receives the
  /// solution; elsewhere it is ignored. Collective; false if MUMPS fails.
  bool solve(std::vector<double>& rhs) {
    if (host_) {
      rhs_.assign(rhs.begin(), rhs.end());
      id_.rhs = rhs_.data();
      id_.nrhs = 1;
      id_.lrhs = id_.n;
    }
    id_.job = 3;
    P::call(&id_);
    detail::throw_if_factor_files_failed(id_);
    if (infog(1) < 0) return false;
    if (host_) std::copy(rhs_.begin(), rhs_.end(), rhs.begin());
    return true;
  }

 private:
  MUMPS_INT& icntl(int i) { return id_.icntl[i - 1]; }
  MUMPS_INT infog(int i) const { return id_.infog[i - 1]; }

  typename P::Struc id_{};
  bool host_ = false, analysed_ = false;
  const std::vector<MUMPS_INT>& perm_in_;
  std::vector<Real> rhs_;
};

/// The solver: owned rows in, right-hand side gathered on process 0, solution scattered (or,
/// while refining, broadcast so that every process can form its rows' residual).
class DistributedMumpsSolver final : public detail::DirectSolver {
 public:
  DistributedMumpsSolver(MPI_Comm comm, FactorPrecision precision, std::vector<Index> order,
                         std::string out_of_core, LinearSolverStats* stats)
      : DirectSolver(stats),
        comm_(comm),
        mixed_(precision == FactorPrecision::Mixed),
        out_of_core_(std::move(out_of_core)) {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &size_);
    if (rank_ == 0 && !order.empty()) {
      perm_in_.assign(order.size(), 0);
      for (std::size_t k = 0; k < order.size(); ++k)
        perm_in_.at(static_cast<std::size_t>(order[k])) = static_cast<MUMPS_INT>(k + 1);
      if (std::count(perm_in_.begin(), perm_in_.end(), 0) != 0)
        throw std::invalid_argument("distributed MUMPS: the order is not a permutation");
    }
  }

  int setup(SUNMatrix A) override {
    Mat J = petsc_matrix(A);
    matrix_ = J;
    const bool first = !layout_known_;
    const bool in_single = mixed_ && backoff_.single_due();
    bool same = rows_.read(J, first, in_single);
    int all_same = same ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &all_same, 1, MPI_INT, MPI_MIN, comm_);
    if (!all_same) rows_.read(J, true, in_single);
    const bool analyse = first || !all_same;
    if (analyse) learn_layout(J);
    if (in_single) {
      if (!single_) {
        double_.reset();  // one set of factors at a time
        single_ = std::make_unique<MumpsInstance<SinglePrecision>>(comm_, perm_in_, out_of_core_);
      }
      if (single_->factorise(rows_, global_nnz_, n_, analyse, stats())) return SUNLS_SUCCESS;
      backoff_.fall_back(stats());
      rows_.read(J, false, false);  // the same matrix, now in double precision
    }
    return factorise_double(analyse) ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
  }

  int solve(SUNMatrix, N_Vector x, N_Vector b) override {
    const auto local = static_cast<std::size_t>(NV_LOCLENGTH_P(b));
    b_.assign(NV_DATA_P(b), NV_DATA_P(b) + local);  // x and b may alias
    gather(b_, full_);
    if (!single_) {
      if (!double_->solve(full_)) return SUNLS_PACKAGE_FAIL_UNREC;
      scatter(full_, NV_DATA_P(x));
      return SUNLS_SUCCESS;
    }
    if (!single_->solve(full_)) return SUNLS_PACKAGE_FAIL_UNREC;
    x_ = std::move(full_);
    x_.resize(static_cast<std::size_t>(n_));
    MPI_Bcast(x_.data(), n_, MPI_DOUBLE, 0, comm_);
    auto correct = [&] {
      gather(r_, full_);
      if (!single_->solve(full_)) return false;
      full_.resize(static_cast<std::size_t>(n_));
      MPI_Bcast(full_.data(), n_, MPI_DOUBLE, 0, comm_);
      for (std::size_t i = 0; i < x_.size(); ++i) x_[i] += full_[i];
      return true;
    };
    switch (RefinementTarget::refine(
        correct, [&] { return excess(); }, stats())) {
      case RefinementTarget::Outcome::Accurate:
        std::copy_n(x_.begin() + offset_[static_cast<std::size_t>(rank_)], local, NV_DATA_P(x));
        return SUNLS_SUCCESS;
      case RefinementTarget::Outcome::SolverFailed:
        return SUNLS_PACKAGE_FAIL_UNREC;
      case RefinementTarget::Outcome::NotAccurate:
        break;
    }
    backoff_.fall_back(stats());
    rows_.read(matrix_, false, false);  // the same matrix, now in double precision
    if (!factorise_double(false)) return SUNLS_PACKAGE_FAIL_UNREC;
    gather(b_, full_);
    if (!double_->solve(full_)) return SUNLS_PACKAGE_FAIL_UNREC;
    scatter(full_, NV_DATA_P(x));
    return SUNLS_SUCCESS;
  }

 private:
  /// Sizes and offsets of every process's owned range, the global size and entry count.
  void learn_layout(Mat J) {
    PetscInt rows = 0, cols = 0;
    petsc_check(MatGetSize(J, &rows, &cols), "MatGetSize");
    n_ = static_cast<MUMPS_INT>(rows);
    const int owned = static_cast<int>(rows_.last - rows_.first);
    count_.assign(static_cast<std::size_t>(size_), 0);
    MPI_Allgather(&owned, 1, MPI_INT, count_.data(), 1, MPI_INT, comm_);
    offset_.assign(static_cast<std::size_t>(size_), 0);
    for (int r = 1; r < size_; ++r)
      offset_[static_cast<std::size_t>(r)] =
          offset_[static_cast<std::size_t>(r - 1)] + count_[static_cast<std::size_t>(r - 1)];
    long long nnz = static_cast<long long>(rows_.irn.size());
    MPI_Allreduce(MPI_IN_PLACE, &nnz, 1, MPI_LONG_LONG, MPI_SUM, comm_);
    global_nnz_ = static_cast<MUMPS_INT8>(nnz);
    layout_known_ = true;
  }

  /// The owned parts `part` of every process, concatenated on process 0 (`whole`).
  void gather(const std::vector<double>& part, std::vector<double>& whole) {
    whole.resize(rank_ == 0 ? static_cast<std::size_t>(n_) : 0);
    MPI_Gatherv(part.data(), static_cast<int>(part.size()), MPI_DOUBLE, whole.data(), count_.data(),
                offset_.data(), MPI_DOUBLE, 0, comm_);
  }
  /// Process 0's `whole` split back into the owned parts.
  void scatter(const std::vector<double>& whole, double* part) {
    MPI_Scatterv(whole.data(), count_.data(), offset_.data(), MPI_DOUBLE, part,
                 count_[static_cast<std::size_t>(rank_)], MPI_DOUBLE, 0, comm_);
  }

  /// r = b − A x on the owned rows (x_ whole on every process; A in double precision, read
  /// from the PETSc matrix of the last set-up), and how far x_ is from the refinement target
  /// (the same value on every process).
  double excess() {
    const auto local = b_.size();
    r_.assign(b_.begin(), b_.end());
    scale_.resize(local);
    for (std::size_t i = 0; i < local; ++i) scale_[i] = std::abs(b_[i]);
    for (PetscInt row = rows_.first; row < rows_.last; ++row) {
      PetscInt count = 0;
      const PetscInt* cols = nullptr;
      const PetscScalar* vals = nullptr;
      petsc_check(MatGetRow(matrix_, row, &count, &cols, &vals), "MatGetRow");
      const auto i = static_cast<std::size_t>(row - rows_.first);
      for (PetscInt q = 0; q < count; ++q) {
        const double t = vals[q] * x_[static_cast<std::size_t>(cols[q])];
        r_[i] -= t;
        scale_[i] += std::abs(t);
      }
      petsc_check(MatRestoreRow(matrix_, row, &count, &cols, &vals), "MatRestoreRow");
    }
    double m[3] = {0.0, 0.0, 0.0};  // backward error, max |r_i|, max |b_i|
    for (std::size_t i = 0; i < local; ++i) {
      if (scale_[i] > 0.0) m[0] = std::max(m[0], std::abs(r_[i]) / scale_[i]);
      m[1] = std::max(m[1], std::abs(r_[i]));
      m[2] = std::max(m[2], std::abs(b_[i]));
    }
    MPI_Allreduce(MPI_IN_PLACE, m, 3, MPI_DOUBLE, MPI_MAX, comm_);
    return RefinementTarget::excess(m[0], m[1], m[2]);
  }

  bool factorise_double(bool analyse) {
    if (!double_) {
      single_.reset();
      double_ = std::make_unique<MumpsInstance<DoublePrecision>>(comm_, perm_in_, out_of_core_);
      analyse = true;
    }
    backoff_.double_factorised();
    return double_->factorise(rows_, global_nnz_, n_, analyse, stats());
  }

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  bool mixed_;
  std::string out_of_core_;  ///< directory of out-of-core factors; empty: in memory
  bool layout_known_ = false;
  std::vector<MUMPS_INT> perm_in_;  ///< process 0: position (1-based) of each unknown
  OwnedRows rows_;
  Mat matrix_ = nullptr;  ///< the matrix of the last set-up (its values stay until the next)
  MUMPS_INT n_ = 0;
  MUMPS_INT8 global_nnz_ = 0;
  std::vector<int> count_, offset_;  ///< per process: owned unknowns, first owned unknown
  PrecisionBackoff backoff_;
  std::unique_ptr<MumpsInstance<SinglePrecision>> single_;
  std::unique_ptr<MumpsInstance<DoublePrecision>> double_;
  std::vector<double> b_, full_, x_, r_, scale_;
};

}  // namespace

LinearSolverPtr make_distributed_mumps_solver(MPI_Comm comm, FactorPrecision precision,
                                              std::vector<Index> order, SUNContext ctx,
                                              LinearSolverStats* stats,
                                              std::string out_of_core_directory) {
  return detail::wrap_direct_solver(
      std::make_unique<DistributedMumpsSolver>(comm, precision, std::move(order),
                                               std::move(out_of_core_directory), stats),
      ctx);
}

}  // namespace biphasic
