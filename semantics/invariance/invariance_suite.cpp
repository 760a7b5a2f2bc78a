#include "semantics/invariance/invariance_suite.hpp"

#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <spdlog/spdlog.h>

#include "core/util/error.hpp"
#include "core/util/progress.hpp"
#include "semantics/evaluation/grid_keypoints.hpp"
#include "semantics/invariance/keypoint_mapping.hpp"
#include "semantics/invariance/match_rate.hpp"
#include "semantics/text.hpp"
#include "core/util/stopwatch.hpp"

namespace facadeslam::semantics {
namespace {

void check_options(const std::vector<std::filesystem::path>& images, const std::vector<PointDescriptor*>& descriptors,
                   const InvarianceOptions& o) {
  if (o.step < 1) throw Error(cat("invariance: the grid step must be at least 1 pixel, got ", o.step));
  if (o.margin < 0) throw Error(cat("invariance: the margin must be >= 0 pixels, got ", o.margin));
  if (o.cases.empty()) throw Error("invariance: no case to run");
  for (std::size_t c = 0; c < o.cases.size(); ++c) {
    for (std::size_t earlier = 0; earlier < c; ++earlier)
      if (o.cases[earlier].id == o.cases[c].id)
        throw Error(cat("invariance: case ", case_info(o.cases[c].id).name, " is listed twice"));
    check_case_values(o.cases[c].id, o.cases[c].values);
  }
  if (descriptors.empty()) throw Error("invariance: no descriptor to evaluate");
  for (const PointDescriptor* d : descriptors)
    if (d == nullptr) throw Error("invariance: a descriptor is missing");
  if (images.empty()) throw Error("invariance: no image");
  // A quick look at each file's header, so that a bad file fails now rather
  // than after an hour.
  for (const auto& image : images)
    if (!cv::haveImageReader(image.string())) fail_file(image, "not an image OpenCV can read");
}

cv::Mat rows_of(const cv::Mat& all, const std::vector<int>& rows) {
  cv::Mat out(static_cast<int>(rows.size()), all.cols, all.type());
  for (std::size_t i = 0; i < rows.size(); ++i) all.row(rows[i]).copyTo(out.row(static_cast<int>(i)));
  return out;
}

InvarianceCaseResult empty_result(const InvarianceCaseRun& run, std::size_t descriptors, std::size_t images) {
  InvarianceCaseResult r;
  r.id = run.id;
  r.values = run.values;
  const std::size_t n = run.values.size();
  r.match_rate.assign(descriptors, std::vector<double>(n, std::nan("")));
  r.compared.assign(descriptors, std::vector<std::size_t>(n, 0));
  r.matched.assign(descriptors, std::vector<std::size_t>(n, 0));
  r.per_image.assign(descriptors, std::vector<std::vector<double>>(n, std::vector<double>(images, std::nan(""))));
  return r;
}

void average_over_images(InvarianceCaseResult& r) {
  for (std::size_t d = 0; d < r.per_image.size(); ++d)
    for (std::size_t v = 0; v < r.values.size(); ++v) {
      double sum = 0;
      int count = 0;
      for (const double rate : r.per_image[d][v])
        if (std::isfinite(rate)) {
          sum += rate;
          ++count;
        }
      r.match_rate[d][v] = count ? sum / count : std::nan("");
    }
}

}  // namespace

std::vector<InvarianceCaseRun> default_invariance_cases() {
  std::vector<InvarianceCaseRun> runs;
  for (const InvarianceCaseInfo& info : kInvarianceCases) runs.push_back({info.id, default_case_values(info.id)});
  return runs;
}

InvarianceResult run_invariance(const std::vector<std::filesystem::path>& images,
                                const std::vector<PointDescriptor*>& descriptors, const InvarianceOptions& options) {
  const Stopwatch start;
  check_options(images, descriptors, options);

  InvarianceResult result;
  result.images = images;
  result.step = options.step;
  result.margin = options.margin;
  for (PointDescriptor* d : descriptors) {
    result.descriptors.emplace_back(d->name());
    result.descriptor_widths.push_back(d->width());
  }
  std::size_t changes_per_image = 0;
  for (const InvarianceCaseRun& run : options.cases) {
    result.cases.push_back(empty_result(run, descriptors.size(), images.size()));
    changes_per_image += run.values.size();
  }
  spdlog::info("invariance: {} images x {} changed copies, {} descriptors", images.size(), changes_per_image,
               descriptors.size());

  Progress progress("invariance", images.size() * changes_per_image);
  std::size_t done = 0;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const cv::Mat bgr = cv::imread(images[i].string(), cv::IMREAD_COLOR);
    if (bgr.empty()) fail_file(images[i], "cannot be read as an image");
    const std::vector<cv::Point2f> grid = grid_keypoints(bgr.size(), options.step, options.margin);
    if (grid.empty())
      fail_file(images[i], cat("the image is ", bgr.cols, "x", bgr.rows, ": too small for one keypoint ",
                               options.margin, " pixels from its edges"));
    result.reference_keypoints += grid.size();
    std::vector<cv::Mat> reference;
    for (PointDescriptor* d : descriptors) reference.push_back(d->compute(bgr, grid));

    for (std::size_t c = 0; c < options.cases.size(); ++c) {
      InvarianceCaseResult& r = result.cases[c];
      for (std::size_t v = 0; v < r.values.size(); ++v) {
        const TransformedImage changed = apply_case(r.id, r.values[v], bgr);
        const KeypointPairs pairs = map_keypoints(grid, changed, options.margin);
        if (!pairs.moved.empty())
          for (std::size_t d = 0; d < descriptors.size(); ++d) {
            const cv::Mat moved = descriptors[d]->compute(changed.bgr, pairs.moved);
            const std::size_t matched = count_matched(rows_of(reference[d], pairs.reference), moved);
            r.compared[d][v] += pairs.moved.size();
            r.matched[d][v] += matched;
            r.per_image[d][v][i] = match_rate(matched, pairs.moved.size());
          }
        progress.update(++done, std::string(case_info(r.id).name));
      }
    }
  }
  progress.finish();
  for (InvarianceCaseResult& r : result.cases) average_over_images(r);
  result.seconds = start.elapsed_s();
  return result;
}

}  // namespace facadeslam::semantics
