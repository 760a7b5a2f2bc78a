#include "core/map/keyframe_queue.hpp"

#include <thread>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

TEST(KeyFrameQueue, DeliversInOrderAcrossThreads) {
  KeyFrameQueue queue;
  std::vector<std::size_t> received;
  std::thread consumer([&] {
    while (auto c = queue.wait_pop()) received.push_back(c->frame_index);
  });
  for (std::size_t i = 0; i < 100; ++i) {
    KeyFrameCandidate c;
    c.frame_index = i;
    queue.push(std::move(c));
  }
  queue.close();
  consumer.join();
  ASSERT_EQ(received.size(), 100u);
  for (std::size_t i = 0; i < received.size(); ++i) EXPECT_EQ(received[i], i);
}

TEST(KeyFrameQueue, ClosedEmptyQueueReturnsNothing) {
  KeyFrameQueue queue;
  EXPECT_FALSE(queue.try_pop().has_value());
  queue.close();
  EXPECT_FALSE(queue.wait_pop().has_value());
  EXPECT_TRUE(queue.closed());
}

TEST(KeyFrameQueue, WaitUntilWakesOnPredicate) {
  KeyFrameQueue queue;
  std::atomic<bool> flag{false};
  std::thread waiter([&] { queue.wait_until([&] { return flag.load(); }); });
  flag = true;
  queue.notify();
  waiter.join();
  EXPECT_TRUE(queue.empty());
}

}  // namespace
}  // namespace facadeslam
