// What a reader promises about any Plc it returns, checked by the reader fuzzers. A broken promise
// is a finding: the target prints it and aborts, so libFuzzer saves the input.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <ruppert/ruppert.h>

namespace ruppert_fuzz {

[[noreturn]] inline void finding(const char* what) {
  std::fprintf(stderr, "FINDING: %s\n", what);
  std::abort();
}

inline void checkPlcInvariants(const ruppert::Plc& plc) {
  if (plc.points.size() % 2 != 0) finding("odd number of point coordinates");
  if (plc.segments.size() % 2 != 0) finding("odd number of segment indices");
  if (plc.holes.size() % 2 != 0) finding("odd number of hole coordinates");
  const std::size_t n = plc.points.size() / 2;
  for (std::uint32_t index : plc.segments)
    if (index >= n) finding("a segment index refers to a point that does not exist");
  // Readers reject non-finite numbers, so a finite-only Plc is part of their contract.
  for (double v : plc.points)
    if (!std::isfinite(v)) finding("non-finite point coordinate accepted");
  for (double v : plc.holes)
    if (!std::isfinite(v)) finding("non-finite hole coordinate accepted");
  for (const ruppert::Region& r : plc.regions)
    if (!std::isfinite(r.x) || !std::isfinite(r.y) || std::isnan(r.attribute) || std::isnan(r.maxArea))
      finding("non-finite region accepted");
  if (!plc.pointMarkers.empty() && plc.pointMarkers.size() != n) finding("pointMarkers is neither empty nor one per point");
  if (!plc.segmentMarkers.empty() && plc.segmentMarkers.size() != plc.segments.size() / 2)
    finding("segmentMarkers is neither empty nor one per segment");
  if (plc.indexBase != 0 && plc.indexBase != 1) finding("indexBase is neither 0 nor 1");
}

// Errors a reader may throw for bad text. Internal means a bug; anything else (bad_alloc, a
// std::exception that is not ruppert::Error) escapes the target and libFuzzer reports it.
inline void checkReaderError(const ruppert::Error& e) {
  if (e.code() == ruppert::ErrorCode::Internal) finding(e.what());
  if (e.what()[0] == '\0') finding("an error without a message");
}

}  // namespace ruppert_fuzz
