// The boundary marker of a subsegment, as the .msh writer's physical groups use it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// Subsegment i's marker: Mesh::segmentMarkers (Triangle's rules: its input segment's nonzero marker,
// else 1 on the boundary, 0 inside). A mesh made without them (read back from files, built by hand)
// falls back on the input segment's marker, 0 when the input has none or the subsegment is an edge
// no input segment covers (a hull edge, a refined mesh's boundary edge).
inline std::int32_t subsegmentMarker(const Mesh& mesh, const Plc& input, std::size_t i) {
  if (i < mesh.segmentMarkers.size()) return mesh.segmentMarkers[i];
  if (i >= mesh.segmentIds.size()) return 0;
  const std::int32_t id = mesh.segmentIds[i];
  if (id < 0 || static_cast<std::size_t>(id) >= input.segmentMarkers.size()) return 0;
  return input.segmentMarkers[static_cast<std::size_t>(id)];
}

}  // namespace ruppert::detail
