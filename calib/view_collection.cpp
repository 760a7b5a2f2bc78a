#include "calib/view_collection.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include <opencv2/imgcodecs.hpp>
#include <spdlog/spdlog.h>

#include "calib/board_detection.hpp"
#include "core/util/error.hpp"
#include "core/util/progress.hpp"

namespace facadeslam::calib {
namespace {

std::string number(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

cv::Mat read_gray(const std::filesystem::path& file) {
  try {
    return cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
  } catch (const cv::Exception&) {
    return {};  // a corrupt file: treated like any undecodable one
  }
}

// The reason a detected view is not used, or nothing when it is usable.
std::optional<std::string> quality_problem(const AcceptedView& view, const std::vector<AcceptedView>& accepted,
                                           const cv::Size& image_size, const QualityThresholds& thresholds) {
  if (std::isfinite(view.edge_width_px) && view.edge_width_px > thresholds.max_edge_width_px)
    return "blurred (board edges " + number(view.edge_width_px, 1) + " px wide, more than " +
           number(thresholds.max_edge_width_px, 1) + " px)";
  const double diagonal = std::hypot(image_size.width, image_size.height);
  const double limit = thresholds.duplicate_fraction * diagonal;
  for (const AcceptedView& other : accepted) {
    const double distance = mean_corner_distance(view.corners, other.corners);
    if (distance < limit)
      return "duplicate view of " + other.file.filename().string() + " (corners " + number(distance, 2) +
             " px apart on average, less than " + number(limit, 2) + " px)";
  }
  return std::nullopt;
}

std::string rejection_list(const std::vector<RejectedImage>& rejected) {
  std::string text;
  for (const RejectedImage& r : rejected) text += "; " + r.file.filename().string() + ": " + r.reason;
  return text;
}

}  // namespace

std::string size_text(const cv::Size& size) { return std::to_string(size.width) + "x" + std::to_string(size.height); }

ViewCollection collect_views(const std::vector<std::filesystem::path>& files, const BoardSpec& board,
                             const QualityThresholds& thresholds) {
  validate_board(board);
  ViewCollection collection;
  collection.image_count = files.size();
  std::filesystem::path first_decoded;
  std::size_t boards_found = 0;

  Progress progress("detecting boards", files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::filesystem::path& file = files[i];
    progress.update(i, file.filename().string());
    const cv::Mat gray = read_gray(file);
    if (gray.empty()) {
      collection.rejected.push_back({file, "cannot be decoded as an image"});
      spdlog::info("{}: rejected, cannot be decoded as an image", file.filename().string());
      continue;
    }
    if (first_decoded.empty()) {
      first_decoded = file;
      collection.image_size = gray.size();
    } else if (gray.size() != collection.image_size) {
      fail_file(file, "image is " + size_text(gray.size()) + " pixels, but the first image (" +
                          first_decoded.filename().string() + ") is " + size_text(collection.image_size) +
                          "; all calibration images must have the same size");
    }

    const std::optional<BoardDetection> detection = detect_board(gray, board);
    if (!detection) {
      collection.rejected.push_back({file, "no " + board.size_text() + " board found"});
      spdlog::info("{}: rejected, no {} board found", file.filename().string(), board.size_text());
      continue;
    }
    ++boards_found;
    AcceptedView view{file, detection->corners, board_edge_width(gray, board, detection->corners),
                      detection->sector_based};
    if (const auto problem = quality_problem(view, collection.views, collection.image_size, thresholds)) {
      collection.rejected.push_back({file, *problem});
      spdlog::info("{}: rejected, {}", file.filename().string(), *problem);
      continue;
    }
    spdlog::debug("{}: board found{}, edge width {:.2f} px", file.filename().string(),
                  view.sector_based ? " (sector-based detector)" : "", view.edge_width_px);
    collection.views.push_back(std::move(view));
  }
  progress.finish();

  if (first_decoded.empty())
    throw Error("none of the " + std::to_string(files.size()) + " image files could be decoded" +
                rejection_list(collection.rejected));
  if (boards_found == 0) {
    throw Error("no image of " + std::to_string(files.size()) + " contained a " + board.size_text() +
                " board (inner corners; check --board, e.g. a board of 10 x 7 squares is 9x6)");
  }
  if (collection.views.size() < kMinimumViews) {
    throw Error("only " + std::to_string(collection.views.size()) + " of " + std::to_string(files.size()) +
                " images are usable, at least " + std::to_string(kMinimumViews) +
                " are needed (10-20 varied views are recommended)" + rejection_list(collection.rejected));
  }
  return collection;
}

}  // namespace facadeslam::calib
