#pragma once
// "label: 12 s" on a terminal, redrawn every second from a thread of its own
// while one long call we cannot look into runs (OpenCV training a forest in
// one call), so a user sees that work goes on. Silent when Progress would be
// (no terminal, --quiet, a silenced thread). The thread waits on a
// condition variable with a timeout, so the destructor ends it at once.
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace facadeslam {

class ElapsedIndicator {
 public:
  explicit ElapsedIndicator(std::string label);
  ~ElapsedIndicator();  // stops, ends the line
  ElapsedIndicator(const ElapsedIndicator&) = delete;
  ElapsedIndicator& operator=(const ElapsedIndicator&) = delete;

 private:
  std::string label_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace facadeslam
