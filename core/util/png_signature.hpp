#pragma once
// Every PNG this program writes carries a text chunk naming it ("Software":
// "facadeslam"), so that an output option (`--plot x.png`) replaces a PNG
// only when this program drew it, never a user's photo that has the name
// (output_policy.hpp). The chunk is PNG's own tEXt, which viewers ignore.
#include <filesystem>
#include <vector>

namespace facadeslam {

// `png` (an encoded PNG, e.g. from cv::imencode) with the chunk inserted
// after its header. Throws Error when `png` does not start like a PNG.
std::vector<unsigned char> sign_png(const std::vector<unsigned char>& png);

// True when the file is a PNG whose chunks before its image data include
// this program's.
bool is_signed_png(const std::filesystem::path& path);

}  // namespace facadeslam
