// The settings readers (`replay --config`, `replay --semantics-config`):
// configs/slam.yaml's nested sections and configs/semantics.yaml's class
// lists, through the project's ConfigNode. The input's first byte chooses
// the reader, so that one target covers both (they are small and share
// ConfigNode, whose YAML handling fuzz_camera_yaml exercises too).
#include <fstream>
#include <sstream>
#include <string>

#include "fuzz/fuzz_input.hpp"
#include "slam/slam_options.hpp"

namespace {

// The shipped file behind the byte that chooses its reader, as a seed.
void write_seed(const std::filesystem::path& folder, const char* shipped, char reader) {
  std::ifstream in(shipped, std::ios::binary);
  if (!in) return;  // not run from the project root: the corpus alone seeds
  std::ostringstream text;
  text << reader << in.rdbuf();
  std::ofstream(folder / std::filesystem::path(shipped).filename(), std::ios::binary | std::ios::trunc) << text.str();
}

}  // namespace

// Seeds the first corpus folder (the command line's arguments that are not
// options) with the shipped settings (scripts/fuzz runs from the project root).
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  for (int i = 1; i < *argc; ++i) {
    const std::filesystem::path folder = (*argv)[i];
    if ((*argv)[i][0] == '-' || !std::filesystem::is_directory(folder)) continue;
    write_seed(folder, "configs/slam.yaml", '\0');
    write_seed(folder, "configs/semantics.yaml", '\1');
    break;
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace facadeslam;
  if (size == 0) return 0;
  const bool semantics = (data[0] & 1u) != 0;
  const auto path = fuzz::write_input(semantics ? "semantics.yaml" : "slam.yaml", data + 1, size - 1);
  fuzz::expect_clean_rejection([&] {
    if (semantics)
      (void)load_semantics_options(path);
    else
      (void)load_slam_options(path);
  });
  return 0;
}
