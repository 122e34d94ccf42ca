// Sample table files (docs/table-format.md) through read_table. The last 8 bytes of a table are
// a checksum of the rest, which random mutations would almost never match, so the harness
// rewrites it: the fuzzer then reaches the table bodies. The checksum's own check is a unit test.
#include "sampling/core/errors.h"
#include "sampling/core/hash.h"
#include "sampling/samplers/sample_table.h"
#include "tests/fuzz/fuzz_input_file.h"

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string bytes(pdrt::fuzz::as_text(data, size));
  if (bytes.size() >= 8) {
    const uint64_t sum = pdrt::fnv1a(std::string_view(bytes).substr(0, bytes.size() - 8));
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
  }
  const auto file = pdrt::fuzz::write_input(bytes, "t.pdrttbl");
  try {
    pdrt::read_table(file);
  } catch (const pdrt::InputError&) {}
  return 0;
}
