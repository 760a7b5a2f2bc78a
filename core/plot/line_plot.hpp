#pragma once
// A small line plot rendered with OpenCV's drawing functions and saved as
// PNG: title, axis labels, ticks at nice values, several named series in
// distinct colours with a legend, optional equal axis scale (for top views
// of trajectories) and optional point markers. Meant for reports: fitness
// curves, invariance curves, trajectories.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::plot {

struct SeriesStyle {
  bool line = true;                  // join the points
  bool markers = false;              // draw a dot at each point
  std::optional<cv::Scalar> colour;  // BGR; default: the palette colour of the series index
  int thickness = 2;                 // line thickness in pixels
};

// The palette colour (BGR) of the series with this index; ten distinct
// colours, then repeating.
cv::Scalar series_colour(std::size_t index);

class LinePlot {
 public:
  // Image size in pixels; at least 300 x 200 (throws Error otherwise).
  explicit LinePlot(int width = 1000, int height = 800);

  void set_title(std::string title) { title_ = std::move(title); }
  void set_x_label(std::string label) { x_label_ = std::move(label); }
  void set_y_label(std::string label) { y_label_ = std::move(label); }
  // One data unit is as long on both axes (a top view is not distorted).
  void set_equal_axes(bool equal) { equal_axes_ = equal; }
  // The y axis shows [lo, hi] (plus the usual bit of air) whatever the data,
  // ticks at nice values inside; points outside are clipped. For curves of
  // one quantity (a rate in 0..1) shown side by side. Not with equal axes.
  // Throws Error unless lo < hi, both finite.
  void set_y_range(double lo, double hi);
  // The same for the x axis (a curve over a run's frames from 0).
  void set_x_range(double lo, double hi);

  // A series of points (x[i], y[i]); non-finite points are skipped and break
  // the line. Throws Error if x and y differ in length. An empty name keeps
  // the series out of the legend.
  void add_series(std::string name, std::vector<double> x, std::vector<double> y, SeriesStyle style = {});
  // y against its index 0, 1, 2, ... (e.g. a value per generation).
  void add_indexed_series(std::string name, std::vector<double> y, SeriesStyle style = {});

  // Where things are drawn, in image pixels (for callers and tests).
  struct Layout {
    cv::Rect plot_area;  // inside the axes box
    cv::Rect legend;     // in the emptiest corner; empty when no series has a name
  };
  Layout layout() const;

  // The finished picture, 8-bit BGR, width x height.
  cv::Mat render() const;

  // Renders and writes a PNG atomically. The name must end in ".png"; throws
  // Error naming the file when it cannot be written.
  void save_png(const std::filesystem::path& path) const;

 private:
  struct Series {
    std::string name;
    std::vector<double> x, y;
    SeriesStyle style;
    cv::Scalar colour;
  };
  struct Arrangement;  // layout, axis ranges and ticks, computed from the series
  Arrangement arrange() const;

  int width_, height_;
  std::string title_, x_label_, y_label_;
  bool equal_axes_ = false;
  std::optional<std::pair<double, double>> y_range_, x_range_;
  std::vector<Series> series_;
};

}  // namespace facadeslam::plot
