#pragma once
// Brute-force nearest-neighbour matching (L2) and the match rate of the
// invariance cases: the share of keypoints whose nearest neighbour among the
// changed image's descriptors is their own counterpart.
//
// Rule for ties: a keypoint counts as matched only when its counterpart is
// strictly nearer than every other candidate. Identical descriptors of
// different keypoints (flat sky, an all-zero row) cannot tell the keypoints
// apart, so they are misses, not a lucky pick of the lower index. Non-finite
// distances (a descriptor with NaN or inf values) are never nearest: a
// counterpart at such a distance is a miss, another candidate at one is
// ignored.
#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

// `squared_distances`: n x n CV_32F, element (i, j) the distance of
// reference keypoint i to candidate j; candidate i is i's counterpart.
// Element i of the result tells whether row i is matched. Throws Error
// unless the matrix is square and CV_32F.
std::vector<bool> matched_rows(const cv::Mat& squared_distances);

// Row i of `reference` and row i of `changed` describe the same keypoint
// (both CV_32F, same size). Returns how many rows are matched (rule above),
// computing the distances in blocks so that memory stays small.
std::size_t count_matched(const cv::Mat& reference, const cv::Mat& changed);

// matched / rows; NaN when there are no rows.
double match_rate(std::size_t matched, std::size_t rows);

}  // namespace facadeslam::semantics
