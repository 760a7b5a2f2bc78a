#pragma once
// The LabelMeFacade layout (../shared/data/README.md):
//   DIR/train.txt, DIR/test.txt   image names, one per line (no extension;
//                                 blank lines and '#' comments are skipped)
//   DIR/images/NAME.jpg           the photo (.jpg, .jpeg or .png)
//   DIR/labels/NAME.png           the colour label image, same size
// Opening checks that every listed file exists, so a long evaluation fails
// at once rather than after hours.
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

struct LabelledImage {
  std::string name;
  std::filesystem::path image, label;
};

// One split list (`list` = "train.txt" or "test.txt") of the dataset at
// `root`. Errors name the folder or file and what was expected: a missing
// folder or list, an empty list, an image without a label file (or the
// reverse).
std::vector<LabelledImage> read_facade_split(const std::filesystem::path& root, const std::string& list);

// The photo (8-bit BGR) and its label image (8-bit BGR). Throws Error naming
// the file when either cannot be read or their sizes differ.
struct LoadedLabelledImage {
  cv::Mat bgr, label;
};
LoadedLabelledImage load_labelled_image(const LabelledImage& entry);

}  // namespace facadeslam::semantics
