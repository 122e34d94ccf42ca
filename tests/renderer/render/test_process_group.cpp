// The in-place byte moves of a distributed render's exchanges (renderer/render/process_group.h):
// a film's rows travel from span lists cut differently on each side.
#include "renderer/render/process_group.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <numeric>
#include <vector>

using namespace pdrt;

namespace {

std::vector<ByteSpan> cut(std::vector<std::byte>& bytes, const std::vector<std::size_t>& sizes) {
  std::vector<ByteSpan> out;
  std::size_t at = 0;
  for (std::size_t n : sizes) out.push_back({bytes.data() + at, n}), at += n;
  return out;
}

std::vector<std::byte> counting(std::size_t n) {
  std::vector<std::byte> b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = std::byte(i * 7 + 3);
  return b;
}

}  // namespace

TEST(ProcessGroup, CopySpansCopiesTheBytesInOrderWhateverTheCuts) {
  std::vector<std::byte> from = counting(100), to(100);
  copy_spans(cut(from, {10, 0, 33, 57}), cut(to, {1, 49, 50}));
  EXPECT_EQ(from, to);
}

TEST(ProcessGroup, MessagesHoldTheSameBytesOnBothSidesOfADifferentCut) {
  std::vector<std::byte> a = counting(1000), b = counting(1000);
  const auto ma = split_messages(cut(a, {300, 300, 400}), 256), mb = split_messages(cut(b, {1, 998, 1}), 256);
  ASSERT_EQ(ma.size(), 4u);  // 256, 256, 256, 232
  ASSERT_EQ(mb.size(), ma.size());
  for (std::size_t k = 0; k < ma.size(); ++k) {
    std::size_t na = 0, nb = 0;
    for (const ByteSpan& s : ma[k]) {
      EXPECT_EQ(s.data - a.data(), std::ptrdiff_t(k * 256 + na)) << "message " << k << " is contiguous, in order";
      na += s.size;
    }
    for (const ByteSpan& s : mb[k]) nb += s.size;
    EXPECT_EQ(na, k + 1 < ma.size() ? 256u : 232u);
    EXPECT_EQ(na, nb);
  }
}

TEST(ProcessGroup, ALocalMoveCopiesItsOwnSpans) {
  std::vector<std::byte> from = counting(64), to(64);
  LocalProcessGroup().move_spans({cut(from, {64})}, {cut(to, {16, 48})});
  EXPECT_EQ(from, to);
}
