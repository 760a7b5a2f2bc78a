#include "calib/residual_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/plot/line_plot.hpp"
#include "core/plot/png_file.hpp"
#include "core/util/error.hpp"

namespace facadeslam::calib {
namespace {

constexpr int kPanelWidth = 280;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kFontScale = 0.45;
constexpr int kLineHeight = 18;
const cv::Scalar kText(30, 30, 30);
const cv::Scalar kGrid(200, 200, 200);
const cv::Scalar kCoveredCell(225, 245, 225);

std::string format(const char* pattern, double value) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

void text_line(cv::Mat& image, const std::string& text, cv::Point& cursor, const cv::Scalar& colour = kText) {
  cv::putText(image, text, cursor, kFont, kFontScale, colour, 1, cv::LINE_AA);
  cursor.y += kLineHeight;
}

}  // namespace

double residual_scale(const CalibrationResult& result, const cv::Size& image_size) {
  double largest = 0.0;
  for (const auto& view : result.residuals)
    for (const Eigen::Vector2d& r : view) largest = std::max(largest, r.norm());
  const double limit = 0.1 * std::hypot(image_size.width, image_size.height);
  constexpr double kDefault = 50.0;
  if (largest * kDefault <= limit) return kDefault;
  // Largest value of the form {1, 2, 5} x 10^k with largest * scale <= limit.
  const double bound = limit / largest;
  const double decade = std::pow(10.0, std::floor(std::log10(bound)));
  for (double mantissa : {5.0, 2.0, 1.0})
    if (mantissa * decade <= bound) return mantissa * decade;
  return decade;
}

cv::Mat render_residual_plot(const ViewCollection& views, const CalibrationResult& result,
                             const CoverageFigures& coverage) {
  const cv::Size size = views.image_size;
  const int zoom = std::max(1, static_cast<int>(std::ceil(640.0 / size.width)));
  const int frame_w = size.width * zoom, frame_h = size.height * zoom;
  cv::Mat image(std::max(frame_h, 480), frame_w + kPanelWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  // Image coordinates -> canvas: pixel centres at integer coordinates, so
  // the image area [-0.5, w - 0.5] maps onto [0, w * zoom].
  const auto canvas = [zoom](double x, double y) { return cv::Point2d((x + 0.5) * zoom, (y + 0.5) * zoom); };
  constexpr int kShift = 4;  // sub-pixel drawing precision, 1/16 px
  const auto fixed = [](const cv::Point2d& p) { return cv::Point(cvRound(p.x * 16.0), cvRound(p.y * 16.0)); };

  for (int row = 0; row < kCoverageRows; ++row)
    for (int col = 0; col < kCoverageColumns; ++col) {
      const cv::Point top_left(col * frame_w / kCoverageColumns, row * frame_h / kCoverageRows);
      const cv::Point bottom_right((col + 1) * frame_w / kCoverageColumns, (row + 1) * frame_h / kCoverageRows);
      if (coverage.cell_counts[row * kCoverageColumns + col] > 0)
        cv::rectangle(image, top_left, bottom_right, kCoveredCell, cv::FILLED);
      cv::rectangle(image, top_left, bottom_right, kGrid, 1);
    }
  cv::rectangle(image, cv::Point(0, 0), cv::Point(frame_w - 1, frame_h - 1), kText, 1);

  const double scale = residual_scale(result, size);
  for (std::size_t v = 0; v < views.views.size(); ++v) {
    const cv::Scalar colour = plot::series_colour(v);
    const auto& corners = views.views[v].corners;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const cv::Point2d at = canvas(corners[k].x, corners[k].y);
      const Eigen::Vector2d& r = result.residuals[v][k];
      const cv::Point2d tip = at + cv::Point2d(r.x() * scale * zoom, r.y() * scale * zoom);
      cv::line(image, fixed(at), fixed(tip), colour, 1, cv::LINE_AA, kShift);
      cv::circle(image, fixed(at), 2 * 16, colour, cv::FILLED, cv::LINE_AA, kShift);
    }
  }

  cv::Point cursor(frame_w + 12, 24);
  text_line(image, "camera model: " + result.camera.model_name(), cursor);
  text_line(image, "image size " + size_text(size), cursor);
  text_line(image, std::to_string(views.views.size()) + " of " + std::to_string(views.image_count) + " images used",
            cursor);
  text_line(image, format("RMS reprojection error %.3f px", result.rms_px), cursor);
  text_line(image, format("residual vectors x%g", scale), cursor);
  text_line(image,
            format("covered cells %.0f %%", 100.0 * coverage.cell_fraction) +
                format(" (%.0f", double(kCoverageColumns)) + format("x%.0f grid)", double(kCoverageRows)),
            cursor);
  text_line(image, format("corner hull %.0f %% of the image", 100.0 * coverage.hull_fraction), cursor);
  cursor.y += kLineHeight / 2;
  text_line(image, "view: RMS px", cursor);
  const int last_line = image.rows - kLineHeight;
  for (std::size_t v = 0; v < views.views.size(); ++v) {
    if (cursor.y > last_line - kLineHeight && v + 1 < views.views.size()) {
      text_line(image, "... " + std::to_string(views.views.size() - v) + " more", cursor);
      break;
    }
    const cv::Scalar colour = plot::series_colour(v);
    cv::rectangle(image, cursor + cv::Point(0, -10), cursor + cv::Point(10, 0), colour, cv::FILLED);
    char line[160];
    std::snprintf(line, sizeof line, "%s: %.3f", views.views[v].file.filename().string().c_str(),
                  result.view_rms_px[v]);
    cv::Point text_at = cursor + cv::Point(16, 0);
    text_line(image, line, text_at);
    cursor.y = text_at.y;
  }
  return image;
}

void save_residual_plot(const std::filesystem::path& path, const ViewCollection& views, const CalibrationResult& result,
                        const CoverageFigures& coverage) {
  if (path.extension() != ".png") fail_file(path, "the coverage plot must be a .png file");
  plot::save_png(path, render_residual_plot(views, result, coverage));
}

}  // namespace facadeslam::calib
