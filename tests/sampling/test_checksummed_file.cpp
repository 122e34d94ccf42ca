// Cache files (checksummed_file.h): what is written reads back; a damaged, truncated or foreign
// file reads as absent, so the cache is regenerated rather than trusted.
#include "sampling/core/checksummed_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace pdrt {
namespace {

std::filesystem::path scratch(const char* name) {
  return std::filesystem::temp_directory_path() / ("pdrt-checksummed-" + std::to_string(getpid()) + "-" + name);
}

TEST(ChecksummedFile, WhatIsWrittenReadsBack) {
  const auto path = scratch("ok.bin");
  const std::string body = std::string("keys\0and more", 13);
  write_checksummed_file(path, "PDRTTEST", body);
  const auto read = read_checksummed_file(path, "PDRTTEST", body.size());
  ASSERT_TRUE(read);
  EXPECT_EQ(*read, body);
  std::filesystem::remove(path);
}

TEST(ChecksummedFile, DamagedTruncatedOrForeignFilesReadAsAbsent) {
  const auto path = scratch("bad.bin");
  const std::string body(100, 'x');
  write_checksummed_file(path, "PDRTTEST", body);
  EXPECT_FALSE(read_checksummed_file(path, "PDRTOTHR", body.size()));      // another magic
  EXPECT_FALSE(read_checksummed_file(path, "PDRTTEST", body.size() + 1));  // another size
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(20);
    f.put('y');  // one byte of the body
  }
  EXPECT_FALSE(read_checksummed_file(path, "PDRTTEST", body.size()));
  std::filesystem::resize_file(path, 50);
  EXPECT_FALSE(read_checksummed_file(path, "PDRTTEST", body.size()));
  EXPECT_FALSE(read_checksummed_file(scratch("missing.bin"), "PDRTTEST", body.size()));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace pdrt
