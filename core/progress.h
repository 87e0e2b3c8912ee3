// Progress lines for long work: "[stage] message (12.3 s)". Passed explicitly, never global.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace voltree {

class Progress {
 public:
  explicit Progress(bool quiet = false) : quiet_(quiet), start_(Clock::now()) {}

  // Prints one line to stderr with the time since this Progress was made.
  void Say(const std::string& stage, const std::string& message);
  // Prints "stage: done/total" at most every few percent; thread-safe.
  void Step(const std::string& stage, size_t done, size_t total);
  double ElapsedSeconds() const;
  bool quiet() const { return quiet_; }

 private:
  using Clock = std::chrono::steady_clock;
  bool quiet_;
  Clock::time_point start_;
  std::mutex mutex_;
  int last_percent_ = -1;
  std::string last_stage_;
};

}  // namespace voltree
