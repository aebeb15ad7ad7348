// Reading HDF5 files back in tests (the C API): datasets, their shapes and attributes.
#pragma once

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace biphasic::test {

/// Opens an HDF5 file read-only and closes it at scope exit.
struct H5Reader {
  explicit H5Reader(const std::filesystem::path& path) {
    file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) throw std::runtime_error("cannot open " + path.string());
  }
  ~H5Reader() { H5Fclose(file); }
  H5Reader(const H5Reader&) = delete;
  H5Reader& operator=(const H5Reader&) = delete;

  /// True if every component of the absolute path exists.
  bool exists(const std::string& path) const {
    std::string prefix;
    std::size_t pos = 1;
    while (pos <= path.size()) {
      const std::size_t next = std::min(path.find('/', pos), path.size());
      prefix = path.substr(0, next);
      if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
      pos = next + 1;
    }
    return true;
  }

  std::vector<hsize_t> dims(const std::string& path) const {
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error("no dataset " + path);
    const hid_t space = H5Dget_space(set);
    std::vector<hsize_t> d(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, d.data(), nullptr);
    H5Sclose(space);
    H5Dclose(set);
    return d;
  }

  template <typename T>
  std::vector<T> read(const std::string& path, hid_t mem_type) const {
    std::size_t count = 1;
    for (hsize_t d : dims(path)) count *= static_cast<std::size_t>(d);
    std::vector<T> data(count);
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    const herr_t status = H5Dread(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
    H5Dclose(set);
    if (status < 0) throw std::runtime_error("cannot read " + path);
    return data;
  }

  double time_attribute(const std::string& path) const {
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    const hid_t attr = H5Aopen(set, "time", H5P_DEFAULT);
    double t = std::nan("");
    const herr_t status = H5Aread(attr, H5T_NATIVE_DOUBLE, &t);
    H5Aclose(attr);
    H5Dclose(set);
    if (status < 0) throw std::runtime_error("cannot read time of " + path);
    return t;
  }

  /// The string attribute `name` of the dataset at `path`.
  std::string string_attribute(const std::string& path, const std::string& name) const {
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    const hid_t attr = H5Aopen(set, name.c_str(), H5P_DEFAULT);
    const hid_t type = H5Aget_type(attr);
    std::string value(H5Tget_size(type), '\0');
    const herr_t status = H5Aread(attr, type, value.data());
    H5Tclose(type);
    H5Aclose(attr);
    H5Dclose(set);
    if (status < 0) throw std::runtime_error("cannot read " + name + " of " + path);
    return value.substr(0, value.find('\0'));
  }

  hid_t file = -1;
};

}  // namespace biphasic::test
