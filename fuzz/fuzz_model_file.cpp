// The forest model reader (`replay --model`, `evaluate labels --model`):
// header, genome, class table, zlib-compressed trees.
#include "fuzz/fuzz_input.hpp"
#include "semantics/forest/forest_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace facadeslam;
  const auto path = fuzz::write_input("input.fsmodel", data, size);
  fuzz::expect_clean_rejection([&] { (void)semantics::load_forest_model(path); });
  return 0;
}
