#include "calib/calibration_report.hpp"

#include <cmath>
#include <cstdio>
#include <random>
#include <type_traits>

#include "core/camera/camera_yaml.hpp"
#include "core/util/error.hpp"

namespace facadeslam::calib {
namespace {

// Below these the report adds a note: corners must reach the borders for
// the distortion there to be measured rather than extrapolated.
constexpr double kLowCellCoverage = 0.5;
constexpr double kLowHullCoverage = 0.4;

std::string printf_string(const char* pattern, auto... values) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

std::string filename(const std::filesystem::path& path) { return path.filename().string(); }

std::string options_text(const CalibrationRun& run) {
  std::string text;
  if (run.request.fit.fix_aspect) text += ", fixed aspect ratio fx = fy";
  if (run.request.fit.fix_k3 && run.request.model == ModelKind::pinhole) text += ", k3 fixed at 0";
  return text;
}

}  // namespace

std::string format_report(const CalibrationRun& run) {
  const CalibrationRequest& q = run.request;
  const ViewCollection& v = run.views;
  const CalibrationResult& r = run.result;
  std::string out;
  out += printf_string("calibration of %s: %zu of %zu images used, board %s, square %g m, model %s%s\n",
                       q.images.string().c_str(), v.views.size(), v.image_count, q.board.size_text().c_str(),
                       q.board.square, model_kind_name(q.model).c_str(), options_text(run).c_str());
  if (!v.rejected.empty()) {
    out += printf_string("  rejected %zu image%s:\n", v.rejected.size(), v.rejected.size() == 1 ? "" : "s");
    for (const RejectedImage& rejected : v.rejected)
      out += printf_string("    %-24s %s\n", filename(rejected.file).c_str(), rejected.reason.c_str());
  }
  out += printf_string("  %-24s %10s %12s\n", "image", "RMS [px]", "edges [px]");
  for (std::size_t i = 0; i < v.views.size(); ++i)
    out += printf_string("  %-24s %10.3f %12.2f%s\n", filename(v.views[i].file).c_str(), r.view_rms_px[i],
                         v.views[i].edge_width_px, v.views[i].sector_based ? "  (sector-based detector)" : "");
  out += printf_string("  %-24s %d x %d\n", "image size", r.camera.width(), r.camera.height());
  out += printf_string("  %-24s %.3f  %.3f\n", "fx fy [px]", r.camera.fx(), r.camera.fy());
  out += printf_string("  %-24s %.3f  %.3f\n", "cx cy [px]", r.camera.cx(), r.camera.cy());
  r.camera.visit([&](const auto& m) {
    if constexpr (std::is_same_v<std::decay_t<decltype(m)>, PinholeRadTan>)
      out += printf_string("  %-24s %.6f  %.6f  %.6f  %.6f  %.6f\n", "k1 k2 p1 p2 k3", m.k1, m.k2, m.p1, m.p2, m.k3);
    else
      out += printf_string("  %-24s %.6f rad\n", "w (FOV)", m.w);
  });
  out += printf_string("  %-24s %.4f px over %zu corners\n", "RMS reprojection error", r.rms_px,
                       v.views.size() * static_cast<std::size_t>(q.board.corner_count()));
  if (run.pinhole_rms_px)
    out += printf_string("  %-24s %.4f px (the start of the ATAN fit)\n", "pinhole RMS", *run.pinhole_rms_px);
  out += printf_string("  %-24s %.0f %% of %dx%d cells, bounding box %.0f %%, hull %.0f %% of the image\n", "coverage",
                       100.0 * run.coverage.cell_fraction, kCoverageColumns, kCoverageRows,
                       100.0 * run.coverage.bounding_box_fraction, 100.0 * run.coverage.hull_fraction);
  if (run.coverage.cell_fraction < kLowCellCoverage || run.coverage.hull_fraction < kLowHullCoverage)
    out +=
        "  note: the corners cover little of the image, so the distortion towards the borders is "
        "extrapolated; add views with the board near the edges and corners\n";
  return out;
}

Json report_json(const CalibrationRun& run) {
  const CalibrationRequest& q = run.request;
  const ViewCollection& v = run.views;
  const CalibrationResult& r = run.result;
  Json report = Json::object();
  report["images"] = q.images.string();
  report["model"] = model_kind_name(q.model);
  Json board = Json::object();
  board["cols"] = q.board.cols;
  board["rows"] = q.board.rows;
  board["square_m"] = q.board.square;
  report["board"] = board;
  report["fix_aspect"] = q.fit.fix_aspect;
  report["fix_k3"] = q.fit.fix_k3;
  report["width"] = r.camera.width();
  report["height"] = r.camera.height();
  report["image_count"] = v.image_count;
  report["used_count"] = v.views.size();
  report["rms_px"] = r.rms_px;
  if (run.pinhole_rms_px) report["pinhole_rms_px"] = *run.pinhole_rms_px;

  Json camera = Json::object();
  camera["fx"] = r.camera.fx();
  camera["fy"] = r.camera.fy();
  camera["cx"] = r.camera.cx();
  camera["cy"] = r.camera.cy();
  r.camera.visit([&](const auto& m) {
    if constexpr (std::is_same_v<std::decay_t<decltype(m)>, PinholeRadTan>)
      camera["distortion"] = Json::array({m.k1, m.k2, m.p1, m.p2, m.k3});
    else
      camera["w"] = m.w;
  });
  report["camera"] = camera;

  Json coverage = Json::object();
  coverage["grid_cols"] = kCoverageColumns;
  coverage["grid_rows"] = kCoverageRows;
  coverage["cell_fraction"] = run.coverage.cell_fraction;
  coverage["bounding_box_fraction"] = run.coverage.bounding_box_fraction;
  coverage["hull_fraction"] = run.coverage.hull_fraction;
  report["coverage"] = coverage;

  Json views = Json::array();
  for (std::size_t i = 0; i < v.views.size(); ++i) {
    Json view = Json::object();
    view["file"] = filename(v.views[i].file);
    view["rms_px"] = r.view_rms_px[i];
    view["edge_width_px"] = v.views[i].edge_width_px;
    view["detector"] = v.views[i].sector_based ? "sector-based" : "classic";
    views.push_back(view);
  }
  report["views"] = views;
  Json rejected = Json::array();
  for (const RejectedImage& item : v.rejected) {
    Json entry = Json::object();
    entry["file"] = filename(item.file);
    entry["reason"] = item.reason;
    rejected.push_back(entry);
  }
  report["rejected"] = rejected;
  return report;
}

std::string camera_file_header(const CalibrationRun& run) {
  const CalibrationRequest& q = run.request;
  return printf_string(
      "Calibrated by `facadeslam calibrate` (model %s%s)\n"
      "from %zu of %zu images in %s, board %s inner corners, square %g m.\n"
      "RMS reprojection error %.4f px.",
      model_kind_name(q.model).c_str(), options_text(run).c_str(), run.views.views.size(), run.views.image_count,
      q.images.string().c_str(), q.board.size_text().c_str(), q.board.square, run.result.rms_px);
}

void write_camera_file(const std::filesystem::path& path, const CalibrationRun& run) {
  const std::string header = camera_file_header(run);
  // Check on a scratch copy first, so a camera nothing could load never
  // replaces an existing file.
  std::random_device random;
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("facadeslam-calib-check-" + std::to_string(random()) + ".yaml");
  try {
    save_camera(scratch, run.result.camera, header);
    load_camera(scratch);
  } catch (const Error& e) {
    std::error_code ec;
    std::filesystem::remove(scratch, ec);
    const std::string hint = run.request.model == ModelKind::pinhole && !run.request.fit.fix_k3
                                 ? "; try --fix-k3, or add views with the board near the image corners"
                                 : "; add views with the board near the image corners";
    fail_file(path, std::string("the calibrated camera is not valid over the whole image (") + e.what() + ")" + hint);
  }
  std::error_code ec;
  std::filesystem::remove(scratch, ec);
  save_camera(path, run.result.camera, header);
}

}  // namespace facadeslam::calib
