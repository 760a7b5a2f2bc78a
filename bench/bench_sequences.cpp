#include "bench/bench_sequences.hpp"

#include <cstdlib>
#include <memory>

#include "core/camera/camera_yaml.hpp"
#include "sequences/open_sequence.hpp"

namespace facadeslam::bench {
namespace {

std::unique_ptr<BenchSequence> read_sequence(const std::filesystem::path& list, const std::filesystem::path& camera) {
  if (!std::filesystem::exists(list) || !std::filesystem::exists(camera)) return nullptr;
  auto s = std::make_unique<BenchSequence>(BenchSequence{load_camera(camera), {}});
  auto source = open_sequence(list, SequenceOptions{});
  while (auto frame = source->next()) s->frames.push_back(std::move(*frame));
  return s;
}

}  // namespace

std::filesystem::path source_dir() {
  const char* root = std::getenv("FACADESLAM_SOURCE_DIR");
  return root ? std::filesystem::path(root) : std::filesystem::path(FACADESLAM_SOURCE_DIR);
}

const BenchSequence* demo_sequence() {
  static const auto s =
      read_sequence(source_dir() / "data/demo/sequence/rgb.txt", source_dir() / "data/demo/sequence/camera.yaml");
  return s.get();
}

const BenchSequence* kitti_snippet() {
  static const auto s = read_sequence(source_dir() / "../shared/data/kitti06-snippet/rgb.txt",
                                      source_dir() / "../shared/data/kitti06-snippet/camera.yaml");
  return s.get();
}

}  // namespace facadeslam::bench
