#pragma once
// The camera trajectory of a synthetic sequence: a chain of segments (pan,
// walk, arc, rotate, shake) starting from a pose, plus optional hand-held
// jitter over the whole run. Each segment starts where the previous one
// ended (position, heading, pitch), so segments chain freely.
//
// Motion per segment, with u = (t - segment start) / duration in [0, 1] and
// s = ease ? 3u^2 - 2u^3 (starts and stops at rest) : u:
//   pan     moves s * distance along the camera's horizontal right axis;
//   walk    moves s * speed * duration along heading + direction, plus a
//           head bob of `bob` metres at two steps per second;
//   arc     follows a circle of `radius` tangent to the heading, turning the
//           heading by s * angle (positive: left), the camera looking along
//           the tangent;
//   rotate  turns heading by s * yaw and pitch by s * pitch about the optical
//           centre (pure rotation: the position does not move at all);
//   shake   stays, with smooth random jitter of the given amplitudes
//           windowed by sin^2(pi u) so that it starts and ends at zero.
// Jitter (shake and hand-held) is a sum of three sinusoids per axis with
// seeded frequencies and phases, bounded by its amplitude, applied in the
// camera frame. The hand-held translation fades out (over half a second)
// around rotate segments, so that they stay pure rotations; its rotation
// part, a rotation about the optical centre, stays.
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "sequences/synth/scene.hpp"

namespace facadeslam::synth {

// Camera -> world for a camera at `position` looking along azimuth
// `heading` (radians, 0 = +x, positive towards +y) tilted up by `pitch` and
// rolled by `roll` about its optical axis (positive: clockwise as seen from
// behind the camera). World z is up; camera x right, y down, z forward.
Eigen::Isometry3d camera_pose(const Eigen::Vector3d& position, double heading, double pitch, double roll);

// A bounded smooth random signal in 6 axes (3 translation, 3 rotation),
// each in [-1, 1].
class SmoothJitter {
 public:
  SmoothJitter(std::uint64_t seed, std::uint64_t stream, double frequency);
  Eigen::Matrix<double, 6, 1> at(double t) const;

 private:
  struct Wave {
    double frequency, phase;
  };
  std::vector<Wave> waves_;  // 3 per axis
};

class CameraPath {
 public:
  CameraPath(const StartSpec& start, const std::vector<SegmentSpec>& segments, const JitterSpec& handheld,
             std::uint64_t seed);

  double duration() const { return duration_; }
  // Camera -> world at time t (seconds), t clamped to [0, duration()].
  Eigen::Isometry3d T_w_c(double t) const;

 private:
  struct State {
    Eigen::Vector3d position;
    double heading, pitch, roll;  // radians
  };
  State advance(const State& from, const SegmentSpec& segment, double u) const;
  // 0 inside rotate segments, rising smoothly to 1 half a second away.
  double translation_gate(double t) const;

  std::vector<SegmentSpec> segments_;
  std::vector<State> starts_;         // state at the start of each segment
  std::vector<double> begins_;        // start time of each segment
  std::vector<SmoothJitter> shakes_;  // one per segment (used by shake segments)
  JitterSpec handheld_;
  SmoothJitter handheld_jitter_;
  double duration_ = 0.0;
};

}  // namespace facadeslam::synth
