// PLY meshes (pbrt-v4's "plymesh") through Assimp and pdrt's checks of what it returns.
#include "renderer/scene/pbrt/ply_mesh.h"
#include "sampling/core/errors.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = pdrt::fuzz::write_input(pdrt::fuzz::as_text(data, size), "mesh.ply");
  try {
    pdrt::load_ply(file, "mesh.ply");
  } catch (const pdrt::InputError&) {}
  return 0;
}
