#include "renderer/render/process_group.h"

#include <algorithm>
#include <cstring>

namespace pdrt {

void copy_spans(const std::vector<ByteSpan>& from, const std::vector<ByteSpan>& to) {
  std::size_t i = 0, at = 0;  // the span of `from` being read and the bytes of it already copied
  for (const ByteSpan& t : to)
    for (std::size_t done = 0; done < t.size && i < from.size();) {
      const std::size_t n = std::min(t.size - done, from[i].size - at);
      std::memcpy(t.data + done, from[i].data + at, n);
      done += n, at += n;
      if (at == from[i].size) ++i, at = 0;
    }
}

std::vector<std::vector<ByteSpan>> split_messages(const std::vector<ByteSpan>& spans, std::size_t limit) {
  std::vector<std::vector<ByteSpan>> out;
  std::size_t in_message = limit;  // full: the next byte opens a message
  for (const ByteSpan& s : spans)
    for (std::size_t at = 0; at < s.size;) {
      if (in_message == limit) out.emplace_back(), in_message = 0;
      const std::size_t n = std::min(s.size - at, limit - in_message);
      out.back().push_back({s.data + at, n});
      at += n, in_message += n;
    }
  return out;
}

}  // namespace pdrt
