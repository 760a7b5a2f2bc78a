#pragma once
// A one-line progress bar for long jobs (replay, training, evaluation). It
// draws only when both stdout and stderr are terminals and logging is not
// quiet, so CI logs and pipes stay clean. Not thread-safe: drive it from the
// thread that owns the loop.
#include <cstddef>
#include <string>

#include "core/util/stopwatch.hpp"

namespace facadeslam {

class Progress {
 public:
  Progress(std::string label, std::size_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Sets the number of finished items; redraws at most ~10 times a second.
  void update(std::size_t done, const std::string& status = {});
  void finish();
  bool enabled() const { return enabled_; }

  static bool terminal_attached();
  // Whether a bar made now on this thread would draw (terminal, not quiet,
  // not silenced).
  static bool drawing_enabled();

  // Bars made on this thread while one of these lives stay silent: work
  // spread over worker threads under one overall bar (the optimiser's
  // fitness evaluations train forests, whose own bars would interleave).
  class SilenceOnThisThread {
   public:
    SilenceOnThisThread();
    ~SilenceOnThisThread();
    SilenceOnThisThread(const SilenceOnThisThread&) = delete;
    SilenceOnThisThread& operator=(const SilenceOnThisThread&) = delete;

   private:
    bool previous_;
  };

 private:
  void draw(const std::string& status);

  std::string label_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool enabled_;
  bool finished_ = false;
  Stopwatch since_start_;
  Stopwatch since_draw_;
  bool drawn_ = false;
};

}  // namespace facadeslam
