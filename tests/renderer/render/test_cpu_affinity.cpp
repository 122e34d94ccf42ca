// The affinity mask pdrt reads and the warning for --threads beyond it (issue 33).
#include "renderer/render/cpu_affinity.h"
#include "tests/support/one_cpu.h"

#include <gtest/gtest.h>

using namespace pdrt;

TEST(CpuAffinity, AllowedCpusFollowTheMask) {
  const int all = allowed_cpus();
  EXPECT_GE(all, 1);
  {
    test::OneCpu one;
    ASSERT_TRUE(one.ok());
    EXPECT_EQ(allowed_cpus(), 1);
  }
  EXPECT_EQ(allowed_cpus(), all);
}

TEST(CpuAffinity, NoWarningWhenTheThreadsFit) {
  EXPECT_EQ(thread_request_warning(0, 1), "");  // 0: all the mask allows
  EXPECT_EQ(thread_request_warning(4, 4), "");
  EXPECT_EQ(thread_request_warning(2, 16), "");
}

TEST(CpuAffinity, WarningNamesTheCountsAndTheMpirunOptions) {
  const std::string w = thread_request_warning(8, 1);
  EXPECT_EQ(w.find('\n'), std::string::npos) << w;
  for (const char* part : {"--threads 8", "1 CPU ", "runs 1 thread;", "--bind-to none", "--map-by slot:PE=8"})
    EXPECT_NE(w.find(part), std::string::npos) << part << " in " << w;
  EXPECT_NE(thread_request_warning(16, 4).find("4 CPUs"), std::string::npos);
}
