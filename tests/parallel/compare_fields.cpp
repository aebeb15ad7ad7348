// compare_fields A.h5 B.h5 TOL: every field of A's fields.h5 (each group below /fields, each
// output) against B's, the largest difference relative to the largest absolute value of A's
// dataset; the mesh (coordinates, topology, vertex count) must be equal, the output times equal
// to rounding (1e-9 of the last).
// Prints one line per field; exits 1 if B lacks a field or output, a shape differs, the mesh or
// the times differ, or a difference exceeds TOL (the MPI tests' comparison of a run on several
// processes, which write the file together, with one).
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../common/h5_reader.hpp"

namespace {

/// The names of the links in group `path`.
std::vector<std::string> members(hid_t file, const std::string& path) {
  std::vector<std::string> names;
  const hid_t group = H5Gopen2(file, path.c_str(), H5P_DEFAULT);
  if (group < 0) return names;
  H5G_info_t info{};
  H5Gget_info(group, &info);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t size =
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    std::string name(static_cast<std::size_t>(size), '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(),
                       static_cast<std::size_t>(size) + 1, H5P_DEFAULT);
    names.push_back(name);
  }
  H5Gclose(group);
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: compare_fields A.h5 B.h5 TOL\n");
    return 2;
  }
  const double tol = std::atof(argv[3]);
  biphasic::test::H5Reader a(argv[1]), b(argv[2]);
  int failures = 0;
  std::size_t compared = 0;
  // What both runs write alike, whoever writes which rows: equal to the last bit.
  const auto same = [&](const std::string& path, auto value_type, hid_t type) {
    using T = decltype(value_type);
    if (!a.exists(path) || !b.exists(path) || a.dims(path) != b.dims(path) ||
        a.read<T>(path, type) != b.read<T>(path, type)) {
      std::printf("FAIL: %s differs between %s and %s\n", path.c_str(), argv[1], argv[2]);
      ++failures;
    } else {
      std::printf("%s: equal\n", path.c_str());
    }
  };
  same("/mesh/coordinates", 0.0, H5T_NATIVE_DOUBLE);
  same("/mesh/topology", std::int64_t{0}, H5T_NATIVE_INT64);
  same("/mesh/vertex_count", std::int64_t{0}, H5T_NATIVE_INT64);
  // The output times to rounding: a run continued from a checkpoint counts its steps from there.
  if (a.dims("/fields/times") != b.dims("/fields/times")) {
    std::printf("FAIL: /fields/times: another number of outputs in %s\n", argv[2]);
    ++failures;
  } else {
    const auto ta = a.read<double>("/fields/times", H5T_NATIVE_DOUBLE);
    const auto tb = b.read<double>("/fields/times", H5T_NATIVE_DOUBLE);
    double scale = 0.0, diff = 0.0;
    for (std::size_t i = 0; i < ta.size(); ++i) {
      scale = std::max(scale, std::abs(ta[i]));
      diff = std::max(diff, std::abs(ta[i] - tb[i]));
    }
    std::printf("/fields/times: %zu outputs, largest difference %.2e s\n", ta.size(), diff);
    if (!(diff <= 1e-9 * scale)) {
      std::printf("FAIL: /fields/times differ by %.2e s\n", diff);
      ++failures;
    }
  }
  for (const std::string& field : members(a.file, "/fields")) {
    if (field == "times") continue;
    double worst = 0.0;
    for (const std::string& output : members(a.file, "/fields/" + field)) {
      const std::string path = "/fields/" + field + "/" + output;
      if (!b.exists(path) || a.dims(path) != b.dims(path)) {
        std::printf("FAIL: %s missing or of another shape in %s\n", path.c_str(), argv[2]);
        ++failures;
        continue;
      }
      const auto x = a.read<double>(path, H5T_NATIVE_DOUBLE);
      const auto y = b.read<double>(path, H5T_NATIVE_DOUBLE);
      double scale = 0.0, diff = 0.0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        scale = std::max(scale, std::abs(x[i]));
        diff = std::max(diff, std::abs(x[i] - y[i]));
      }
      worst = std::max(worst, scale > 0.0 ? diff / scale : diff);
      ++compared;
    }
    std::printf("%s: largest difference %.2e of the largest value\n", field.c_str(), worst);
    if (!(worst <= tol)) {
      std::printf("FAIL: %s differs by %.2e (tolerance %.1e)\n", field.c_str(), worst, tol);
      ++failures;
    }
  }
  if (compared == 0) {
    std::printf("FAIL: no field in %s\n", argv[1]);
    ++failures;
  }
  return failures ? 1 : 0;
}
