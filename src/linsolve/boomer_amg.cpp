#include "boomer_amg.hpp"

#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>

namespace biphasic::detail {

namespace {

/// hypre is an MPI library: one process on MPI_COMM_WORLD (an MPI singleton, no launcher
/// needed). Initialised on first use, finalised at exit.
void ensure_mpi_and_hypre() {
  static const bool ready = [] {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) {
      // Open MPI binds a singleton to one core, which would serialise the OpenMP threads of
      // the assembly and of hypre itself; keep the process free unless the user says otherwise.
      setenv("OMPI_MCA_hwloc_base_binding_policy", "none", 0);
      if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS)
        throw std::runtime_error("MPI_Init failed (needed by hypre's BoomerAMG)");
      std::atexit([] {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Finalize();
      });
    }
    HYPRE_Init();
    return true;
  }();
  (void)ready;
}

void check(HYPRE_Int code, const char* what) {
  if (code != 0) {
    HYPRE_ClearAllErrors();
    throw std::runtime_error(std::string("hypre: ") + what + " failed (code " +
                             std::to_string(code) + ")");
  }
}

}  // namespace

struct BoomerAmg::Hypre {
  HYPRE_IJMatrix A = nullptr;
  HYPRE_IJVector b = nullptr, x = nullptr;
  HYPRE_Solver amg = nullptr, gmres = nullptr;
  HYPRE_ParCSRMatrix parA = nullptr;
  HYPRE_ParVector parb = nullptr, parx = nullptr;
  int n = 0;

  void clear() {
    if (gmres) HYPRE_ParCSRGMRESDestroy(gmres);
    gmres = nullptr;
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (A) HYPRE_IJMatrixDestroy(A);
    if (b) HYPRE_IJVectorDestroy(b);
    if (x) HYPRE_IJVectorDestroy(x);
    amg = nullptr;
    A = nullptr;
    b = x = nullptr;
  }
  ~Hypre() { clear(); }
};

BoomerAmg::BoomerAmg(const AmgSettings& settings)
    : h_(std::make_unique<Hypre>()), settings_(settings) {
  ensure_mpi_and_hypre();
}

BoomerAmg::~BoomerAmg() = default;

void BoomerAmg::setup(const CsrMatrix& M) {
  Hypre& h = *h_;
  h.clear();
  const int n = M.rows();
  h.n = n;
  check(HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &h.A), "IJMatrixCreate");
  check(HYPRE_IJMatrixSetObjectType(h.A, HYPRE_PARCSR), "IJMatrixSetObjectType");
  std::vector<int> ncols(n), rows(n);
  for (int i = 0; i < n; ++i) ncols[i] = M.row_ptr[i + 1] - M.row_ptr[i];
  std::iota(rows.begin(), rows.end(), 0);
  check(HYPRE_IJMatrixSetRowSizes(h.A, ncols.data()), "IJMatrixSetRowSizes");
  check(HYPRE_IJMatrixInitialize(h.A), "IJMatrixInitialize");
  check(HYPRE_IJMatrixSetValues(h.A, n, ncols.data(), rows.data(), M.col.data(), M.value.data()),
        "IJMatrixSetValues");
  check(HYPRE_IJMatrixAssemble(h.A), "IJMatrixAssemble");
  check(HYPRE_IJMatrixGetObject(h.A, reinterpret_cast<void**>(&h.parA)), "IJMatrixGetObject");

  for (HYPRE_IJVector* v : {&h.b, &h.x}) {
    check(HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, v), "IJVectorCreate");
    check(HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR), "IJVectorSetObjectType");
    check(HYPRE_IJVectorInitialize(*v), "IJVectorInitialize");
    check(HYPRE_IJVectorAssemble(*v), "IJVectorAssemble");
  }
  check(HYPRE_IJVectorGetObject(h.b, reinterpret_cast<void**>(&h.parb)), "IJVectorGetObject");
  check(HYPRE_IJVectorGetObject(h.x, reinterpret_cast<void**>(&h.parx)), "IJVectorGetObject");

  check(HYPRE_BoomerAMGCreate(&h.amg), "BoomerAMGCreate");
  HYPRE_BoomerAMGSetPrintLevel(h.amg, 0);
  HYPRE_BoomerAMGSetCoarsenType(h.amg, 10);  // HMIS: cheap coarse grids in 3D
  HYPRE_BoomerAMGSetInterpType(h.amg, 6);    // extended+i interpolation
  HYPRE_BoomerAMGSetPMaxElmts(h.amg, 4);     // interpolation truncation
  HYPRE_BoomerAMGSetAggNumLevels(h.amg, 0);
  HYPRE_BoomerAMGSetStrongThreshold(h.amg, settings_.strong_threshold);
  HYPRE_BoomerAMGSetRelaxType(h.amg, 8);  // ℓ1-scaled symmetric hybrid Gauss–Seidel
  HYPRE_BoomerAMGSetNumSweeps(h.amg, 1);
  HYPRE_BoomerAMGSetNumFunctions(h.amg, settings_.num_functions);  // unknown-based systems AMG
  HYPRE_BoomerAMGSetMaxIter(h.amg, settings_.cycles);
  HYPRE_BoomerAMGSetTol(h.amg, 0.0);
  if (settings_.inner_rtol > 0.0) {
    check(HYPRE_ParCSRGMRESCreate(MPI_COMM_WORLD, &h.gmres), "ParCSRGMRESCreate");
    HYPRE_ParCSRGMRESSetKDim(h.gmres, 50);
    HYPRE_ParCSRGMRESSetTol(h.gmres, settings_.inner_rtol);
    HYPRE_ParCSRGMRESSetMaxIter(h.gmres, settings_.inner_max_iterations);
    HYPRE_ParCSRGMRESSetPrecond(h.gmres, HYPRE_BoomerAMGSolve, HYPRE_BoomerAMGSetup, h.amg);
    check(HYPRE_ParCSRGMRESSetup(h.gmres, h.parA, h.parb, h.parx), "ParCSRGMRESSetup");
  } else {
    check(HYPRE_BoomerAMGSetup(h.amg, h.parA, h.parb, h.parx), "BoomerAMGSetup");
  }
}

int BoomerAmg::apply(const double* r, double* z) {
  Hypre& h = *h_;
  check(HYPRE_IJVectorSetValues(h.b, h.n, nullptr, r), "IJVectorSetValues");
  check(HYPRE_ParVectorSetConstantValues(h.parx, 0.0), "ParVectorSetConstantValues");
  // hypre reports a solve that stops short of its tolerance (or a fixed cycle count) as an
  // error; for a preconditioner that is expected.
  int cycles = settings_.cycles;
  if (h.gmres) {
    HYPRE_ParCSRGMRESSolve(h.gmres, h.parA, h.parb, h.parx);
    HYPRE_Int iterations = 0;
    HYPRE_ParCSRGMRESGetNumIterations(h.gmres, &iterations);
    cycles *= iterations;
  } else {
    HYPRE_BoomerAMGSolve(h.amg, h.parA, h.parb, h.parx);
  }
  HYPRE_ClearAllErrors();
  check(HYPRE_IJVectorGetValues(h.x, h.n, nullptr, z), "IJVectorGetValues");
  return cycles;
}

}  // namespace biphasic::detail
