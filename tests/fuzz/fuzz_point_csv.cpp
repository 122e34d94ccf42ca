// Point-set CSV files (`pdrt sample`'s output, read back by `pdrt analyze`) through read_point_csv.
#include "sampling/core/errors.h"
#include "sampling/core/point_csv.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = pdrt::fuzz::write_input(pdrt::fuzz::as_text(data, size), "points.csv");
  try {
    pdrt::read_point_csv(file);
  } catch (const pdrt::InputError&) {}
  return 0;
}
