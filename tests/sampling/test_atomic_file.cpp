// write_file_atomically: missing parent directories are created; failures name the path.
#include "sampling/core/atomic_file.h"
#include "sampling/core/errors.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pdrt {
namespace {
namespace fs = std::filesystem;

TEST(AtomicFile, CreatesMissingParentDirectories) {
  const fs::path path = test::scratch_dir("atomic_mkdir") / "a" / "b" / "f.txt";
  write_file_atomically(path, [](std::ostream& os) { os << "hello\n"; });
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "hello");
  EXPECT_EQ(std::distance(fs::directory_iterator(path.parent_path()), fs::directory_iterator()), 1)
      << "no temporary file left beside it";
}

TEST(AtomicFile, DirectoryThatCannotBeCreatedIsAnInputErrorNamingThePath) {
  const fs::path dir = test::scratch_dir("atomic_mkdir_fail");
  std::ofstream(dir / "a-file") << "x";
  const fs::path path = dir / "a-file" / "sub" / "f.txt";
  try {
    write_file_atomically(path, [](std::ostream& os) { os << "hello\n"; });
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "a-file"));
}

TEST(AtomicFile, CheckWritableCreatesNothing) {
  const fs::path dir = test::scratch_dir("atomic_check");
  check_writable(dir / "new" / "f.txt");
  EXPECT_FALSE(fs::exists(dir / "new"));
}

}  // namespace
}  // namespace pdrt
