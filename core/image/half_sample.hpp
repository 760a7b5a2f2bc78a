#pragma once
// 2x2 box down-sampling, as PTAM's pyramid does. Unlike cv::pyrDown (whose
// Gaussian is centred on even pixels) a box average keeps the pixel-centre
// convention exact across levels: level-l coordinate x_l = (x_0 + 0.5) / 2^l - 0.5.
#include <opencv2/core.hpp>

namespace facadeslam {

// Averages each 2x2 block of an 8-bit single-channel image (rounded); the
// result is floor(w/2) x floor(h/2): an odd last row/column is dropped.
cv::Mat half_sample(const cv::Mat& grey);

}  // namespace facadeslam
