#include "gmsh_backend.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>

#ifndef BIPHASIC_GMSH_MODULE_PATH
#error "BIPHASIC_GMSH_MODULE_PATH must name the built gmsh module"
#endif
#ifndef BIPHASIC_GMSH_LIBRARY_PATH
#error "BIPHASIC_GMSH_LIBRARY_PATH must name the gmsh library the module links"
#endif

namespace biphasic::detail {

namespace {

namespace fs = std::filesystem;

std::string module_path() {
  const char* env = std::getenv("BIPHASIC_GMSH_MODULE");
  return env && *env ? std::string(env) : std::string(BIPHASIC_GMSH_MODULE_PATH);
}

/// "path size mtime" of the file a path resolves to, or "path missing".
std::string file_identity(const std::string& path) {
  std::error_code ec;
  const fs::path real = fs::canonical(path, ec);
  if (ec) return path + " missing";
  const auto size = fs::file_size(real, ec);
  const auto time = fs::last_write_time(real, ec).time_since_epoch().count();
  return real.string() + ' ' + std::to_string(size) + ' ' + std::to_string(time);
}

}  // namespace

const GmshBackend& gmsh_backend() {
  static std::mutex mutex;
  static const GmshBackend* backend = nullptr;
  std::lock_guard lock(mutex);
  if (backend) return *backend;
  const std::string path = module_path();
  // RTLD_LOCAL: gmsh's symbols stay out of the process's global scope.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw std::runtime_error("cannot load the gmsh mesher module '" + path +
                             "': " + (why ? why : "unknown error"));
  }
  using Entry = const GmshBackend* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "biphasic_gmsh_backend"));
  const GmshBackend* table = entry ? entry() : nullptr;
  if (!table || table->abi != GmshBackend::kAbi) {
    dlclose(handle);
    throw std::runtime_error("'" + path + "' is not a gmsh mesher module of this build");
  }
  backend = table;  // the module stays loaded for the life of the process
  return *backend;
}

std::string gmsh_backend_identity() {
  return "module " + file_identity(module_path()) + "; gmsh " +
         file_identity(BIPHASIC_GMSH_LIBRARY_PATH);
}

}  // namespace biphasic::detail
