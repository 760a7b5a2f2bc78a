#pragma once
// Sequences read once into memory for the benches that replay them, so that
// only the system is measured, not decoding: the embedded demo (rendered by
// scripts/make-demo) and, when ../shared/data is beside the project, the
// KITTI 06 snippet. nullptr when absent (the bench then skips with a message).
// Paths are taken from FACADESLAM_SOURCE_DIR (environment, else the build's).
#include <filesystem>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/image/frame.hpp"

namespace facadeslam::bench {

struct BenchSequence {
  Camera camera;
  std::vector<Frame> frames;
};

std::filesystem::path source_dir();
const BenchSequence* demo_sequence();
const BenchSequence* kitti_snippet();

}  // namespace facadeslam::bench
