#include "core/plot/line_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "core/plot/png_file.hpp"
#include "core/plot/ticks.hpp"
#include "core/util/error.hpp"

namespace facadeslam::plot {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTitleScale = 0.8, kLabelScale = 0.6, kTickScale = 0.5;
constexpr int kTitleThickness = 2;
const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0), kGrid(225, 225, 225), kLegendBorder(160, 160, 160);
constexpr int kTickLength = 5;
constexpr int kTickSpacing = 110;
constexpr int kPad = 10;
constexpr int kLegendRow = 24, kLegendSample = 34;
// Sub-pixel drawing: OpenCV takes coordinates in 1/2^shift pixels.
constexpr int kShift = 4;
constexpr double kSubpixel = 1 << kShift;

cv::Size text_size(const std::string& text, double scale, int thickness = 1) {
  int baseline = 0;
  cv::Size size = cv::getTextSize(text, kFont, scale, thickness, &baseline);
  size.height += baseline;
  return size;
}

// Text with its top-left corner at `top_left` (putText takes the baseline).
void put_text(cv::Mat& image, const std::string& text, cv::Point top_left, double scale, int thickness = 1) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kFont, scale, thickness, &baseline);
  cv::putText(image, text, top_left + cv::Point(0, size.height), kFont, scale, kBlack, thickness, cv::LINE_AA);
}

// Text turned 90° counter-clockwise (for the y label), centred at `centre`.
void put_vertical_text(cv::Mat& image, const std::string& text, cv::Point centre, double scale) {
  const cv::Size size = text_size(text, scale);
  cv::Mat horizontal(size.height + 2, size.width + 2, CV_8UC3, kWhite);
  put_text(horizontal, text, {1, 1}, scale);
  cv::Mat vertical;
  cv::rotate(horizontal, vertical, cv::ROTATE_90_COUNTERCLOCKWISE);
  cv::Rect target(centre.x - vertical.cols / 2, centre.y - vertical.rows / 2, vertical.cols, vertical.rows);
  const cv::Rect visible = target & cv::Rect(0, 0, image.cols, image.rows);
  if (visible.empty()) return;
  vertical(cv::Rect(visible.tl() - target.tl(), visible.size())).copyTo(image(visible));
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void include(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
  double span() const { return hi - lo; }
};

// The multiples of `step` inside `range` (equal axes keep their own range
// rather than extending it to the outer ticks).
std::vector<double> multiples_inside(double step, const Range& range) {
  std::vector<double> values;
  const double first = std::ceil(range.lo / step - 1e-9), last = std::floor(range.hi / step + 1e-9);
  for (double k = first; k <= last + 0.5; k += 1.0) values.push_back(k * step);
  return values;
}

// Data units -> image pixels (continuous; pixel centres at integers).
struct Mapping {
  Range x, y;
  cv::Rect area;
  double px(double v) const { return area.x + (v - x.lo) / x.span() * (area.width - 1); }
  double py(double v) const { return area.y + (y.hi - v) / y.span() * (area.height - 1); }
};

// Calls `visit` with pixel positions along a series' polyline, every few
// pixels, so that long segments count as much as dense points.
template <typename Visit>
void for_each_drawn_point(const std::vector<double>& xs, const std::vector<double>& ys, const Mapping& map,
                          Visit&& visit) {
  bool have_previous = false;
  cv::Point2d previous;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (!std::isfinite(xs[i]) || !std::isfinite(ys[i])) {
      have_previous = false;
      continue;
    }
    const cv::Point2d p(map.px(xs[i]), map.py(ys[i]));
    if (have_previous) {
      const int steps = static_cast<int>(std::ceil(cv::norm(p - previous) / 4.0));
      for (int k = 1; k < steps; ++k) visit(previous + (p - previous) * (static_cast<double>(k) / steps));
    }
    visit(p);
    previous = p;
    have_previous = true;
  }
}

}  // namespace

struct LinePlot::Arrangement {
  Layout layout;
  Range x, y;  // data units shown across the plot area
  std::vector<double> x_ticks, y_ticks;
  double x_step = 1.0, y_step = 1.0;
};

