#include "renderer/render/image_module.h"

#include "sampling/core/errors.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace pdrt {
namespace fs = std::filesystem;

namespace {

fs::path module_path() {
  if (const char* env = std::getenv("PDRT_IMAGE_MODULE"); env && *env) return env;
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path beside = exe.parent_path() / PDRT_IMAGE_MODULE_FILE_NAME;
    if (fs::exists(beside, ec)) return beside;
  }
  return PDRT_IMAGE_MODULE_BUILD_PATH;
}

const PdrtImageModule& load() {
  const fs::path path = module_path();
  // Never closed: OpenImageIO keeps threads and static state until the process exits.
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError("cannot load the image module " + path.string() + ": " + ::dlerror());
  auto entry = reinterpret_cast<const PdrtImageModule* (*)()>(::dlsym(handle, PDRT_IMAGE_MODULE_SYMBOL));
  if (!entry) throw InputError("image module " + path.string() + ": " + ::dlerror());
  const PdrtImageModule* m = entry();
  if (!m || m->abi != PDRT_IMAGE_MODULE_ABI)
    throw InputError("image module " + path.string() + ": ABI version " + std::to_string(m ? m->abi : -1) +
                     ", expected " + std::to_string(PDRT_IMAGE_MODULE_ABI) + " (rebuild pdrt)");
  return *m;
}

}  // namespace

const PdrtImageModule& image_module() {
  // A throwing initialiser leaves the static uninitialised: the next call tries again.
  static const PdrtImageModule& m = load();
  return m;
}

}  // namespace pdrt
