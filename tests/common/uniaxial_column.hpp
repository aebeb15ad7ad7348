// A column in homogeneous uniaxial strain for end-to-end tests: the case-file text of a
// one-cell-wide column (mesh source "column", two layers) whose top is pulled up to the
// stretch λ_z by t = 1 s with rollers on the sides, under a uniform pore pressure.
#pragma once

#include <sstream>
#include <string>

namespace biphasic::test {

struct UniaxialColumn {
  double mu = 0.5, lambda = 0.3;                  ///< Neo-Hookean moduli [MPa]
  double pressure = 0.05;                         ///< pore pressure on every face [MPa]
  double stretch = 1.2;                           ///< λ_z at t = 1 s
  double width = 1.0, depth = 1.5, height = 2.0;  ///< [mm]
};

/// Every section of the case but [time], [linear_solver] and [output]. Every vertex of the
/// column lies on its boundary, so p = p0 on all faces fixes a uniform pressure; rollers on the
/// sides and the top pulled up give F = diag(1, 1, λ_z).
inline std::string uniaxial_column_case(const UniaxialColumn& c) {
  std::ostringstream s;
  s << "format_version = 1\n"
    << "[mesh]\nsource = \"column\"\n"
    << "[mesh.column]\nwidth = " << c.width << "\ndepth = " << c.depth << "\nheight = " << c.height
    << "\nnz = 2\n"
    << "[material]\nmu = " << c.mu << "\nlambda = " << c.lambda << "\npermeability = 1e-3\n"
    << "[curves]\nramp = [[0.0, 0.0], [1.0, 1.0]]\n"
    << "[[boundary]]\nname = \"top\"\ntype = \"displacement\"\ncomponent = \"z\"\nvalue = "
    << (c.stretch - 1.0) * c.height << "\ncurve = \"ramp\"\n"
    << "[[boundary]]\nname = \"bottom\"\ntype = \"displacement\"\ncomponent = \"z\"\nvalue = 0\n";
  for (const char* face : {"x0", "x1", "y0", "y1"})
    s << "[[boundary]]\nname = \"" << face << "\"\ntype = \"symmetry\"\n";
  for (const char* face : {"top", "bottom", "x0", "x1", "y0", "y1"})
    s << "[[boundary]]\nname = \"" << face << "\"\ntype = \"pressure\"\nvalue = " << c.pressure
      << "\n";
  return s.str();
}

}  // namespace biphasic::test
