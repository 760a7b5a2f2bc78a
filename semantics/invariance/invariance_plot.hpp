#pragma once
// Plots of an invariance run: per case, the match rate (0..1) against the
// case's parameter, one line per descriptor (core/plot/line_plot.hpp).
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

#include "core/plot/line_plot.hpp"
#include "semantics/invariance/invariance_suite.hpp"

namespace facadeslam::semantics {

plot::LinePlot case_plot(const InvarianceResult& result, const InvarianceCaseResult& r, cv::Size size = {560, 400});

// Every case as one panel of a single picture, `columns` panels per row.
cv::Mat invariance_figure(const InvarianceResult& result, int columns = 4, cv::Size panel = {560, 400});

// The figure as a PNG (name must end in .png), written atomically.
void save_invariance_figure(const std::filesystem::path& path, const InvarianceResult& result);

// One PNG per case, folder/invariance-<case>.png (folder created if needed);
// returns the files written.
std::vector<std::filesystem::path> save_case_plots(const std::filesystem::path& folder, const InvarianceResult& result);

}  // namespace facadeslam::semantics
