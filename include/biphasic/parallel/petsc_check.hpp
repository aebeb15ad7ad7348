// PETSc error codes as exceptions: the project's code reports failures by throwing, and a
// PETSc call that fails says which call and the code.
#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace biphasic {

/// Throws std::runtime_error "PETSc: <what> failed (error <code>)" unless `code` is 0.
inline void petsc_check(PetscErrorCode code, const char* what) {
  if (code != 0)
    throw std::runtime_error(std::string("PETSc: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(code)) + ")");
}

}  // namespace biphasic
