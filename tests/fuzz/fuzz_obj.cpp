// Wavefront OBJ meshes with their MTL library through tinyobjloader and pdrt's checks. The input
// holds both: what follows a line "#pdrt-fuzz-mtl" is written to model.mtl (the seeds are OBJ
// files with their MTL appended so), the rest to model.obj. The first byte's low bit picks
// override_materials.
#include "renderer/scene/obj_loader.h"
#include "sampling/core/errors.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text = pdrt::fuzz::as_text(data, size);
  constexpr std::string_view kSplit = "#pdrt-fuzz-mtl\n";
  const std::size_t cut = text.find(kSplit);
  const auto obj = pdrt::fuzz::write_input(text.substr(0, cut), "model.obj");
  pdrt::fuzz::write_input(cut == text.npos ? std::string_view() : text.substr(cut + kSplit.size()), "model.mtl");
  try {
    pdrt::load_obj(obj, size > 0 && (data[0] & 1));
  } catch (const pdrt::InputError&) {}
  return 0;
}
