// Which keyframes are redundant: most of their points measured by enough
// other keyframes at a comparable scale; the kept ones never go; one chosen
// no longer vouches for the others.
#include "mapmaker/keyframe_culling.hpp"

#include <algorithm>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

// `count` points (ids from `first`) at `level`.
MeasuredLevels points(std::uint64_t first, std::uint64_t count, int level = 0) {
  MeasuredLevels out;
  for (std::uint64_t id = first; id < first + count; ++id) out.emplace(id, level);
  return out;
}

// The rule with round numbers: 90 % of the points, 3 other keyframes.
KeyFrameCullingOptions three_others() {
  KeyFrameCullingOptions options;
  options.redundant_share = 0.9;
  options.min_other_keyframes = 3;
  return options;
}

TEST(KeyFrameCulling, AKeyframeWhosePointsThreeOthersMeasureGoes) {
  // Keyframes 1-4 all measure points 0-99; keyframe 0 (the gauge) too.
  std::map<std::uint64_t, MeasuredLevels> keyframes;
  for (std::uint64_t kf = 0; kf < 5; ++kf) keyframes[kf] = points(0, 100);
  // With 0 and 4 kept, 1 goes first (4 others measure everything), then 2
  // (0, 3, 4 remain), then 3 has only 0 and 4: it stays.
  EXPECT_EQ(redundant_keyframes(keyframes, {0, 4}, three_others()), (std::vector<std::uint64_t>{1, 2}));
  // The default asks for 4 others: only 1 goes.
  EXPECT_EQ(redundant_keyframes(keyframes, {0, 4}, {}), (std::vector<std::uint64_t>{1}));
}

TEST(KeyFrameCulling, OwnPointsKeepAKeyframe) {
  std::map<std::uint64_t, MeasuredLevels> keyframes;
  for (std::uint64_t kf = 0; kf < 5; ++kf) keyframes[kf] = points(0, 100);
  // Keyframe 2 also measures 12 points nobody else does: 100 of 112 = 89 %
  // redundant, under 90 %: it stays, and vouches for 3.
  for (std::uint64_t id = 1000; id < 1012; ++id) keyframes[2].emplace(id, 0);
  EXPECT_EQ(redundant_keyframes(keyframes, {0, 4}, three_others()), (std::vector<std::uint64_t>{1, 3}));
  KeyFrameCullingOptions lenient = three_others();
  lenient.redundant_share = 0.85;
  EXPECT_EQ(redundant_keyframes(keyframes, {0, 4}, lenient), (std::vector<std::uint64_t>{1, 2}));
}

TEST(KeyFrameCulling, OnlyMeasurementsAtAComparableScaleCount) {
  // Keyframe 1 sees the points at level 0; the others only at level 2 (from
  // far away): they do not show its detail, it stays. Seen at level 1 they do.
  std::map<std::uint64_t, MeasuredLevels> keyframes;
  keyframes[1] = points(0, 50, 0);
  for (std::uint64_t kf : {0, 2, 3, 4}) keyframes[kf] = points(0, 50, 2);
  EXPECT_TRUE(redundant_keyframes(keyframes, {0, 2, 3, 4}, three_others()).empty());
  for (std::uint64_t kf : {0, 2, 3, 4}) keyframes[kf] = points(0, 50, 1);
  EXPECT_EQ(redundant_keyframes(keyframes, {0, 2, 3, 4}, three_others()), (std::vector<std::uint64_t>{1}));
}

TEST(KeyFrameCulling, DisabledOrEmptyChoosesNothing) {
  std::map<std::uint64_t, MeasuredLevels> keyframes;
  for (std::uint64_t kf = 0; kf < 5; ++kf) keyframes[kf] = points(0, 100);
  keyframes[7] = {};
  KeyFrameCullingOptions off;
  off.enabled = false;
  EXPECT_TRUE(redundant_keyframes(keyframes, {0}, off).empty());
  const auto chosen = redundant_keyframes(keyframes, {0}, three_others());
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), 7u), 0) << "a keyframe measuring nothing proves nothing";
}

}  // namespace
}  // namespace facadeslam
