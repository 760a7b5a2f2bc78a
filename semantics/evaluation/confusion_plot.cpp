#include "semantics/evaluation/confusion_plot.hpp"

#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "core/plot/png_file.hpp"
#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kCell = 78;
constexpr int kLeft = 150;  // room for the true-class names
constexpr int kTop = 110;   // title + predicted-class names
constexpr int kMargin = 20;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

void centred_text(cv::Mat& image, const std::string& text, cv::Point centre, double scale, const cv::Scalar& colour,
                  int thickness = 1) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kFont, scale, thickness, &baseline);
  cv::putText(image, text, {centre.x - size.width / 2, centre.y + size.height / 2}, kFont, scale, colour, thickness,
              cv::LINE_AA);
}

}  // namespace

cv::Mat render_confusion_matrix(const ConfusionMatrix& matrix, const std::vector<std::string>& names,
                                const std::string& title) {
  const int n = matrix.classes();
  if (static_cast<int>(names.size()) != n) throw Error("confusion plot: one name per class is needed");
  cv::Mat image(kTop + n * kCell + kMargin, kLeft + n * kCell + kMargin, CV_8UC3, cv::Scalar::all(255));
  const cv::Scalar black(0, 0, 0), white(255, 255, 255), full(150, 60, 15);  // BGR dark blue

  cv::putText(image, title, {kMargin, 30}, kFont, 0.55, black, 1, cv::LINE_AA);
  cv::putText(image, "predicted", {kLeft, 60}, kFont, 0.5, black, 1, cv::LINE_AA);
  cv::putText(image, "true", {kMargin, kTop - 10}, kFont, 0.5, black, 1, cv::LINE_AA);
  char text[64];
  for (int t = 0; t < n; ++t) {
    const std::uint64_t row_total = matrix.truth_count(t);
    centred_text(image, names[static_cast<std::size_t>(t)], {kLeft + t * kCell + kCell / 2, kTop - 18}, 0.4, black);
    cv::putText(image, names[static_cast<std::size_t>(t)], {kMargin, kTop + t * kCell + kCell / 2 + 5}, kFont, 0.45,
                black, 1, cv::LINE_AA);
    for (int p = 0; p < n; ++p) {
      const std::uint64_t count = matrix.at(t, p);
      const double share = row_total ? static_cast<double>(count) / static_cast<double>(row_total) : 0.0;
      const cv::Rect cell(kLeft + p * kCell, kTop + t * kCell, kCell, kCell);
      cv::rectangle(image, cell, white * (1.0 - share) + full * share, cv::FILLED);
      cv::rectangle(image, cell, cv::Scalar::all(p == t ? 0 : 190), p == t ? 2 : 1);
      const cv::Scalar ink = share > 0.5 ? white : black;
      const cv::Point centre(cell.x + kCell / 2, cell.y + kCell / 2);
      if (row_total) {
        std::snprintf(text, sizeof text, "%.1f%%", 100.0 * share);
        centred_text(image, text, centre - cv::Point(0, 9), 0.45, ink, p == t ? 2 : 1);
      }
      std::snprintf(text, sizeof text, "%llu", static_cast<unsigned long long>(count));
      centred_text(image, text, centre + cv::Point(0, 13), 0.35, ink);
    }
  }
  return image;
}

void save_confusion_matrix_png(const std::filesystem::path& path, const ConfusionMatrix& matrix,
                               const std::vector<std::string>& names, const std::string& title) {
  plot::save_png(path, render_confusion_matrix(matrix, names, title));
}

}  // namespace facadeslam::semantics
