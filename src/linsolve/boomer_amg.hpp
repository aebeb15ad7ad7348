// hypre's BoomerAMG as a preconditioner for one sparse block (serial, on MPI_COMM_WORLD of a
// single process). Internal to the iterative linear solver.
#pragma once

#include <memory>
#include <vector>

namespace biphasic::detail {

/// Settings of the algebraic multigrid hierarchy.
struct AmgSettings {
  int num_functions = 1;          ///< unknowns per node, interleaved (3 for displacements)
  double strong_threshold = 0.5;  ///< strength-of-connection threshold [-]
  int cycles = 1;                 ///< V-cycles per application (per inner iteration)
  /// > 0: each application is a GMRES solve preconditioned by the V-cycles, to this relative
  /// residual (for blocks where a fixed number of cycles is too weak); 0: the cycles alone.
  double inner_rtol = 0.0;
  int inner_max_iterations = 200;
};

/// A square CSR matrix (0-based, rows sorted or not) handed to BoomerAMG.
struct CsrMatrix {
  std::vector<int> row_ptr, col;
  std::vector<double> value;
  int rows() const { return static_cast<int>(row_ptr.size()) - 1; }
};

class BoomerAmg {
 public:
  explicit BoomerAmg(const AmgSettings& settings);
  ~BoomerAmg();
  BoomerAmg(const BoomerAmg&) = delete;
  BoomerAmg& operator=(const BoomerAmg&) = delete;

  /// Builds the hierarchy of A (the matrix is copied into hypre's format).
  void setup(const CsrMatrix& A);
  /// z ≈ A⁻¹ r from z = 0 (V-cycles, or inner GMRES with them); returns the V-cycles used.
  int apply(const double* r, double* z);

 private:
  struct Hypre;
  std::unique_ptr<Hypre> h_;
  AmgSettings settings_;
};

}  // namespace biphasic::detail
