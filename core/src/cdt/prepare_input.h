// Validation and normalization of a PLC before triangulation: checks, scaling, duplicates,
// insertion order (the result's layout: prepared_input.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "prepared_input.h"
#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Room a plain CDT keeps for vertices beyond the input's: the 4 box corners and a few crossings.
inline constexpr std::size_t kCdtExtraVertices = 68;

// The caller's input's shape (even lengths, segments' indices in range, one marker per point and
// per segment or none); throws ruppert::Error naming the offending item. triangulate() runs it
// first: curves' pieces then add points, segments and per-curve segment markers, and prepareInput
// checks lengths and indices again on what is meshed.
void checkShape(const Plc& plc);

// Throws ruppert::Error naming the offending item. Appends DuplicatePoint notices.
PreparedInput prepareInput(const Plc& plc, const Options& options, std::vector<Notice>& notices);

}  // namespace ruppert::detail
