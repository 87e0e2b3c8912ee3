#include "core/progress.h"

#include <cstdio>

namespace voltree {

double Progress::ElapsedSeconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void Progress::Say(const std::string& stage, const std::string& message) {
  if (quiet_) return;
  std::lock_guard lock(mutex_);
  std::fprintf(stderr, "[%s] %s (%.1f s)\n", stage.c_str(), message.c_str(), ElapsedSeconds());
  std::fflush(stderr);
}

void Progress::Step(const std::string& stage, size_t done, size_t total) {
  if (quiet_ || total == 0) return;
  std::lock_guard lock(mutex_);
  const int percent = static_cast<int>(100 * done / total);
  if (stage != last_stage_) {
    last_stage_ = stage;
    last_percent_ = -1;
  }
  if (done != total && percent < last_percent_ + 10) return;
  last_percent_ = percent;
  std::fprintf(stderr, "[%s] %zu/%zu (%.1f s)\n", stage.c_str(), done, total, ElapsedSeconds());
  std::fflush(stderr);
}

}  // namespace voltree