cv::Scalar series_colour(std::size_t index) {
  // A colour-blind-friendly qualitative palette (Tableau 10), in BGR.
  static const std::array<cv::Scalar, 10> palette{{
      {180, 119, 31},
      {14, 127, 255},
      {44, 160, 44},
      {40, 39, 214},
      {189, 103, 148},
      {75, 86, 140},
      {194, 119, 227},
      {127, 127, 127},
      {34, 189, 188},
      {207, 190, 23},
  }};
  return palette[index % palette.size()];
}

LinePlot::LinePlot(int width, int height) : width_(width), height_(height) {
  if (width < 300 || height < 200)
    throw Error("plot size must be at least 300 x 200 pixels, got " + std::to_string(width) + " x " +
                std::to_string(height));
}

namespace {

std::pair<double, double> checked_range(const char* axis, double lo, double hi) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi)) {
    std::string message = "plot ";
    message.append(axis).append(" range: expected finite lo < hi, got ");
    message.append(std::to_string(lo)).append(" and ").append(std::to_string(hi));
    throw Error(message);
  }
  return {lo, hi};
}

}  // namespace

void LinePlot::set_y_range(double lo, double hi) { y_range_ = checked_range("y", lo, hi); }
void LinePlot::set_x_range(double lo, double hi) { x_range_ = checked_range("x", lo, hi); }

void LinePlot::add_series(std::string name, std::vector<double> x, std::vector<double> y, SeriesStyle style) {
  if (x.size() != y.size())
    throw Error("plot series '" + name + "': " + std::to_string(x.size()) + " x values but " +
                std::to_string(y.size()) + " y values (expected one of each per point)");
  const cv::Scalar colour = style.colour.value_or(series_colour(series_.size()));
  series_.push_back({std::move(name), std::move(x), std::move(y), style, colour});
}

void LinePlot::add_indexed_series(std::string name, std::vector<double> y, SeriesStyle style) {
  std::vector<double> x(y.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i);
  add_series(std::move(name), std::move(x), std::move(y), style);
}

