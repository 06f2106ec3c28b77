// Everything the stages (build, constrain, classify, refine, output) share about one meshing run.
#pragma once

#include <cstdint>
#include <vector>

#include "prepare_input.h"
#include "ruppert/ruppert.h"
#include "triangulation.h"

namespace ruppert::detail {

class OldMesh;  // old_mesh.h

struct MeshState {
  const Plc* plc = nullptr;
  const Options* options = nullptr;
  PreparedInput input;
  Triangulation tri;
  std::vector<VertexKind> kind;              // per vertex
  std::vector<std::int32_t> onSegment;       // per vertex: input segment it was inserted on, or -1
  std::uint32_t inputCount = 0;              // vertices [0, inputCount) are the input points
  std::uint32_t boxFirst = kNone;            // 4 bounding-box corners start here (kNone: removed)
  std::vector<Notice> notices;
  // Per triangle slot, valid after classification.
  std::vector<double> attribute;
  std::vector<double> maxArea;               // scaled; 0 = none
  // Bounding-box variant only: triangles outside the domain stay (and are refined) until the end.
  std::vector<std::uint8_t> inDomain;        // per slot: 1 inside the domain; empty in the CDT variant
  // Refining a mesh (Plc::triangles): its triangles' domain and area bounds; null otherwise.
  const OldMesh* oldMesh = nullptr;
  std::size_t segmentCount() const { return plc->segments.size() / 2; }
  // Input segment id's end (0 or 1) as an internal vertex: the representative of its input point.
  std::uint32_t segmentEnd(std::size_t id, int end) const { return input.representative[plc->segments[2 * id + end]]; }

  // Plc::pointAttributes per vertex (attributeCount each; point_attributes.h), or empty.
  std::uint32_t attributeCount = 0;
  std::vector<double> attributes;

  std::uint32_t addVertex(double x, double y, VertexKind k, std::int32_t segment) {
    kind.push_back(k);
    onSegment.push_back(segment);
    attributes.resize(attributes.size() + attributeCount, 0.0);
    return tri.addVertex(x, y);
  }
  // Per internal vertex: its index in Mesh::points, or kNone if left out (built by the output stage).
  std::vector<std::uint32_t> outputMap;
};

// Stages, in order.
void buildDelaunay(MeshState& m);          // box corners + every distinct input point
void insertHull(MeshState& m);             // convex hull edges as constraints (no segments / convexHull)
void insertSegments(MeshState& m);         // input segments, repairing crossings and overlaps
void classifyTriangles(MeshState& m);      // remove exterior and holes; regions' attributes and areas
void removeOutside(MeshState& m);          // bounding-box variant: drop what lies outside, after refining

}  // namespace ruppert::detail
