#pragma once
// The optimise tests' GA settings: configs/optimise.yaml as shipped (its
// fitness weights, time term and cost model included) with only the run's
// size scaled down to a tiny synthetic dataset, so that what the tests
// check (the same result whatever the threads, ranks or a resume) is
// checked on the settings users run.
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::test {

// configs/optimise.yaml with each top-level `key: value` line of `sizes`
// replaced (a key the file lacks fails the test: the file changed shape).
inline std::string scaled_down_shipped_config(const std::vector<std::pair<std::string, std::string>>& sizes = {
                                                  {"population", "4"},
                                                  {"generations", "3"},
                                                  {"max_train_images", "6"},
                                                  {"max_validation_images", "2"},
                                                  {"max_samples", "2000"},
                                                  {"max_trees", "8"},
                                                  {"max_depth", "8"}}) {
  std::istringstream in(read_file_text(source_dir() / "configs" / "optimise.yaml"));
  std::string text, line;
  std::vector<bool> found(sizes.size(), false);
  bool cost_model = false;
  while (std::getline(in, line)) {
    cost_model |= line.rfind("cost_model:", 0) == 0;
    for (std::size_t i = 0; i < sizes.size(); ++i)
      if (line.rfind(sizes[i].first + ":", 0) == 0) {
        line = sizes[i].first + ": " + sizes[i].second;
        found[i] = true;
      }
    text += line + "\n";
  }
  EXPECT_TRUE(cost_model) << "configs/optimise.yaml has no cost_model block";
  for (std::size_t i = 0; i < sizes.size(); ++i)
    EXPECT_TRUE(found[i]) << "configs/optimise.yaml has no top-level " << sizes[i].first;
  return text;
}

}  // namespace facadeslam::test
