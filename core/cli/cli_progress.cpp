#include "cli_progress.h"

#include <cstdio>

namespace ruppert::cli {

std::string progressText(const Progress& progress, double seconds) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "ruppert: %llu vertices inserted, %llu triangles, worst angle %.1f deg, %.1f s",
                static_cast<unsigned long long>(progress.insertedVertices),
                static_cast<unsigned long long>(progress.triangles), progress.worstAngle, seconds);
  return buf;
}

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), start_(Clock::now()), lastDrawn_(start_) {}

bool ProgressLine::update(const Progress& progress) {
  if (!enabled_) return true;
  const Clock::time_point now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  // After the first second, at most five redraws a second: the terminal is not the bottleneck.
  if (seconds < 1.0 || (drawn_ && now - lastDrawn_ < std::chrono::milliseconds(200))) return true;
  // "\r" returns to the line's start and "\033[K" clears what a longer previous line left.
  std::fprintf(stderr, "\r%s\033[K", progressText(progress, seconds).c_str());
  std::fflush(stderr);
  drawn_ = true;
  lastDrawn_ = now;
  return true;
}

void ProgressLine::finish() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace ruppert::cli
