// pbrt-v4 scene text through the tokenizer, the parser and the scene builder: the importer reads
// scenes downloaded from the internet. Include/Import paths resolve against an empty scratch
// directory, so they fail as missing files rather than reading the machine's files.
#include "renderer/scene/pbrt/pbrt_parser.h"
#include "renderer/scene/pbrt/pbrt_scene_builder.h"
#include "sampling/core/errors.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto directives =
        pdrt::parse_pbrt_text(pdrt::fuzz::as_text(data, size), "fuzz.pbrt", pdrt::fuzz::scratch_dir());
    // Not strict: the lenient path reaches every mapping and records the report lines. A
    // subdivided mesh is bounded to 2^20 triangles, what one input may cost here (about 8 s
    // and 0.6 GiB under the sanitizers; the default, 2^22, takes 26 s, past the 20 s limit).
    pdrt::PbrtLimits limits;
    limits.max_subdivided_triangles = int64_t(1) << 20;
    pdrt::build_pbrt_scene(directives, false, limits);
  } catch (const pdrt::InputError&) {
  } catch (const pdrt::UsageError&) {}
  return 0;
}
