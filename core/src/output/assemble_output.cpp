// Output assembly, the pipeline's last stage: the final triangulation (MeshState) and refinement's
// outcome become the public Mesh. Vertices are numbered for output (MeshState::outputMap), then
// points, attributes, triangles, segments, statistics, boundary markers (boundary_markers.h), the
// trace's events in output numbering and user units, and what the options add (jettison.h, edges).
#include "output/assemble_output.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "mesh/angle_stats.h"
#include "output/boundary_markers.h"
#include "mesh/huge_pages.h"
#include "output/jettison.h"
#include "refine/exemptions.h"
#include "cold_code.h"

namespace ruppert::detail {
namespace {


// Mesh::pointAttributes: the input points' own values, the new vertices' interpolated ones.
void copyAttributes(const MeshState& m, Mesh& mesh) {
  const Plc& plc = *m.plc;
  const std::size_t k = m.attributeCount;
  if (k == 0) return;
  mesh.attributesPerPoint = m.attributeCount;
  mesh.pointAttributes.assign(k * (mesh.points.size() / 2), 0.0);
  std::copy(plc.pointAttributes.begin(), plc.pointAttributes.begin() + k * (plc.points.size() / 2),
            mesh.pointAttributes.begin());
  for (std::uint32_t v = m.inputCount; v < m.outputMap.size(); ++v) {  // (the coordinates may be gone)
    const std::uint32_t o = m.outputMap[v];
    if (o == kNone) continue;
    std::copy_n(m.attributes.begin() + k * v, k, mesh.pointAttributes.begin() + k * o);
  }
}

// Output numbering (MeshState::outputMap): input points keep their indices (internal vertices of
// input points are numbered in insertion order, see PreparedInput); Steiner vertices that some
// triangle uses follow in creation order; box corners and Steiner vertices in no triangle (refused
// insertions, or outside the domain in the bounding-box variant) are left out.
//
// Where the kept Steiner vertices are all those from the first kept one on (the usual case: at
// most the box's corners, made first, are left out), a kept Steiner vertex's output index is its
// own plus `shift` (mod 2^32), and no entry of the map need be read: on large meshes each read is a
// cache miss.
struct VertexNumbering {
  std::uint32_t count = 0;      // output vertices
  std::uint32_t firstKept = 0;  // the first kept Steiner vertex (the vertex count if none is)
  bool shifted = false;
  std::uint32_t shift = 0;
  std::uint32_t of(const MeshState& m, std::uint32_t v) const {
    return shifted && v >= m.inputCount ? v + shift : m.outputMap[v];
  }
};

VertexNumbering numberVertices(MeshState& m) {
  const Triangulation& t = m.tri;
  const std::uint32_t inputPoints = static_cast<std::uint32_t>(m.plc->points.size() / 2);
  m.outputMap = m.tri.takeVertexScratch();
  m.outputMap.assign(t.vertexCount(), kNone);
  VertexNumbering n;
  n.count = inputPoints, n.firstKept = t.vertexCount();
  for (std::uint32_t v = 0; v < t.vertexCount(); ++v) {
    if (v < m.inputCount) {
      m.outputMap[v] = m.input.inputIndex[v];
    } else if (t.vtri[v] != kNone && m.kind[v] != VertexKind::Unused) {
      if (n.count == inputPoints) n.firstKept = v;
      m.outputMap[v] = n.count++;
    }
  }
  n.shifted = n.count - inputPoints == t.vertexCount() - n.firstKept;
  n.shift = inputPoints - n.firstKept;
  return n;
}

// mesh.points and vertexKinds. Where every kept Steiner vertex's output index is at or below its
// own and above every input point's (no duplicate points beyond the left-out vertices before the
// first kept one), the triangulation's coordinates become the points in place, rewritten in
// ascending order: the two arrays are never held at once.
void writeVertices(MeshState& m, const VertexNumbering& numbering, Mesh& mesh) {
  Triangulation& t = m.tri;
  const Plc& plc = *m.plc;
  const std::uint32_t inputPoints = static_cast<std::uint32_t>(plc.points.size() / 2);
  const std::uint32_t vertices = t.vertexCount(), outVertices = numbering.count;
  const bool inPlace = numbering.shifted && numbering.firstKept >= inputPoints;
  if (inPlace) {
    mesh.points = std::move(t.xy);
  } else {
    reserveHuge(mesh.points, 2 * std::size_t(outVertices));
    mesh.points.resize(2 * std::size_t(outVertices));
  }
  const double* xy = inPlace ? mesh.points.data() : t.xy.data();
  mesh.vertexKinds.resize(outVertices);
  for (std::uint32_t v = numbering.shifted ? numbering.firstKept : m.inputCount; v < vertices; ++v) {
    const std::uint32_t o = numbering.of(m, v);
    if (o == kNone) continue;
    mesh.points[2 * std::size_t(o)] = m.input.toUser(xy[2 * std::size_t(v)]);  // a power of two: exact
    mesh.points[2 * std::size_t(o) + 1] = m.input.toUser(xy[2 * std::size_t(v) + 1]);
    mesh.vertexKinds[o] = static_cast<std::uint8_t>(m.kind[v]);
  }
  // Every input point, duplicates included, keeps its coordinates bit-identical; only the lowest index
  // of a set of identical points is an Input vertex of the mesh (if a triangle still uses it).
  for (std::uint32_t i = 0; i < inputPoints; ++i) {
    const std::uint32_t v = m.input.representative[i];
    mesh.points[2 * std::size_t(i)] = plc.points[2 * std::size_t(i)];
    mesh.points[2 * std::size_t(i) + 1] = plc.points[2 * std::size_t(i) + 1];
    const bool used = m.input.inputIndex[v] == i && t.vtri[v] != kNone;
    // Points made on curves (cdt/curves.h) are splits of their curves.
    const VertexKind own = i >= m.curves->firstPoint ? VertexKind::SegmentSplit : VertexKind::Input;
    mesh.vertexKinds[i] = static_cast<std::uint8_t>(used ? own : VertexKind::Unused);
  }
  mesh.points.resize(2 * std::size_t(outVertices));  // in place: the left-out vertices' room goes
}

// mesh.segments, segmentIds and the angle statistics (unless refinement's census has them), in one
// pass over the slots while the triangulation is whole. Labels each slot with its output triangle
// (kNone for a free slot). boundary[s]: whether subsegment s has a triangle on one side only (for
// the markers). freeSlots: the free slots, in order.
void scanTriangles(MeshState& m, std::optional<AngleStats>& census, Mesh& mesh, std::vector<std::uint8_t>& boundary,
                   std::vector<std::uint32_t>& freeSlots) {
  Triangulation& t = m.tri;
  auto outIndex = [&](std::uint32_t v) { return m.outputMap[v]; };
  // The subsegments number at least the input's segments: room for those and some splits, so that
  // small meshes do not grow these lists from empty (their count is known only after this pass).
  mesh.segments.reserve(m.plc->segments.size() + 64), mesh.segmentIds.reserve(m.plc->segments.size() / 2 + 32);
  boundary.reserve(mesh.segmentIds.capacity());
  freeSlots.reserve(t.freeSlots.size());  // the dead slots (a hint: the list is not grown from empty)
  const bool measure = !census;
  if (measure) census.emplace();
  AngleStats& angles = *census;
  std::uint32_t count = 0;
  for (std::uint32_t s = 0; s < t.slotCount(); ++s) {
    if (measure) t.prefetchCorners(s + Triangulation::kScanAhead);
    if (!t.alive(s)) {
      t.setLabel(s, kNone);
      freeSlots.push_back(s);
      continue;
    }
    t.setLabel(s, count++);
    for (std::uint32_t h = 3 * s; h < 3 * s + 3; ++h) {
      const std::uint32_t g = t.twin[h];
      if (t.con[h] != kFree && (g == kNone || h < g)) {
        mesh.segments.push_back(outIndex(t.origin(h)));
        mesh.segments.push_back(outIndex(t.dest(h)));
        mesh.segmentIds.push_back(t.con[h] >= 0 ? m.curves->outputId(t.con[h]) : kNoInputSegment);
        boundary.push_back(g == kNone || !t.alive(g / 3));  // as mesh.neighbors will say
      }
    }
    if (measure) angles.add(t.pt(t.tv[3 * s]), t.pt(t.tv[3 * s + 1]), t.pt(t.tv[3 * s + 2]));
  }
  Stats& st = mesh.stats;
  st.angleHistogram = angles.takeHistogram();
  angles.extremes(st.minAngle, st.maxAngle);
  st.triangles = count;
}

// Options::exemptions: each triangle's §6.6 exemption under the bounds asked for, by refinement's
// own rules, while the slots still carry their labels and the vertices their kinds. Once per
// call, on request: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN
void markExemptions(const MeshState& m, Mesh& mesh) {
  const ExemptionBounds bounds = exemptionBounds(*m.options);
  mesh.triangleExemptions.assign(mesh.stats.triangles, kNotExempt);
  for (std::uint32_t s = 0; s < m.tri.slotCount(); ++s) {
    const std::uint32_t out = m.tri.label(s);
    if (out != kNone) mesh.triangleExemptions[out] = exemptionOf(m, s, bounds);
  }
}
RUPPERT_COLD_END

// Output index of slot n's triangle, or kNoNeighbor for a free slot: n less the free slots before it.
std::int32_t triangleAfterFreeSlots(const std::vector<std::uint32_t>& freeSlots, std::uint32_t n) {
  const auto after = std::upper_bound(freeSlots.begin(), freeSlots.end(), n);
  if (after != freeSlots.begin() && after[-1] == n) return kNoNeighbor;
  return static_cast<std::int32_t>(n - static_cast<std::uint32_t>(after - freeSlots.begin()));
}

// mesh.neighbors and the corners. A neighbor's index comes from the list of free slots (few: refinement
// reuses the slots it frees, a triangulation of points leaves a handful) rather than from its
// record, a cache miss apiece on large meshes; so the scan reads each record once, in order, and
// can compact the corners into the records' memory and hand back the pages it leaves behind as it
// goes: the records and the neighbors are never all held at once.
void writeArraysCompacting(MeshState& m, const std::vector<std::uint32_t>& freeSlots, const VertexNumbering& numbering,
                           Mesh& mesh) {
  Triangulation& t = m.tri;
  const std::uint32_t slots = t.slotCount(), count = mesh.stats.triangles;
  const bool dense = freeSlots.empty();
  auto outputVertex = [&](std::uint32_t v) { return numbering.of(m, v); };
  constexpr std::uint32_t kReleaseEvery = 1u << 14;  // slots: 640 KB of records
  for (std::uint32_t s = 0; s < slots; ++s) {
    const TriangleSlot r = t.slot(s);  // a copy: writeCompactCorners may overwrite the record
    if (r.mark != kNone) {
      const std::uint32_t o = r.mark;
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t g = r.twin[i];
        mesh.neighbors.push_back(g == kNone ? kNoNeighbor
                                 : dense   ? static_cast<std::int32_t>(g / 3)
                                           : triangleAfterFreeSlots(freeSlots, g / 3));
      }
      t.writeCompactCorners(o, outputVertex(r.tv[0]), outputVertex(r.tv[1]), outputVertex(r.tv[2]));
    }
    if ((s + 1) % kReleaseEvery == 0) t.releaseReadRecords(s + 1, count);
  }
  mesh.triangles = t.takeCompactCorners(count);
}

// mesh.triangles, neighbors and triangleAttributes, each array of the state going as soon as it is
// read.
void writeTriangleArrays(MeshState& m, const std::vector<std::uint32_t>& freeSlots, const VertexNumbering& numbering,
                         Mesh& mesh) {
  Triangulation& t = m.tri;
  const std::uint32_t slots = t.slotCount(), count = mesh.stats.triangles;
  // Regions' attributes need the labels, which go with the slots; zeros are written after them.
  if (!m.attribute.empty()) {
    reserveHuge(mesh.triangleAttributes, count);
    mesh.triangleAttributes.resize(count);
    for (std::uint32_t s = 0; s < slots; ++s)
      if (t.label(s) != kNone) mesh.triangleAttributes[t.label(s)] = m.attribute[s];
    release(m.attribute);
  }
  // Filled in order (output indices follow the slots'), not zeroed first: that would touch all
  // of its pages while the records still hold theirs.
  reserveHuge(mesh.neighbors, 3 * std::size_t(count));
  writeArraysCompacting(m, freeSlots, numbering, mesh);
  if (mesh.triangleAttributes.empty()) {
    reserveHuge(mesh.triangleAttributes, count);
    mesh.triangleAttributes.assign(count, 0.0);
  }
}

// Stats: the vertices by kind.
void countVertexKinds(Mesh& mesh) {
  Stats& st = mesh.stats;
  for (std::uint8_t k : mesh.vertexKinds) {
    switch (static_cast<VertexKind>(k)) {
      case VertexKind::Input: st.inputVertices++; break;
      case VertexKind::SegmentSplit: st.segmentVertices++; break;
      case VertexKind::Interior: st.interiorVertices++; break;
      case VertexKind::OffCenter: st.offCenterVertices++; break;
      case VertexKind::Intersection: st.intersectionVertices++; break;
      case VertexKind::Unused: break;
    }
  }
  st.vertices = st.inputVertices + st.segmentVertices + st.interiorVertices + st.offCenterVertices +
                st.intersectionVertices;
}

// The public Mesh from the state, which it takes apart: vertices, attributes, triangles, counts,
// markers and notices. census: the angle statistics, if refinement gathered them.
Mesh assembleMesh(MeshState& m, std::optional<AngleStats>& census) {
  Mesh mesh;
  const Plc& plc = *m.plc;
  const VertexNumbering numbering = numberVertices(m);
  // Each part of the state goes once read (see writeTriangleArrays).
  std::vector<std::uint8_t> boundarySubsegment;
  std::vector<std::uint32_t> freeSlots;
  scanTriangles(m, census, mesh, boundarySubsegment, freeSlots);
  if (m.options->exemptions) markExemptions(m, mesh);
  release(m.maxArea), release(m.inDomain);
  m.tri.releaseScratch();
  writeVertices(m, numbering, mesh);
  copyAttributes(m, mesh);
  release(m.tri.xy), release(m.tri.vtri), release(m.kind), release(m.onSegment), release(m.attributes);
  writeTriangleArrays(m, freeSlots, numbering, mesh);
  countVertexKinds(mesh);
  mesh.indexBase = plc.indexBase;
  mesh.notices = std::move(m.notices);
  assignMarkers(mesh, plc, boundarySubsegment);
  return mesh;
}

// Refinement's outcome: reasons (and whether they leave the mesh incomplete), the trace, counts.
void addOutcome(const MeshState& m, RefineOutcome&& outcome, Mesh& mesh) {
  // The chapter's exemptions (§6.6) are reported but do not make the mesh incomplete.
  mesh.complete = true;
  for (const Reason& r : outcome.reasons)
    if (r.kind != ReasonKind::SmallInputAngle && r.kind != ReasonKind::SeditiousEdge) mesh.complete = false;
  mesh.reasons = std::move(outcome.reasons);
  mesh.events = std::move(outcome.events);
  // Events keep vertices that are not in the output (see Event::vertex) as kNoVertex.
  auto outIndex = [&](std::uint32_t v) { return v < m.outputMap.size() ? m.outputMap[v] : kNone; };
  for (Event& e : mesh.events) {
    e.vertex = outIndex(e.vertex), e.a = outIndex(e.a), e.b = outIndex(e.b);
    e.t0 = outIndex(e.t0), e.t1 = outIndex(e.t1), e.t2 = outIndex(e.t2);
    if (e.by >= 0) e.by = outIndex(static_cast<std::uint32_t>(e.by)) == kNone ? -1 : outIndex(static_cast<std::uint32_t>(e.by));
    e.x = m.input.toUser(e.x), e.y = m.input.toUser(e.y), e.cx = m.input.toUser(e.cx), e.cy = m.input.toUser(e.cy);
  }
  mesh.stats.rejectedCircumcenters = outcome.rejected;
  mesh.stats.reachedAngle = outcome.reachedAngle >= 0 ? outcome.reachedAngle : mesh.stats.minAngle;
  mesh.stats.lfsIntegral = outcome.lfsIntegral;
  mesh.stats.trianglesPerLfsIntegral = outcome.lfsIntegral > 0 ? mesh.stats.triangles / outcome.lfsIntegral : 0;
}

// What the options add: unused input points left out (Options::jettison), the edge list (edges).
void applyOutputOptions(const MeshState& m, Mesh& mesh) {
  const Options& options = *m.options;
  if (options.jettison) {
    std::vector<std::uint32_t> mergedInto(m.plc->points.size() / 2);
    for (std::size_t i = 0; i < mergedInto.size(); ++i) mergedInto[i] = m.input.inputIndex[m.input.representative[i]];
    jettisonUnused(mesh, mergedInto);
  } else if (m.curves->firstPoint < m.plc->points.size() / 2) {
    // Points made on a curve that lies in a hole or outside the domain: they are the mesher's, and
    // the mesher returns no vertex that no triangle uses; the user's points stay where they are.
    jettisonUnused(mesh, {}, m.curves->firstPoint);
  }
  if (options.edges) {
    MeshEdges edges = meshEdges(mesh);
    mesh.edges = std::move(edges.edges);
    mesh.edgeMarkers = std::move(edges.markers);
  }
}

}  // namespace

Mesh assembleOutput(MeshState& m, RefineOutcome outcome) {
  Mesh mesh = assembleMesh(m, outcome.angles);
  addOutcome(m, std::move(outcome), mesh);
  applyOutputOptions(m, mesh);
  return mesh;
}

}  // namespace ruppert::detail
