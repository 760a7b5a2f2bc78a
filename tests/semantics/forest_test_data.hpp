#pragma once
// A small classification problem and forest settings shared by the forest
// and model-file tests, and whole-file byte access for damaging files.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/forest/forest_params.hpp"

namespace facadeslam::semantics::test_util {

// Three well separated 2-D blobs (classes 1, 4, 6) plus a noise column.
inline void blobs(int per_class, unsigned seed, cv::Mat& samples, std::vector<int>& labels) {
  cv::RNG rng(seed);
  const int ids[3] = {1, 4, 6};
  const float cx[3] = {0.f, 5.f, 0.f}, cy[3] = {0.f, 0.f, 5.f};
  samples.create(3 * per_class, 3, CV_32F);
  labels.clear();
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < per_class; ++i) {
      float* row = samples.ptr<float>(c * per_class + i);
      row[0] = cx[c] + static_cast<float>(rng.gaussian(0.6));
      row[1] = cy[c] + static_cast<float>(rng.gaussian(0.6));
      row[2] = static_cast<float>(rng.uniform(0.0, 1.0));
      labels.push_back(ids[c]);
    }
}

inline ForestParams small_forest() {
  ForestParams p;
  p.trees = 15;
  p.max_depth = 8;
  p.split_variables = 2;
  p.min_sample_count = 2;
  return p;
}

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace facadeslam::semantics::test_util
