#include "semantics/invariance/invariance_plot.hpp"

#include <algorithm>
#include <string>

#include "core/plot/png_file.hpp"
#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

plot::LinePlot case_plot(const InvarianceResult& result, const InvarianceCaseResult& r, cv::Size size) {
  const InvarianceCaseInfo& info = case_info(r.id);
  plot::LinePlot p(size.width, size.height);
  p.set_title(std::string(info.title));
  p.set_x_label(std::string(info.parameter));
  p.set_y_label("match rate");
  // Every curve on the same scale, so that panels compare at a glance.
  p.set_y_range(0.0, 1.0);
  plot::SeriesStyle style;
  style.markers = true;
  for (std::size_t d = 0; d < result.descriptors.size(); ++d)
    p.add_series(result.descriptors[d], r.values, r.match_rate[d], style);
  return p;
}

cv::Mat invariance_figure(const InvarianceResult& result, int columns, cv::Size panel) {
  if (result.cases.empty()) throw Error("invariance plot: the run has no case");
  if (columns < 1) throw Error(cat("invariance plot: expected at least one column, got ", columns));
  const int count = static_cast<int>(result.cases.size());
  const int cols = std::min(columns, count), rows = (count + cols - 1) / cols;
  cv::Mat figure(rows * panel.height, cols * panel.width, CV_8UC3, cv::Scalar::all(255));
  for (int k = 0; k < count; ++k) {
    const cv::Rect where((k % cols) * panel.width, (k / cols) * panel.height, panel.width, panel.height);
    case_plot(result, result.cases[static_cast<std::size_t>(k)], panel).render().copyTo(figure(where));
  }
  return figure;
}

void save_invariance_figure(const std::filesystem::path& path, const InvarianceResult& result) {
  plot::save_png(path, invariance_figure(result));
}

std::vector<std::filesystem::path> save_case_plots(const std::filesystem::path& folder,
                                                   const InvarianceResult& result) {
  std::vector<std::filesystem::path> written;
  for (const InvarianceCaseResult& r : result.cases) {
    const std::filesystem::path path = folder / cat("invariance-", case_info(r.id).name, ".png");
    case_plot(result, r).save_png(path);
    written.push_back(path);
  }
  return written;
}

}  // namespace facadeslam::semantics
