#include "calib/calibrate.hpp"

#include <spdlog/spdlog.h>

#include "calib/atan_calibration.hpp"
#include "calib/image_files.hpp"
#include "calib/pinhole_calibration.hpp"

namespace facadeslam::calib {

CalibrationRun run_calibration(const CalibrationRequest& request) {
  validate_board(request.board);
  const auto files = list_image_files(request.images);
  spdlog::info("{} image files in {}", files.size(), request.images.string());
  ViewCollection views = collect_views(files, request.board, request.quality);
  spdlog::info("board found and usable in {} of {} images", views.views.size(), views.image_count);

  CalibrationResult pinhole = calibrate_pinhole(views.views, views.image_size, request.board, request.fit);
  std::optional<double> pinhole_rms;
  CalibrationResult result = [&] {
    if (request.model == ModelKind::pinhole) return std::move(pinhole);
    pinhole_rms = pinhole.rms_px;
    spdlog::info("pinhole start: RMS {:.3f} px; fitting the ATAN model", pinhole.rms_px);
    return calibrate_atan(views.views, pinhole, request.board, request.fit);
  }();
  CoverageFigures coverage = compute_coverage(views.views, views.image_size);
  return CalibrationRun{request, std::move(views), std::move(result), std::move(coverage), pinhole_rms};
}

}  // namespace facadeslam::calib
