#pragma once
// Distance of every pixel to the nearest Canny edge pixel (thesis III.4.4).
#include <opencv2/core.hpp>

namespace facadeslam::semantics {

// `edges`: CV_8U, non-zero = edge. `distance`: CV_32F of the same size,
// written in place. Exact Euclidean distance in pixels (separable: distances
// down the columns, then the nearest column along each row); an image
// without any edge gets the image diagonal everywhere (nothing is closer).
void distance_to_edges(const cv::Mat& edges, cv::Mat& distance);

}  // namespace facadeslam::semantics
