// The boundary marker of a subsegment, as the .msh writer's physical groups use it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Subsegment i's marker: its input segment's marker, 0 when the input has none (or the subsegment is
// a convex-hull edge no input segment covers). It reads the input's segment markers; once
// Mesh::segmentMarkers (one marker per subsegment, issue 16 item 1) lands, it will read that
// instead, and this is the one place to switch.
inline std::int32_t subsegmentMarker(const Mesh& mesh, const Plc& input, std::size_t i) {
  if (i >= mesh.segmentIds.size()) return 0;
  const std::int32_t id = mesh.segmentIds[i];
  if (id < 0 || static_cast<std::size_t>(id) >= input.segmentMarkers.size()) return 0;
  return input.segmentMarkers[static_cast<std::size_t>(id)];
}

}  // namespace ruppert::detail
