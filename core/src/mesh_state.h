// Everything the stages share about one meshing run. The stages, in triangulate()'s order:
//   prepare    prepareInput (cdt/prepare_input.h), in triangulate.cpp
//   build      buildDelaunay (cdt/build_delaunay.h), initAttributes (point_attributes.h)
//   constrain  insertHull, insertSegments, constrainBoxSides (cdt/segment_insertion.h)
//   classify   findDomain, classifyTriangles, removeOutside (cdt/classify.h), keepOldMeshDomain
//              (cdt/old_mesh.h)
//   refine     refine (refine/refine.h; class Refiner in refine/refiner.h)
//   output     assembleOutput (output/assemble_output.h), which takes the state apart
// Each field says which stages write it ("w:") and which read it ("r:").
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "curve_pieces.h"
#include "mesh/triangulation.h"
#include "prepared_input.h"
#include "ruppert/ruppert.h"

namespace ruppert::detail {

class OldMesh;  // old_mesh.h

struct MeshState {
  // w: triangulate (before prepare). r: every stage.
  const Plc* plc = nullptr;
  const Options* options = nullptr;
  // The scaled, merged, ordered input (prepared_input.h). w: prepare. r: every stage (coordinates,
  // representatives, holes, regions, the unit conversions).
  PreparedInput input;
  // The triangulation. w: build, constrain, classify (removeOutside), refine. r: every stage.
  Triangulation tri;
  // Per vertex (addVertex appends to both). w: build (input points, box corners), constrain
  // (intersections), refine (Steiner vertices; Unused when an insertion is refused). r: constrain
  // (insertHull), refine (acute corners, which vertices may move, seditious edges), output (vertex kinds).
  std::vector<VertexKind> kind;
  // Per vertex: the input segment it was inserted on (refine's subsegment splits), -2 - k for
  // hull edge k (hullEdgeEnds), or -1. w: refine. r: refine (seditious edges).
  std::vector<std::int32_t> onSegment;
  // Per convex-hull (or bounding-box) edge that refinement split: its two end vertices, so that the
  // seditious rule (§6.6) treats it as the segment it stands for. w and r: refine.
  std::vector<std::array<std::uint32_t, 2>> hullEdgeEnds;
  // Plc::curves cut into pieces, which are plc's segments from curves->first on (curve_pieces.h); held
  // by triangulate (a pointer: MeshState is copied during refinement's push, the pieces never change).
  // w: triangulate (before prepare; scaled after it). r: constrain (rejectRepairedCurves), refine
  // (split points, the disk rule, the tolerance), output (segmentIds, vertex kinds).
  const CurvePieces* curves = &kNoCurves;
  // Per vertex refinement put on a curve piece: its curve parameter (NaN or absent for others; a
  // piece's end vertices take theirs from the piece, CurvePieces::t0 and t1). w and r: refine.
  std::vector<double> curveT;
  // Vertices [0, inputCount) are the distinct input points. w: build. r: constrain, refine, output,
  // initAttributes, the size measure.
  std::uint32_t inputCount = 0;
  // The 4 bounding-box corners start here. w: build. r: constrain (constrainBoxSides), classify
  // (the exterior is flooded from them).
  std::uint32_t boxFirst = kNone;
  // w: prepare, constrain, classify (seeds outside the domain), triangulate (the hull standing in
  // for segments that enclose nothing, which also drops what the empty domain reported). r: output
  // (moved into Mesh::notices).
  std::vector<Notice> notices;
  // Per triangle slot, from classification on: the region attribute and the area bound (scaled;
  // 0 = none). w: classify, refine (new triangles inherit them). r: refine (area bounds, the
  // budget), output (triangle attributes). Both empty where every triangle has attribute 0 and the
  // bound input.maxArea (no region seed in the domain, constrained variant): the common case keeps
  // neither 16 bytes per slot nor their copying at every insertion (read them through maxAreaOf).
  std::vector<double> attribute;
  std::vector<double> maxArea;
  double maxAreaOf(std::uint32_t slot) const { return maxArea.empty() ? input.maxArea : maxArea[slot]; }
  // Per slot: 1 inside the domain. w: classify (classifyTriangles, keepOldMeshDomain), refine (new
  // triangles inherit it); removeOutside reads it, deletes the rest and clears it. So it is empty
  // during refinement in the constrained variant and full in the bounding-box variant, whose
  // outside stays (and is refined) until the pipeline removes it after refinement; refine tells the
  // variants apart by it (the domain's boundary, what new triangles inherit).
  std::vector<std::uint8_t> inDomain;
  // Refining a mesh (Plc::triangles): its triangles' domain and area bounds; null otherwise.
  // w: triangulate. r: classify (keepOldMeshDomain), refine (area bounds, budget).
  const OldMesh* oldMesh = nullptr;
  std::size_t segmentCount() const { return plc->segments.size() / 2; }
  // Input segment id's end (0 or 1) as an internal vertex: the representative of its input point.
  std::uint32_t segmentEnd(std::size_t id, int end) const { return input.representative[plc->segments[2 * id + end]]; }

  // Plc::pointAttributes per vertex (attributeCount each; point_attributes.h), or empty.
  // w: build (initAttributes), constrain and refine (new vertices interpolate). r: output.
  std::uint32_t attributeCount = 0;
  std::vector<double> attributes;

  // Out of line: one copy of the vectors' growth code for the two callers (build, refinement).
  [[gnu::noinline]] void reserve(std::size_t vertices, std::size_t slots) {
    kind.reserve(vertices), reserveHuge(onSegment, vertices);
    tri.reserve(vertices, slots);
  }
  // The distinct input points as vertices 0 .. n-1, taking their coordinates without a copy.
  void adoptInputPoints(std::vector<double>&& xy, std::size_t vertices, std::size_t slots) {
    kind.reserve(vertices), reserveHuge(onSegment, vertices);
    kind.assign(xy.size() / 2, VertexKind::Input), onSegment.assign(xy.size() / 2, -1);
    tri.adoptVertices(std::move(xy), vertices);
    tri.reserve(vertices, slots);
  }
  std::uint32_t addVertex(double x, double y, VertexKind k, std::int32_t segment) {
    kind.push_back(k);
    onSegment.push_back(segment);
    attributes.resize(attributes.size() + attributeCount, 0.0);
    return tri.addVertex(x, y);
  }
  // Per internal vertex: its index in Mesh::points, or kNone if left out. w and r: output.
  std::vector<std::uint32_t> outputMap;
};

}  // namespace ruppert::detail
