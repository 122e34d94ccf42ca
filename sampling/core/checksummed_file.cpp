#include "sampling/core/checksummed_file.h"

#include "sampling/core/atomic_file.h"
#include "sampling/core/hash.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace pdrt {

void write_checksummed_file(const std::filesystem::path& path, std::string_view magic, std::string_view body) {
  const uint64_t sum = fnv1a(body);
  write_file_atomically(path, [&](std::ostream& os) {
    os.write(magic.data(), std::streamsize(magic.size()));
    os.write(body.data(), std::streamsize(body.size()));
    os.write(reinterpret_cast<const char*>(&sum), sizeof sum);
  });
}

std::optional<std::string> read_checksummed_file(const std::filesystem::path& path, std::string_view magic,
                                                 std::size_t body_size) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() != magic.size() + body_size + 8 || std::string_view(bytes).substr(0, magic.size()) != magic)
    return std::nullopt;
  std::string body = bytes.substr(magic.size(), body_size);
  uint64_t sum;
  std::memcpy(&sum, bytes.data() + magic.size() + body_size, 8);
  if (sum != fnv1a(body)) return std::nullopt;
  return body;
}

}  // namespace pdrt
