#include "sequences/sequence_options.hpp"

#include <cmath>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "sequences/frame_selection.hpp"

namespace facadeslam {
namespace {

using ::testing::HasSubstr;

std::string message_of(const SequenceOptions& options) {
  try {
    validate(options);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(SequenceOptions, DefaultsAreValid) { EXPECT_NO_THROW(validate(SequenceOptions{})); }

TEST(SequenceOptions, StrideZeroIsAnError) {
  SequenceOptions options;
  options.stride = 0;
  EXPECT_THAT(message_of(options), HasSubstr("stride must be at least 1"));
}

TEST(SequenceOptions, NonPositiveOrNonFiniteFpsIsAnError) {
  for (const double fps :
       {0.0, -5.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    SequenceOptions options;
    options.fps = fps;
    EXPECT_THAT(message_of(options), HasSubstr("fps must be a positive number")) << fps;
  }
}

TEST(SequenceOptions, CorruptPolicyRoundTripsAndRejectsOthers) {
  EXPECT_EQ(corrupt_policy_from_string("stop"), CorruptPolicy::stop);
  EXPECT_EQ(corrupt_policy_from_string("skip"), CorruptPolicy::skip);
  EXPECT_EQ(to_string(CorruptPolicy::skip), "skip");
  EXPECT_EQ(to_string(CorruptPolicy::stop), "stop");
  try {
    corrupt_policy_from_string("ignore");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("'stop' or 'skip' (got 'ignore')"));
  }
}

TEST(FrameSelection, StartStrideAndLimitCount) {
  SequenceOptions options;
  EXPECT_EQ(selected_count(10, options), 10u);
  options.start = 1;
  options.stride = 3;  // 1 4 7
  EXPECT_EQ(selected_count(10, options), 3u);
  EXPECT_TRUE(passes_start_and_stride(4, options));
  EXPECT_FALSE(passes_start_and_stride(5, options));
  EXPECT_FALSE(passes_start_and_stride(0, options));
  options.limit = 2;
  EXPECT_EQ(selected_count(10, options), 2u);
  options.start = 10;
  EXPECT_EQ(selected_count(10, options), 0u);
}

}  // namespace
}  // namespace facadeslam
