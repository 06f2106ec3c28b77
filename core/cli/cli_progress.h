// The progress line on standard error for long runs: "ruppert: 812345 vertices inserted, worst angle
// 12.3 deg, 4.2 s", rewritten in place, shown only when standard error is a terminal and once the run
// has lasted a second (short runs and pipelines into files print nothing).
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "ruppert/ruppert.h"

namespace ruppert::cli {

std::string progressText(const Progress& progress, double seconds);

class ProgressLine {
 public:
  // `enabled`: the caller checked that standard error is a terminal (and --quiet is not given).
  explicit ProgressLine(bool enabled);
  ~ProgressLine() { finish(); }  // a run that throws leaves no half line behind
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  // For Options::onProgress: always returns true (never stops the run).
  bool update(const Progress& progress);
  // Clears the line if one was drawn.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool drawn_ = false;
  Clock::time_point start_, lastDrawn_;
};

}  // namespace ruppert::cli
