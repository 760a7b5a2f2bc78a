#pragma once
// A confusion matrix as a picture: one cell per (true, predicted) class
// pair, shaded by the share of the true class's keypoints (row-normalised,
// so rare classes are as readable as common ones), with that percentage and
// the count written in the cell. The diagonal is the per-class recall.
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/evaluation/confusion_matrix.hpp"

namespace facadeslam::semantics {

// 8-bit BGR picture. `names` has one entry per class (Error otherwise).
cv::Mat render_confusion_matrix(const ConfusionMatrix& matrix, const std::vector<std::string>& names,
                                const std::string& title);

// Renders and writes a PNG atomically (name must end in .png).
void save_confusion_matrix_png(const std::filesystem::path& path, const ConfusionMatrix& matrix,
                               const std::vector<std::string>& names, const std::string& title);

}  // namespace facadeslam::semantics
