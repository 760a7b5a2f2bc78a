#pragma once
// The calibration images of a folder: regular files ending in .png, .jpg,
// .jpeg or .bmp (any letter case), sorted by name. Sub-folders are not
// searched, so a folder of outputs beside the images does not leak in.
#include <filesystem>
#include <vector>

namespace facadeslam::calib {

// Throws Error naming the folder when it does not exist, is not a folder, or
// holds no image file.
std::vector<std::filesystem::path> list_image_files(const std::filesystem::path& folder);

}  // namespace facadeslam::calib
