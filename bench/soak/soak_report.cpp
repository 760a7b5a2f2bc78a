// soak_report REPORT.json PLOT.png: the soak's figures from a long replay's
// report.json (its "resources" columns, one sample every 100 frames): the
// resident memory, the map's size and the per-frame time over the run, as a
// three-panel PNG, and on stdout how much each grew. Growth is measured
// after the first pass (a map is still being built then) and time as a
// ratio of the run's last tenth to its first tenth after that pass: a
// figure against a peer in the same run, not a wall-clock number.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "core/plot/line_plot.hpp"
#include "core/plot/png_file.hpp"
#include "core/util/median.hpp"

namespace {

using facadeslam::median;
using facadeslam::plot::LinePlot;

std::vector<double> column(const nlohmann::json& resources, const char* name) {
  std::vector<double> out;
  for (const auto& v : resources.at(name)) out.push_back(v.get<double>());
  return out;
}

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double d = n * sxx - sx * sx;
  return d > 0 ? (n * sxy - sx * sy) / d : 0.0;
}

cv::Mat panel(const std::string& title, const std::string& y_label, const std::vector<double>& frames,
              const std::vector<std::pair<std::string, std::vector<double>>>& series) {
  LinePlot plot(1000, 360);
  plot.set_x_range(0.0, frames.back());
  plot.set_title(title);
  plot.set_x_label("frame");
  plot.set_y_label(y_label);
  double hi = 0;
  for (const auto& [name, y] : series) {
    plot.add_series(name, frames, y);
    for (double v : y) hi = std::max(hi, v);
  }
  plot.set_y_range(0.0, std::max(1e-9, hi * 1.1));
  return plot.render();
}

int run(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: soak_report REPORT.json PLOT.png\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "%s: cannot read (expected a replay's report.json)\n", argv[1]);
    return 1;
  }
  const nlohmann::json report = nlohmann::json::parse(in);
  const nlohmann::json& resources = report.at("resources");
  const std::vector<double> frames = column(resources, "frames"), memory = column(resources, "resident_mib"),
                            keyframes = column(resources, "keyframes"), points = column(resources, "points"),
                            frame_ms = column(resources, "frame_ms_median"),
                            tracker_ms = column(resources, "tracker_ms_median");
  if (frames.size() < 20) {
    std::fprintf(stderr, "%s: %zu resource samples; a soak needs at least 20 (2000 frames)\n", argv[1], frames.size());
    return 1;
  }
  const double pass_frames = report.value("frames", 0.0) / std::max(1.0, report.value("passes", 1.0));
  // Samples after the first pass (at least the first tenth of the run).
  const auto warm = static_cast<std::size_t>(std::count_if(
      frames.begin(), frames.end(), [&](double f) { return f <= std::max(pass_frames, frames.back() / 10.0); }));
  const std::vector<double> warm_frames(frames.begin() + static_cast<std::ptrdiff_t>(warm), frames.end()),
      warm_memory(memory.begin() + static_cast<std::ptrdiff_t>(warm), memory.end());
  const std::size_t tenth = std::max<std::size_t>(1, warm_frames.size() / 10);
  const auto first_tenth = [&](const std::vector<double>& v) {
    return median(
        {v.begin() + static_cast<std::ptrdiff_t>(warm), v.begin() + static_cast<std::ptrdiff_t>(warm + tenth)});
  };
  const auto last_tenth = [&](const std::vector<double>& v) {
    return median({v.end() - static_cast<std::ptrdiff_t>(tenth), v.end()});
  };

  std::printf("soak: %.0f frames, %s, %.0f tracked, %.0f lost, %.0f relocalisations, %.0f map resets\n",
              report.value("frames", 0.0), report.value("mode", std::string("?")).c_str(),
              report.value("frames_tracked", 0.0), report.value("frames_lost", 0.0),
              report.value("relocalisations", 0.0), report.value("map_resets", 0.0));
  std::printf(
      "resident memory: %.1f MiB at frame %.0f, %.1f MiB at the end, %.1f MiB at most; "
      "%.3f MiB per 1000 frames after frame %.0f\n",
      warm_memory.front(), warm_frames.front(), memory.back(), *std::max_element(memory.begin(), memory.end()),
      1000.0 * slope(warm_frames, warm_memory), warm_frames.front());
  std::printf("map: %.0f keyframes and %.0f points at the end, at most %.0f and %.0f\n", keyframes.back(),
              points.back(), *std::max_element(keyframes.begin(), keyframes.end()),
              *std::max_element(points.begin(), points.end()));
  const std::vector<double> warm_frame_ms(frame_ms.begin() + static_cast<std::ptrdiff_t>(warm), frame_ms.end());
  std::printf("frame time: trend %+.3f ms per 1000 frames after frame %.0f (median %.2f ms)\n",
              1000.0 * slope(warm_frames, warm_frame_ms), warm_frames.front(), median(warm_frame_ms));
  std::printf(
      "frame time (median of the window medians): %.2f ms in the first tenth after frame %.0f, %.2f ms "
      "in the last tenth: ratio %.3f (tracker %.2f / %.2f ms: %.3f)\n",
      first_tenth(frame_ms), warm_frames.front(), last_tenth(frame_ms),
      last_tenth(frame_ms) / std::max(1e-9, first_tenth(frame_ms)), first_tenth(tracker_ms), last_tenth(tracker_ms),
      last_tenth(tracker_ms) / std::max(1e-9, first_tenth(tracker_ms)));

  cv::Mat figure;
  cv::vconcat(std::vector<cv::Mat>{panel("Resident memory", "MiB", frames, {{"resident memory", memory}}),
                                   panel("Map size", "count", frames,
                                         {{"keyframes x 100",
                                           [&] {
                                             std::vector<double> k = keyframes;
                                             for (double& v : k) v *= 100;
                                             return k;
                                           }()},
                                          {"points", points}}),
                                   panel("Time per frame (median of each 100 frames)", "ms", frames,
                                         {{"frame", frame_ms}, {"tracker", tracker_ms}})},
              figure);
  facadeslam::plot::save_png(argv[2], figure);
  std::printf("plot: %s\n", argv[2]);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "soak_report: %s\n", e.what());
    return 1;
  }
}
