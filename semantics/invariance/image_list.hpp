#pragma once
// The images an invariance run uses, from what the user names:
//  - a folder: its image files (.jpg .jpeg .png .bmp .ppm .pgm .tif .tiff,
//    any case), sorted by name, not recursive;
//  - an image file;
//  - a .txt list, one image per line (blank lines and '#' comments skipped):
//    a path relative to the list's folder, or a LabelMeFacade name looked up
//    as images/NAME.jpg (or .jpeg/.png) beside the list, so that the dataset's
//    own test.txt works as it is.
// Entries keep the order given. Every failure is an Error naming the path.
#include <cstddef>
#include <filesystem>
#include <vector>

namespace facadeslam::semantics {

// `max_images` > 0 keeps the first max_images of the result. Throws Error for
// no input, a missing path, a folder or list without images, or a list entry
// that names no file.
std::vector<std::filesystem::path> list_images(const std::vector<std::filesystem::path>& inputs,
                                               std::size_t max_images = 0);

}  // namespace facadeslam::semantics
