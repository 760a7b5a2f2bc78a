#pragma once
// A folder of images, read in natural name order (frame2 before frame10).
//
// Images: regular files with extension png, jpg, jpeg, bmp, tif, tiff, pgm or
// ppm (any case); hidden files (".name") are ignored, sub-folders are not read.
// Timestamps, in this order of preference:
//  - SequenceOptions::timestamps_file when set;
//  - times.txt or timestamps.txt in the folder (both present is an Error);
//  - otherwise index / fps.
// A timestamps file holds one number per image, in name order ('#' comments
// and blank lines allowed); a count that differs from the number of images, a
// line that is not one number or a timestamp not after the previous one is an
// Error naming the file (and line).
#include <filesystem>

#include "sequences/image_list_source.hpp"
#include "sequences/sequence_options.hpp"

namespace facadeslam {

class ImageFolderSource : public ImageListSource {
 public:
  // Lists the folder (no image is decoded yet). Error when the folder is
  // missing, holds no images, or its timestamps file is wrong.
  ImageFolderSource(const std::filesystem::path& folder, const SequenceOptions& options);
};

// True for the extensions above (case-insensitive), e.g. ".PNG".
bool has_image_extension(const std::filesystem::path& path);

}  // namespace facadeslam
