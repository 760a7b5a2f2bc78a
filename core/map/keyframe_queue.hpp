#pragma once
// The hand-off from the tracker to the map maker: a small blocking queue.
// The tracker pushes and never waits; the map maker waits on a condition
// variable (never a sleep) until a candidate arrives or the queue is closed.
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

#include "core/map/keyframe_candidate.hpp"

namespace facadeslam {

class KeyFrameQueue {
 public:
  void push(KeyFrameCandidate candidate) {
    {
      std::lock_guard lock(mutex_);
      queue_.push_back(std::move(candidate));
    }
    changed_.notify_all();
  }

  // Blocks until a candidate is there (returns it) or the queue is closed
  // and empty (returns nothing).
  std::optional<KeyFrameCandidate> wait_pop() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !queue_.empty() || closed_; });
    return pop_locked();
  }

  std::optional<KeyFrameCandidate> try_pop() {
    std::lock_guard lock(mutex_);
    return pop_locked();
  }

  // Waits until a candidate is there, the queue is closed, or `wake` returns
  // true (checked whenever notify() is called): the map maker's idle wait,
  // woken for global bundle adjustment requests too.
  template <class Predicate>
  void wait_until(Predicate wake) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !queue_.empty() || closed_ || wake(); });
  }

  // Call after changing what a wait_until predicate reads. Taking the lock
  // first orders the change before the waiter's next predicate check, so the
  // wake-up cannot be lost between that check and the wait.
  void notify() {
    { std::lock_guard lock(mutex_); }
    changed_.notify_all();
  }

  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return queue_.size();
  }

  bool empty() const { return size() == 0; }

  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    changed_.notify_all();
  }

  bool closed() const {
    std::lock_guard lock(mutex_);
    return closed_;
  }

 private:
  std::optional<KeyFrameCandidate> pop_locked() {
    if (queue_.empty()) return std::nullopt;
    KeyFrameCandidate c = std::move(queue_.front());
    queue_.pop_front();
    return c;
  }

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<KeyFrameCandidate> queue_;
  bool closed_ = false;
};

}  // namespace facadeslam
