#pragma once
// A fixture for loader tests that write small scene files: a scratch folder per test, a scene
// whose head (camera, film) is lines 1-3 so `rest` starts on line 4, side files, and the
// one-line error a refused file gives.
#include "renderer/scene/scene_loader.h"
#include "sampling/core/errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace pdrt::test {

class SceneFileTest : public ::testing::Test {
 protected:
  std::filesystem::path dir() const {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return std::filesystem::temp_directory_path() / ("pdrt_" + std::string(info->test_suite_name()) + "_" +
                                                     std::string(info->name()) + "_" + std::to_string(::getpid()));
  }
  std::filesystem::path scene(const std::string& rest) {
    std::filesystem::create_directories(dir());
    std::ofstream(dir() / "s.json") << "{\n"
                                       "  \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
                                       "  \"film\": {\"width\": 8, \"height\": 8},\n" +
                                           rest;
    return dir() / "s.json";
  }
  void file(const std::string& name, const std::string& text) {
    std::filesystem::create_directories(dir());
    std::ofstream(dir() / name, std::ios::binary) << text;
  }
  // The message load_scene refuses `f` with, checked to be one line.
  std::string error(const std::filesystem::path& f) {
    try {
      load_scene(f);
    } catch (const InputError& e) {
      std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      return m;
    }
    ADD_FAILURE() << "expected an InputError";
    return "";
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir(), ec);
  }
};

}  // namespace pdrt::test

#define EXPECT_ERROR(f, text)                          \
  do {                                                 \
    std::string m_ = error(f);                         \
    EXPECT_NE(m_.find(text), std::string::npos) << m_; \
  } while (0)
