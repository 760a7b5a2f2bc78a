#include "sequences/synth/scene.hpp"

namespace facadeslam::synth {

double SceneSpec::trajectory_duration() const {
  double total = 0.0;
  for (const auto& segment : trajectory) total += segment.duration;
  return total;
}

}  // namespace facadeslam::synth
