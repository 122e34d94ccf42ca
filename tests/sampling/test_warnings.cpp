// sampling/core/warnings.h: lines another process held (an MPI rank other than 0) are printed
// once per kind, and not at all when this process printed that kind itself. (Holding is
// process-wide and for good, so the tests here never turn it on.)
#include "sampling/core/warnings.h"

#include <gtest/gtest.h>

namespace pdrt {
namespace {

TEST(Warnings, HeldLinesOfAKindPrintedHereOrBeforeAreNotPrintedAgain) {
  ::testing::internal::CaptureStderr();
  warn("pdrt: test: first pixel (1, 2)", "test: pixel kind");
  print_held_warnings({"test: pixel kind\npdrt: test: first pixel (7, 9)", "test: count kind\npdrt: test: 3 things",
                       "test: count kind\npdrt: test: 4 things"});
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "pdrt: test: first pixel (1, 2)\npdrt: test: 3 things\n");
}

}  // namespace
}  // namespace pdrt
