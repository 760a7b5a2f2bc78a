#pragma once
// From the renderer's float images to what a camera delivers and what the
// sequence stores: pixel noise, 8-bit quantisation, depth in millimetres.
#include <cstdint>

#include <opencv2/core.hpp>

namespace facadeslam::synth {

// Adds zero-mean Gaussian noise of `sigma` (8-bit units) independently to
// every channel of every pixel of a CV_32FC3 image, in place. The noise of a
// value depends only on (seed, frame, pixel, channel), so it is the same on
// every run. (Deviates come from a 65536-entry quantile table indexed by
// 16-bit slices of a hash: exact in distribution to 1/65536.)
void add_pixel_noise(cv::Mat& colour, double sigma, std::uint64_t seed, int frame);

// CV_32FC3 -> CV_8UC3: rounded to the nearest integer, clamped to 0..255.
cv::Mat quantise(const cv::Mat& colour);

// z-depth in metres (CV_32FC1, 0 = no surface) -> CV_16UC1 millimetres,
// rounded; 0 means no surface, or a surface farther than 65.535 m (which a
// 16-bit millimetre image cannot hold).
cv::Mat depth_millimetres(const cv::Mat& depth_m);

}  // namespace facadeslam::synth
