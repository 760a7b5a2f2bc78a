// The camera YAML reader (`--camera`, a sequence's camera.yaml): yaml-cpp
// through the project's ConfigNode (unknown keys, ranges, models).
#include "core/camera/camera_yaml.hpp"
#include "fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace facadeslam;
  const auto path = fuzz::write_input("camera.yaml", data, size);
  fuzz::expect_clean_rejection([&] { (void)load_camera(path); });
  return 0;
}
