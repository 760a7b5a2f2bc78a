// The map file reader (`replay --load-map`): magic, version, checksum, then
// the semantic checks (levels, ids, finite values, sizes before allocating).
#include "core/map/map.hpp"
#include "core/map/map_io.hpp"
#include "fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace facadeslam;
  const auto path = fuzz::write_input("input.fslmap", data, size);
  fuzz::expect_clean_rejection([&] {
    Map map;
    load_map(path, map);
  });
  return 0;
}