LinePlot::Arrangement LinePlot::arrange() const {
  Range data_x, data_y;
  for (const auto& s : series_)
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
        data_x.include(s.x[i]);
        data_y.include(s.y[i]);
      }
  if (data_x.empty()) data_x = {0.0, 1.0};
  if (data_y.empty()) data_y = {0.0, 1.0};
  if (y_range_) data_y = {y_range_->first, y_range_->second};
  if (x_range_) data_x = {x_range_->first, x_range_->second};
  // A little air so that no line runs along the axes box.
  const auto padded = [](Range r) {
    const double pad = 0.03 * r.span();
    return Range{r.lo - pad, r.hi + pad};
  };
  data_x = padded(data_x);
  data_y = padded(data_y);

  const int title_height = title_.empty() ? kPad : text_size(title_, kTitleScale, kTitleThickness).height + 2 * kPad;
  const int tick_label_height = text_size("0", kTickScale).height;
  const int x_label_height = x_label_.empty() ? 0 : text_size(x_label_, kLabelScale).height + kPad;
  const int y_label_width = y_label_.empty() ? 0 : text_size(y_label_, kLabelScale).height + kPad;
  const int bottom = kTickLength + 4 + tick_label_height + x_label_height + kPad;
  const int right = 3 * kPad;

  // Two passes: the left margin depends on the widest y tick label, and with
  // equal axes the y ticks depend on the size of the plot area.
  Arrangement a;
  int left = 100;
  for (int pass = 0; pass < 2; ++pass) {
    a.layout.plot_area = cv::Rect(left, title_height, width_ - left - right, height_ - title_height - bottom);
    const auto& area = a.layout.plot_area;
    // About one tick per kTickSpacing pixels, so larger plots get more.
    const int x_count = std::max(4, area.width / kTickSpacing), y_count = std::max(4, area.height / kTickSpacing);
    const AxisTicks tx = nice_ticks(data_x.lo, data_x.hi, x_count);
    const AxisTicks ty = nice_ticks(data_y.lo, data_y.hi, y_count);
    a.x_step = tx.step;
    a.y_step = ty.step;
    if (equal_axes_) {
      // Same data units per pixel on both axes, ranges centred on the data
      // (a single point gets one unit across the width).
      const double width_px = area.width - 1, height_px = area.height - 1;
      double units_per_pixel = std::max(data_x.span() / width_px, data_y.span() / height_px);
      if (!(units_per_pixel > 0.0)) units_per_pixel = 1.0 / width_px;
      const auto centred = [](const Range& r, double span) {
        const double mid = 0.5 * (r.lo + r.hi);
        return Range{mid - 0.5 * span, mid + 0.5 * span};
      };
      a.x = centred(data_x, units_per_pixel * width_px);
      a.y = centred(data_y, units_per_pixel * height_px);
      // One step for both axes so that the grid is made of squares.
      const double step = std::min(nice_ticks(a.x.lo, a.x.hi, x_count).step, nice_ticks(a.y.lo, a.y.hi, y_count).step);
      a.x_step = a.y_step = step;
      a.x_ticks = multiples_inside(step, a.x);
      a.y_ticks = multiples_inside(step, a.y);
    } else {
      a.x = {tx.lo, tx.hi};
      a.y = {ty.lo, ty.hi};
      a.x_ticks = tx.values;
      a.y_ticks = ty.values;
      // A given range is kept, not widened to the outer ticks.
      if (y_range_) {
        a.y = data_y;
        a.y_ticks = multiples_inside(ty.step, data_y);
      }
      if (x_range_) {
        a.x = data_x;
        a.x_ticks = multiples_inside(tx.step, data_x);
      }
    }
    int widest = 0;
    for (const double v : a.y_ticks) widest = std::max(widest, text_size(format_tick(v, a.y_step), kTickScale).width);
    left = kPad + y_label_width + widest + kTickLength + 6;
  }

  // Legend: in the corner of the plot area that hides the least of the data
  // (top-right when that is free).
  int rows = 0, widest_name = 0;
  for (const auto& s : series_)
    if (!s.name.empty()) {
      ++rows;
      widest_name = std::max(widest_name, text_size(s.name, kLabelScale).width);
    }
  if (rows > 0) {
    const cv::Size size(kPad + kLegendSample + 8 + widest_name + kPad, rows * kLegendRow + kPad);
    const auto& area = a.layout.plot_area;
    const int left_x = area.x + kPad, right_x = area.x + area.width - size.width - kPad;
    const int top_y = area.y + kPad, bottom_y = area.y + area.height - size.height - kPad;
    const std::array<cv::Rect, 4> corners{{{cv::Point(right_x, top_y), size},
                                           {cv::Point(left_x, top_y), size},
                                           {cv::Point(right_x, bottom_y), size},
                                           {cv::Point(left_x, bottom_y), size}}};
    std::array<int, 4> hidden{};
    const Mapping map{a.x, a.y, area};
    for (const auto& s : series_)
      for_each_drawn_point(s.x, s.y, map, [&](cv::Point2d p) {
        for (std::size_t c = 0; c < corners.size(); ++c)
          if (corners[c].contains(cv::Point(static_cast<int>(p.x), static_cast<int>(p.y)))) ++hidden[c];
      });
    const auto best = std::min_element(hidden.begin(), hidden.end()) - hidden.begin();
    a.layout.legend = corners[static_cast<std::size_t>(best)];
  }
  return a;
}

LinePlot::Layout LinePlot::layout() const { return arrange().layout; }

