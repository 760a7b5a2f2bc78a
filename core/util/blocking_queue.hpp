#pragma once
// The hand-off between threads (tracker -> map maker, and map maker ->
// semantic worker): an unbounded FIFO. Producers push and never wait; a
// consumer waits on a condition variable (never a sleep) until an item
// arrives, the queue is closed, or its own wake-up condition holds.
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

namespace facadeslam {

template <class T>
class BlockingQueue {
 public:
  void push(T item) {
    {
      std::lock_guard lock(mutex_);
      items_.push_back(std::move(item));
    }
    changed_.notify_all();
  }

  std::optional<T> try_pop() {
    std::lock_guard lock(mutex_);
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    return item;
  }

  // Waits until an item is there, the queue is closed, or `wake()` returns
  // true. `wake` is checked under the queue's lock when the wait starts and
  // at every push/close, so it may only read state that the waiting thread
  // itself changes (the map maker's "map changed since the last global BA"):
  // nothing else would wake the wait.
  template <class Predicate>
  void wait_until(Predicate wake) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !items_.empty() || closed_ || wake(); });
  }

  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return items_.size();
  }
  bool empty() const { return size() == 0; }

  // No more items will come: waiters wake; items already queued can still be
  // popped.
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

  // Drops what is queued; producers and consumers carry on (a map reset:
  // what was queued belongs to the old map, and stopping the consumer must
  // not first work through it).
  void clear() {
    std::lock_guard lock(mutex_);
    items_.clear();
  }

  // Empties the queue and opens it again. Only once the consumer thread has
  // been joined: a consumer still waiting would miss the close it was woken for.
  void reopen() {
    std::lock_guard lock(mutex_);
    items_.clear();
    closed_ = false;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<T> items_;
  bool closed_ = false;
};

}  // namespace facadeslam
