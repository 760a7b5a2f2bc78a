#include "core/util/blocking_queue.hpp"

#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

// The consumer loop the map maker runs: wait, pop, stop once closed and empty.
std::vector<int> consume(BlockingQueue<int>& queue) {
  std::vector<int> received;
  for (;;) {
    queue.wait_until([] { return false; });
    if (auto item = queue.try_pop()) {
      received.push_back(*item);
      continue;
    }
    if (queue.closed()) return received;
  }
}

TEST(BlockingQueue, DeliversInOrderAcrossThreads) {
  BlockingQueue<int> queue;
  std::vector<int> received;
  std::thread consumer([&] { received = consume(queue); });
  for (int i = 0; i < 100; ++i) queue.push(i);
  queue.close();
  consumer.join();
  ASSERT_EQ(received.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(received[static_cast<std::size_t>(i)], i);
}

TEST(BlockingQueue, ItemsQueuedBeforeCloseAreStillDelivered) {
  BlockingQueue<int> queue;
  queue.push(1);
  queue.push(2);
  queue.close();
  EXPECT_EQ(consume(queue), (std::vector<int>{1, 2}));
  EXPECT_FALSE(queue.try_pop().has_value());
  EXPECT_TRUE(queue.closed());
}

TEST(BlockingQueue, WaitReturnsAtOnceWhenTheWakeConditionHolds) {
  BlockingQueue<int> queue;
  bool called = false;
  queue.wait_until([&] { return called = true; });
  EXPECT_TRUE(called);
  EXPECT_TRUE(queue.empty());
}

TEST(BlockingQueue, CloseWakesAWaitingConsumer) {
  BlockingQueue<int> queue;
  std::thread waiter([&] { queue.wait_until([] { return false; }); });
  queue.close();
  waiter.join();
  EXPECT_TRUE(queue.closed());
}

// A map reset: what was queued is dropped, the consumer is stopped without
// working through it, and the queue opens again for the new map.
TEST(BlockingQueue, ClearDropsTheQueueAndReopenFollowsTheJoin) {
  BlockingQueue<int> queue;
  for (int i = 0; i < 5; ++i) queue.push(i);
  queue.clear();
  EXPECT_TRUE(queue.empty());
  EXPECT_FALSE(queue.closed());
  std::vector<int> received{-1};
  std::thread consumer([&] { received = consume(queue); });
  queue.close();
  consumer.join();
  EXPECT_TRUE(received.empty()) << "the cleared items reached the consumer";
  queue.reopen();
  queue.push(7);
  EXPECT_FALSE(queue.closed());
  EXPECT_EQ(queue.try_pop(), std::optional<int>(7));
}

// The back-pressure: a full queue refuses try_push and holds push() until
// the consumer takes an item; every item arrives, in order.
TEST(BlockingQueue, ABoundedQueueHoldsItsProducerBack) {
  BlockingQueue<int> queue(2);
  EXPECT_TRUE(queue.try_push(0));
  EXPECT_TRUE(queue.try_push(1));
  EXPECT_TRUE(queue.full());
  EXPECT_FALSE(queue.try_push(2));
  std::vector<int> received;
  std::thread consumer([&] { received = consume(queue); });
  for (int i = 2; i < 50; ++i) EXPECT_TRUE(queue.push(i));
  queue.close();
  consumer.join();
  ASSERT_EQ(received.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(received[static_cast<std::size_t>(i)], i);
}

// A producer waiting for room is woken by close (nobody will take the item:
// it is dropped) and by clear (a map reset: room again).
TEST(BlockingQueue, CloseAndClearWakeAWaitingProducer) {
  BlockingQueue<int> queue(1);
  queue.push(0);
  bool pushed = true;
  std::thread producer([&] { pushed = queue.push(1); });
  queue.close();
  producer.join();
  EXPECT_FALSE(pushed);
  queue.reopen();
  queue.push(0);
  std::thread second([&] { pushed = queue.push(2); });
  queue.clear();
  second.join();
  EXPECT_TRUE(pushed);
  EXPECT_EQ(queue.try_pop(), std::optional<int>(2));
}

}  // namespace
}  // namespace facadeslam
