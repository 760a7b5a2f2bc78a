#include "sequences/synth/camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/util/angles.hpp"
#include "sequences/synth/deterministic_random.hpp"

namespace facadeslam::synth {
namespace {

// Streams of the seeded generators, so that each use draws independently.
constexpr std::uint64_t kHandheldStream = 0x4A17;
constexpr std::uint64_t kShakeStream = 0x5AE0;

double smoothstep(double u) { return u * u * (3.0 - 2.0 * u); }

Eigen::Matrix3d rotation_from_vector(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

}  // namespace

Eigen::Isometry3d camera_pose(const Eigen::Vector3d& position, double heading, double pitch, double roll) {
  // Body frame: x forward, y left, z up. Camera axes in the body frame:
  // x_c = right = -y_b, y_c = down = -z_b, z_c = forward = x_b.
  Eigen::Matrix3d R_b_c;
  R_b_c << 0, 0, 1,  //
      -1, 0, 0,      //
      0, -1, 0;
  const Eigen::Matrix3d R_w_b =
      (Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-pitch, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R_w_b * R_b_c * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = position;
  return T;
}

SmoothJitter::SmoothJitter(std::uint64_t seed, std::uint64_t stream, double frequency) {
  SeededSequence random(seed, stream);
  // Three incommensurate frequencies around the nominal one per axis.
  const double multipliers[] = {0.53, 1.0, 1.87};
  for (int axis = 0; axis < 6; ++axis)
    for (double m : multipliers)
      waves_.push_back({frequency * m * random.uniform(0.8, 1.2), 2.0 * std::numbers::pi * random.uniform()});
}

Eigen::Matrix<double, 6, 1> SmoothJitter::at(double t) const {
  Eigen::Matrix<double, 6, 1> v;
  for (int axis = 0; axis < 6; ++axis) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Wave& w = waves_[axis * 3 + k];
      sum += std::sin(2.0 * std::numbers::pi * w.frequency * t + w.phase);
    }
    v(axis) = sum / 3.0;
  }
  return v;
}

CameraPath::CameraPath(const StartSpec& start, const std::vector<SegmentSpec>& segments, const JitterSpec& handheld,
                       std::uint64_t seed)
    : segments_(segments), handheld_(handheld), handheld_jitter_(seed, kHandheldStream, handheld.frequency) {
  State state{start.position, deg_to_rad(start.heading_deg), deg_to_rad(start.pitch_deg), deg_to_rad(start.roll_deg)};
  double time = 0.0;
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    starts_.push_back(state);
    begins_.push_back(time);
    shakes_.emplace_back(seed, kShakeStream + i, segments_[i].frequency);
    state = advance(state, segments_[i], 1.0);
    time += segments_[i].duration;
  }
  starts_.push_back(state);
  duration_ = time;
}

CameraPath::State CameraPath::advance(const State& from, const SegmentSpec& segment, double u) const {
  const double s = segment.ease ? smoothstep(u) : u;
  State state = from;
  switch (segment.type) {
    case SegmentType::pan: {
      const Eigen::Vector3d right(std::sin(from.heading), -std::cos(from.heading), 0.0);
      state.position += s * segment.distance * right;
      break;
    }
    case SegmentType::walk: {
      const double direction = from.heading + deg_to_rad(segment.direction_deg);
      state.position +=
          s * segment.speed * segment.duration * Eigen::Vector3d(std::cos(direction), std::sin(direction), 0.0);
      // Two steps per second, a whole number of them so the bob ends at zero.
      const double steps = std::max(1.0, std::round(2.0 * segment.duration));
      state.position.z() += segment.bob * std::sin(2.0 * std::numbers::pi * steps * u);
      break;
    }
    case SegmentType::arc: {
      const double turn = deg_to_rad(segment.angle_deg);
      const double side = turn >= 0.0 ? 1.0 : -1.0;  // centre on the left for a left turn
      const auto left = [](double heading) { return Eigen::Vector3d(-std::sin(heading), std::cos(heading), 0.0); };
      const Eigen::Vector3d centre = from.position + side * segment.radius * left(from.heading);
      state.heading = from.heading + s * turn;
      state.position = centre - side * segment.radius * left(state.heading);
      state.position.z() = from.position.z();
      break;
    }
    case SegmentType::rotate:
      state.heading = from.heading + s * deg_to_rad(segment.yaw_deg);
      state.pitch = from.pitch + s * deg_to_rad(segment.pitch_deg);
      break;
    case SegmentType::shake: break;  // the jitter is added in T_w_c()
  }
  return state;
}

double CameraPath::translation_gate(double t) const {
  constexpr double kRamp = 0.5;  // seconds
  double distance = kRamp;
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    if (segments_[i].type != SegmentType::rotate) continue;
    const double begin = begins_[i], end = begins_[i] + segments_[i].duration;
    distance = std::min(distance, t < begin ? begin - t : t > end ? t - end : 0.0);
  }
  return smoothstep(distance / kRamp);
}

Eigen::Isometry3d CameraPath::T_w_c(double t) const {
  t = std::clamp(t, 0.0, duration_);
  // The segment holding t (the last one for t == duration).
  std::size_t i = 0;
  while (i + 1 < segments_.size() && t >= begins_[i + 1]) ++i;
  const SegmentSpec& segment = segments_[i];
  const double u = std::clamp((t - begins_[i]) / segment.duration, 0.0, 1.0);
  const State state = advance(starts_[i], segment, u);
  Eigen::Isometry3d T = camera_pose(state.position, state.heading, state.pitch, state.roll);

  // Jitter in the camera frame: T_w_c <- T_w_c * (R(delta_omega), delta_t).
  Eigen::Matrix<double, 6, 1> delta = Eigen::Matrix<double, 6, 1>::Zero();
  if (segment.type == SegmentType::shake) {
    const double window = std::pow(std::sin(std::numbers::pi * u), 2);
    const auto j = shakes_[i].at(t);
    delta.head<3>() += window * segment.translation * j.head<3>();
    delta.tail<3>() += window * deg_to_rad(segment.rotation_deg) * j.tail<3>();
  }
  if (handheld_.translation > 0.0 || handheld_.rotation_deg > 0.0) {
    const auto j = handheld_jitter_.at(t);
    delta.head<3>() += handheld_.translation * translation_gate(t) * j.head<3>();
    delta.tail<3>() += deg_to_rad(handheld_.rotation_deg) * j.tail<3>();
  }
  if (!delta.isZero()) {
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
    offset.linear() = rotation_from_vector(delta.tail<3>());
    offset.translation() = delta.head<3>();
    T = T * offset;
  }
  return T;
}

}  // namespace facadeslam::synth