cv::Mat LinePlot::render() const {
  const Arrangement a = arrange();
  const cv::Rect& area = a.layout.plot_area;
  cv::Mat image(height_, width_, CV_8UC3, kWhite);

  // Data -> pixel, as fixed-point for sub-pixel anti-aliased drawing.
  const Mapping map{a.x, a.y, area};
  const auto px = [&](double x) { return map.px(x); };
  const auto py = [&](double y) { return map.py(y); };
  const auto fixed = [](double x, double y) {
    return cv::Point(static_cast<int>(std::lround(x * kSubpixel)), static_cast<int>(std::lround(y * kSubpixel)));
  };

  // Grid, ticks and tick labels.
  for (const double v : a.x_ticks) {
    const int x = static_cast<int>(std::lround(px(v)));
    cv::line(image, {x, area.y}, {x, area.y + area.height - 1}, kGrid, 1);
    cv::line(image, {x, area.y + area.height}, {x, area.y + area.height + kTickLength}, kBlack, 1);
    const std::string label = format_tick(v, a.x_step);
    const cv::Size size = text_size(label, kTickScale);
    put_text(image, label, {x - size.width / 2, area.y + area.height + kTickLength + 4}, kTickScale);
  }
  for (const double v : a.y_ticks) {
    const int y = static_cast<int>(std::lround(py(v)));
    cv::line(image, {area.x, y}, {area.x + area.width - 1, y}, kGrid, 1);
    cv::line(image, {area.x - kTickLength - 1, y}, {area.x - 1, y}, kBlack, 1);
    const std::string label = format_tick(v, a.y_step);
    const cv::Size size = text_size(label, kTickScale);
    put_text(image, label, {area.x - kTickLength - 4 - size.width, y - size.height / 2}, kTickScale);
  }

  // Series, clipped to the plot area by drawing into its view.
  cv::Mat canvas = image(area);
  const cv::Point origin = fixed(area.x, area.y);
  for (const auto& s : series_) {
    std::vector<cv::Point> run;  // consecutive finite points
    const auto flush = [&] {
      if (s.style.line && run.size() >= 2)
        cv::polylines(canvas, run, false, s.colour, s.style.thickness, cv::LINE_AA, kShift);
      run.clear();
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        flush();
        continue;
      }
      const cv::Point p = fixed(px(s.x[i]), py(s.y[i])) - origin;
      run.push_back(p);
      if (s.style.markers)
        cv::circle(canvas, p, static_cast<int>(3.5 * kSubpixel), s.colour, cv::FILLED, cv::LINE_AA, kShift);
    }
    flush();
  }
  cv::rectangle(image, area, kBlack, 1);

  // Legend.
  if (!a.layout.legend.empty()) {
    const cv::Rect& box = a.layout.legend;
    cv::rectangle(image, box, kWhite, cv::FILLED);
    cv::rectangle(image, box, kLegendBorder, 1);
    int row = 0;
    for (const auto& s : series_) {
      if (s.name.empty()) continue;
      const int mid_y = box.y + kPad / 2 + row * kLegendRow + kLegendRow / 2;
      const cv::Point a0(box.x + kPad, mid_y), a1(box.x + kPad + kLegendSample, mid_y);
      if (s.style.line || !s.style.markers)
        cv::line(image, a0, a1, s.colour, std::max(3, s.style.thickness), cv::LINE_AA);
      if (s.style.markers) cv::circle(image, (a0 + a1) / 2, 4, s.colour, cv::FILLED, cv::LINE_AA);
      const cv::Size size = text_size(s.name, kLabelScale);
      put_text(image, s.name, {a1.x + 8, mid_y - size.height / 2}, kLabelScale);
      ++row;
    }
  }

  // Title and axis labels.
  if (!title_.empty()) {
    const cv::Size size = text_size(title_, kTitleScale, kTitleThickness);
    put_text(image, title_, {area.x + area.width / 2 - size.width / 2, kPad}, kTitleScale, kTitleThickness);
  }
  if (!x_label_.empty()) {
    const cv::Size size = text_size(x_label_, kLabelScale);
    const int top = area.y + area.height + kTickLength + 4 + text_size("0", kTickScale).height + kPad;
    put_text(image, x_label_, {area.x + area.width / 2 - size.width / 2, top}, kLabelScale);
  }
  if (!y_label_.empty()) {
    const int half = text_size(y_label_, kLabelScale).height / 2;
    put_vertical_text(image, y_label_, {kPad + half, area.y + area.height / 2}, kLabelScale);
  }
  return image;
}

void LinePlot::save_png(const std::filesystem::path& path) const { plot::save_png(path, render()); }

}  // namespace facadeslam::plot
