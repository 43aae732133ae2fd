/// \file TemporaryFolder.h
/// A fresh folder per test under the system's temporary directory, removed afterwards.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace sgp::testing
{

class TemporaryFolderTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    folder = std::filesystem::temp_directory_path() /
             ("sgp-" + std::to_string(::getpid()) + "-" +
              ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "-" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(folder);
  }
  void TearDown() override { std::filesystem::remove_all(folder); }

  std::filesystem::path folder;
};

} // namespace sgp::testing
