#pragma once
// The fixture of the CLI tests that run `facadeslam` on a tiny synthetic
// LabelMeFacade-layout dataset (3 training, 2 test images) in a scratch
// folder of their own.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/apps/cli_run.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::test {

class DatasetCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(scratch());
    semantics::test_util::write_synthetic_dataset(data(), 3, 2);
  }
  std::filesystem::path data() const { return dir_ / "data"; }
  std::filesystem::path scratch() const { return dir_ / "scratch"; }
  CliResult run(const std::string& arguments) { return run_cli(FACADESLAM_BINARY, arguments, scratch()); }

  TempDir dir_;
};

}  // namespace facadeslam::test
