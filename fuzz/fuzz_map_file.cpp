// The map file reader (`replay --load-map`): magic, version, checksum, then
// the semantic checks (levels, ids, finite values, sizes before allocating).
//
// The input is the file's body: the target appends the right checksum.
// Random bytes with a wrong checksum stop at one comparison (the bad-input
// corpus and the unit tests cover that); with it, every mutation reaches the
// checks a hostile file with a valid checksum meets. So that mutations start
// from a real structure, the target seeds its corpus with a small valid map
// (the map tests' fixture on an 80x64 camera, ~45 KB) before libFuzzer reads
// the corpus.
#include <string>

#include "core/map/map.hpp"
#include "core/map/map_io.hpp"
#include "fuzz/fuzz_input.hpp"
#include "tests/support/small_map.hpp"

namespace {

// A valid map without its trailing 8-byte checksum, written as `path`.
void write_valid_map_body(const std::filesystem::path& path) {
  using namespace facadeslam;
  const Camera camera(80, 64, PinholeRadTan{75, 75, 39.5, 31.5, 0.01, 0, 0, 0, 0});  // the pyramid needs 64 px
  Map map;
  test::build_test_map(map, 8, camera);
  save_map(path, map, camera);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - sizeof(std::uint64_t));
}

}  // namespace

// The corpus folders are the command line's arguments that are not options.
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  for (int i = 1; i < *argc; ++i) {
    const std::filesystem::path folder = (*argv)[i];
    if ((*argv)[i][0] == '-' || !std::filesystem::is_directory(folder)) continue;
    write_valid_map_body(folder / "valid_small_map.body");
    break;
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace facadeslam;
  const std::string file = test::with_map_checksum(std::string(reinterpret_cast<const char*>(data), size));
  const auto path = fuzz::write_input("input.fslmap", reinterpret_cast<const std::uint8_t*>(file.data()), file.size());
  fuzz::expect_clean_rejection([&] {
    Map map;
    load_map(path, map);
  });
  return 0;
}
