#include "calib/pinhole_calibration.hpp"

#include <cmath>
#include <string>

#include <Eigen/Core>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "core/util/error.hpp"

namespace facadeslam::calib {
namespace {

SE3d pose_from_opencv(const cv::Mat& rvec, const cv::Mat& tvec) {
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  Eigen::Matrix3d r;
  Eigen::Vector3d t;
  cv::cv2eigen(rotation, r);
  cv::cv2eigen(tvec.reshape(1, 3), t);
  return SE3d(r, t);
}

}  // namespace

CalibrationResult calibrate_pinhole(const std::vector<AcceptedView>& views, const cv::Size& image_size,
                                    const BoardSpec& board, const FitOptions& options) {
  if (views.size() < kMinimumViews)
    throw Error("pinhole calibration needs at least " + std::to_string(kMinimumViews) + " views, got " +
                std::to_string(views.size()));
  const std::vector<cv::Point3f> object = board_object_points(board);
  std::vector<std::vector<cv::Point3f>> object_points(views.size(), object);
  std::vector<std::vector<cv::Point2f>> image_points;
  for (const AcceptedView& view : views) image_points.push_back(view.corners);

  int flags = 0;
  if (options.fix_aspect) flags |= cv::CALIB_FIX_ASPECT_RATIO;  // ratio taken from K below: 1
  if (options.fix_k3) flags |= cv::CALIB_FIX_K3;
  cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
  cv::Mat distortion = cv::Mat::zeros(1, 5, CV_64F);
  std::vector<cv::Mat> rvecs, tvecs;
  try {
    cv::calibrateCamera(object_points, image_points, image_size, K, distortion, rvecs, tvecs, flags,
                        cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-12));
  } catch (const cv::Exception& e) {
    throw Error(std::string("OpenCV calibration failed: ") + e.what());
  }
  K.convertTo(K, CV_64F);
  distortion.convertTo(distortion, CV_64F);
  const cv::Mat d = distortion.reshape(1, 1);
  PinholeRadTan model;
  model.fx = K.at<double>(0, 0);
  model.fy = K.at<double>(1, 1);
  model.cx = K.at<double>(0, 2);
  model.cy = K.at<double>(1, 2);
  model.k1 = d.at<double>(0);
  model.k2 = d.at<double>(1);
  model.p1 = d.at<double>(2);
  model.p2 = d.at<double>(3);
  model.k3 = d.cols > 4 ? d.at<double>(4) : 0.0;
  for (double v : {model.fx, model.fy, model.cx, model.cy, model.k1, model.k2, model.p1, model.p2, model.k3})
    if (!std::isfinite(v)) throw Error("OpenCV calibration returned non-finite parameters (degenerate views?)");
  if (model.fx <= 0.0 || model.fy <= 0.0)
    throw Error("OpenCV calibration returned a focal length <= 0 (degenerate views?)");

  std::vector<SE3d> poses;
  for (std::size_t i = 0; i < views.size(); ++i) poses.push_back(pose_from_opencv(rvecs[i], tvecs[i]));
  return evaluate_calibration(Camera(image_size.width, image_size.height, model), std::move(poses), views, board);
}

}  // namespace facadeslam::calib
