#pragma once
// The hand-off between threads (tracker -> map maker, and map maker ->
// semantic worker): a FIFO of at most `capacity` items, which is the
// back-pressure between them. A producer that must not wait (the tracker)
// asks try_push and drops what does not fit; one that may (the map maker)
// push()es and waits for room. A consumer waits on a condition variable
// (never a sleep) until an item arrives, the queue is closed, or its own
// wake-up condition holds.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <limits>
#include <mutex>
#include <optional>

namespace facadeslam {

template <class T>
class BlockingQueue {
 public:
  static constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

  explicit BlockingQueue(std::size_t capacity = kUnbounded) : capacity_(capacity == 0 ? 1 : capacity) {}

  // Waits while the queue is full, then adds the item. False (the item
  // dropped) when the queue is, or gets, closed while full: nobody will take it.
  bool push(T item) {
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return items_.size() < capacity_ || closed_; });
      if (items_.size() >= capacity_) return false;
      items_.push_back(std::move(item));
    }
    changed_.notify_all();
    return true;
  }

  // Adds the item if there is room; false (the item not taken) when full.
  bool try_push(T&& item) {
    {
      std::lock_guard lock(mutex_);
      if (items_.size() >= capacity_) return false;
      items_.push_back(std::move(item));
    }
    changed_.notify_all();
    return true;
  }

  std::optional<T> try_pop() {
    std::optional<T> item;
    {
      std::lock_guard lock(mutex_);
      if (items_.empty()) return std::nullopt;
      item.emplace(std::move(items_.front()));
      items_.pop_front();
    }
    changed_.notify_all();  // a producer may be waiting for room
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
  bool full() const { return size() >= capacity_; }
  std::size_t capacity() const { return capacity_; }

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
    {
      std::lock_guard lock(mutex_);
      items_.clear();
    }
    changed_.notify_all();
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
  const std::size_t capacity_;
  std::deque<T> items_;
  bool closed_ = false;
};

}  // namespace facadeslam
