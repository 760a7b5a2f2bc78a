#include "render/map_view_legend.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace facadeslam::render {
// Named, so that the unity build's other render files cannot clash with these.
namespace map_view_legend_detail {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

// Text metrics for an image of this height: a 720-row picture gets 0.6
// (about 13-pixel capitals), never below 0.4 where Hershey glyphs blur.
struct Metrics {
  double scale;
  int thickness, text_height, row, pad, swatch;
};

Metrics metrics(const cv::Size& image_size) {
  Metrics m{};
  m.scale = std::max(0.4, image_size.height / 1200.0);
  m.thickness = m.scale >= 0.9 ? 2 : 1;
  int baseline = 0;
  m.text_height = cv::getTextSize("Mg", kFont, m.scale, m.thickness, &baseline).height;
  m.row = m.text_height * 2;
  m.pad = m.text_height;
  m.swatch = m.text_height * 2;
  return m;
}

}  // namespace
}  // namespace map_view_legend_detail

cv::Rect legend_box(const cv::Size& image_size, const std::vector<LegendEntry>& entries) {
  using namespace map_view_legend_detail;
  if (entries.empty()) return {};
  const Metrics m = metrics(image_size);
  int text_width = 0;
  for (const LegendEntry& e : entries) {
    int baseline = 0;
    text_width = std::max(text_width, cv::getTextSize(e.text, kFont, m.scale, m.thickness, &baseline).width);
  }
  const int width = m.pad + m.swatch + m.pad + text_width + m.pad;
  const int height = m.pad / 2 + static_cast<int>(entries.size()) * m.row + m.pad / 2;
  return cv::Rect(m.pad, m.pad, width, height) & cv::Rect(0, 0, image_size.width, image_size.height);
}

void draw_legend(cv::Mat& image, const std::vector<LegendEntry>& entries, const cv::Scalar& background_bgr) {
  using namespace map_view_legend_detail;
  const cv::Rect box = legend_box(image.size(), entries);
  if (box.empty()) return;
  const Metrics m = metrics(image.size());
  const cv::Scalar fill = background_bgr * 0.3 + cv::Scalar::all(255 * 0.7);
  cv::rectangle(image, box, fill, cv::FILLED);
  cv::rectangle(image, box, cv::Scalar::all(150), 1);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const LegendEntry& e = entries[i];
    const int centre_y = box.y + m.pad / 2 + static_cast<int>(i) * m.row + m.row / 2;
    const int swatch_x = box.x + m.pad;
    const cv::Scalar colour(e.colour_bgr[0], e.colour_bgr[1], e.colour_bgr[2]);
    if (e.line) {
      cv::line(image, {swatch_x, centre_y}, {swatch_x + m.swatch, centre_y}, colour, std::max(2, m.thickness + 1),
               cv::LINE_AA);
    } else {
      // The dot as the map draws it: the colour inside a darker ring.
      const cv::Point centre(swatch_x + m.swatch / 2, centre_y);
      const int radius = std::max(3, m.text_height * 6 / 10);
      cv::circle(image, centre, radius, colour * 0.55, cv::FILLED, cv::LINE_AA);
      cv::circle(image, centre, radius - 1, colour, cv::FILLED, cv::LINE_AA);
    }
    cv::putText(image, e.text, {swatch_x + m.swatch + m.pad, centre_y + m.text_height / 2}, kFont, m.scale,
                cv::Scalar::all(30), m.thickness, cv::LINE_AA);
  }
}

}  // namespace facadeslam::render
