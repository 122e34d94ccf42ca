// pdrt's JSON scene files (docs/scene-format.md) through load_scene: parsing, the located error
// messages and every object's validation. Files the scene names (OBJ, textures) resolve against
// the scratch directory, where only the scene itself is.
#include "renderer/scene/scene_loader.h"
#include "sampling/core/errors.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = pdrt::fuzz::write_input(pdrt::fuzz::as_text(data, size), "scene.json");
  try {
    pdrt::load_scene(file);
  } catch (const pdrt::InputError&) {
  } catch (const pdrt::UsageError&) {}
  return 0;
}
