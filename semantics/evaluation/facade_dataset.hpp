#pragma once
// The LabelMeFacade layout (../shared/data/README.md):
//   DIR/train.txt, DIR/test.txt   image names, one per line (no extension;
//                                 blank lines and '#' comments are skipped)
//   DIR/images/NAME.jpg           the photo (.jpg, .jpeg or .png)
//   DIR/labels/NAME.png           the colour label image, same size
// Opening checks that every listed file exists, so a long evaluation fails
// at once rather than after hours.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

struct LabelledImage {
  std::string name;
  std::filesystem::path image, label;
  // How the photo is seen (training augmentation, `train --scales --grey`):
  // resized by `scale` (labels by nearest neighbour) and, when `grey`, turned
  // to grey in three channels, as a grey camera's frames reach the worker.
  double scale = 1.0;
  bool grey = false;
};

// One split list (`list` = "train.txt" or "test.txt") of the dataset at
// `root`. Errors name the folder or file and what was expected: a missing
// folder or list, an empty list, an image without a label file (or the
// reverse).
std::vector<LabelledImage> read_facade_split(const std::filesystem::path& root, const std::string& list);

// The photo (8-bit BGR) and its label image (8-bit BGR), seen as the entry
// says (scale, grey). Throws Error naming the file when either cannot be read
// or their sizes differ.
struct LoadedLabelledImage {
  cv::Mat bgr, label;
};
LoadedLabelledImage load_labelled_image(const LabelledImage& entry);

// `images` once per scale (scale-major order), all grey when `grey`. Throws
// Error for a scale outside (0, 8] or an empty list of scales.
std::vector<LabelledImage> with_views(const std::vector<LabelledImage>& images, const std::vector<double>& scales,
                                      bool grey);

// Where the evaluations get an entry's pixels: load_labelled_image, or a
// DecodedImageCache that decoded them once.
using LabelledImageLoader = std::function<LoadedLabelledImage(const LabelledImage&)>;

// Photos and label images decoded once (as stored: the entry's view is
// applied on the way out), up to a memory budget (~2 MB per
// LabelMeFacade image): the optimiser reads the same training images for every
// genome, and decoding them was a fifth of an evaluation. Entries beyond the
// budget, or not given at construction, are read from disk when asked for.
// Read-only after construction, so threads may share it (cv::Mat headers are
// copied, not the pixels).
class DecodedImageCache {
 public:
  DecodedImageCache(const std::vector<LabelledImage>& images, std::size_t budget_bytes);
  LoadedLabelledImage operator()(const LabelledImage& entry) const;
  std::size_t images() const { return decoded_.size(); }
  std::size_t bytes() const { return bytes_; }

 private:
  std::map<std::filesystem::path, LoadedLabelledImage> decoded_;  // by photo path
  std::size_t bytes_ = 0;
};

}  // namespace facadeslam::semantics
