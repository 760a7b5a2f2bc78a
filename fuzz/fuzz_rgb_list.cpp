// The TUM rgb.txt reader (`replay --sequence DIR/rgb.txt`): timestamps,
// paths, order. One image, a.png, exists beside the list so that valid
// lines get past the existence check.
#include <opencv2/imgcodecs.hpp>

#include "fuzz/fuzz_input.hpp"
#include "sequences/sequence_options.hpp"
#include "sequences/tum_list_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace facadeslam;
  static const bool image_written =
      cv::imwrite((fuzz::scratch_folder() / "a.png").string(), cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(90)));
  (void)image_written;
  const auto path = fuzz::write_input("rgb.txt", data, size);
  fuzz::expect_clean_rejection([&] {
    TumListSource source(path, SequenceOptions{});
    (void)source;
  });
  return 0;
}
