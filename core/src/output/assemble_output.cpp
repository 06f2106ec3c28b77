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
  for (std::uint32_t v = m.inputCount; v < m.tri.vertexCount(); ++v) {
    const std::uint32_t o = m.outputMap[v];
    if (o == kNone) continue;
    std::copy_n(m.attributes.begin() + k * v, k, mesh.pointAttributes.begin() + k * o);
  }
}

// Output numbering (MeshState::outputMap): input points keep their indices (internal vertices of
// input points are numbered in insertion order, see PreparedInput); Steiner vertices that some
// triangle uses follow in creation order; box corners and Steiner vertices in no triangle (refused
// insertions, or outside the domain in the bounding-box variant) are left out. Returns the count.
std::uint32_t numberVertices(MeshState& m) {
  const Triangulation& t = m.tri;
  const std::uint32_t inputPoints = static_cast<std::uint32_t>(m.plc->points.size() / 2);
  m.outputMap = m.tri.takeVertexScratch();
  m.outputMap.assign(t.vertexCount(), kNone);
  std::uint32_t outVertices = inputPoints;
  for (std::uint32_t v = 0; v < t.vertexCount(); ++v) {
    if (v < m.inputCount) m.outputMap[v] = m.input.inputIndex[v];
    else if (t.vtri[v] != kNone && m.kind[v] != VertexKind::Unused) m.outputMap[v] = outVertices++;
  }
  return outVertices;
}

// mesh.points and vertexKinds.
void writeVertices(const MeshState& m, std::uint32_t outVertices, Mesh& mesh) {
  const Triangulation& t = m.tri;
  const Plc& plc = *m.plc;
  const std::uint32_t inputPoints = static_cast<std::uint32_t>(plc.points.size() / 2);
  auto outIndex = [&](std::uint32_t v) { return m.outputMap[v]; };
  reserveHuge(mesh.points, 2 * std::size_t(outVertices));
  mesh.points.resize(2 * std::size_t(outVertices));
  mesh.vertexKinds.resize(outVertices);
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
  for (std::uint32_t v = m.inputCount; v < t.vertexCount(); ++v) {
    const std::uint32_t o = outIndex(v);
    if (o == kNone) continue;
    mesh.points[2 * std::size_t(o)] = m.input.toUser(t.xy[2 * v]);  // a power of two: exact
    mesh.points[2 * std::size_t(o) + 1] = m.input.toUser(t.xy[2 * v + 1]);
    mesh.vertexKinds[o] = static_cast<std::uint8_t>(m.kind[v]);
  }

}

// mesh.segments, segmentIds and the angle statistics (unless refinement's census has them), in one
// pass over the slots while the triangulation is whole. Labels each slot with its output triangle
// (kNone for a free slot). boundary[s]: whether subsegment s has a triangle on one side only (for
// the markers).
void scanTriangles(MeshState& m, std::optional<AngleStats>& census, Mesh& mesh, std::vector<std::uint8_t>& boundary) {
  Triangulation& t = m.tri;
  auto outIndex = [&](std::uint32_t v) { return m.outputMap[v]; };
  // The subsegments number at least the input's segments: room for those and some splits, so that
  // small meshes do not grow these lists from empty (their count is known only after this pass).
  mesh.segments.reserve(m.plc->segments.size() + 64), mesh.segmentIds.reserve(m.plc->segments.size() / 2 + 32);
  boundary.reserve(mesh.segmentIds.capacity());
  const bool measure = !census;
  if (measure) census.emplace();
  AngleStats& angles = *census;
  std::uint32_t count = 0;
  for (std::uint32_t s = 0; s < t.slotCount(); ++s) {
    t.prefetchCorners(s + Triangulation::kScanAhead);
    if (!t.alive(s)) {
      t.setLabel(s, kNone);
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

// mesh.triangles, neighbors and triangleAttributes. The output's corners are written over the
// triangulation's slots in place (a triangle's output index is never above its slot) and copied
// out of the slot records, which then go; each array goes as soon as it is read. steinerShift:
// where every Steiner vertex is in the output, the amount each one's index moves by (else kNone).
void writeTriangleArrays(MeshState& m, std::uint32_t steinerShift, Mesh& mesh) {
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
  reserveHuge(mesh.neighbors, 3 * std::size_t(count));
  mesh.neighbors.resize(3 * std::size_t(count));
  // On large meshes, reading a neighbor's label or a corner's entry in the map is a cache miss
  // apiece. Where every slot holds a triangle (refinement reuses the slots it frees: the common
  // case) each slot is the output triangle of its own index, and where every Steiner vertex is
  // kept (numbered in creation order after the input's points) each one's index is its own shifted:
  // neither is read then.
  const bool dense = count == slots;
  const bool shifted = steinerShift != kNone;
  const std::uint32_t firstSteiner = m.inputCount;
  // Slot o's corners are written after slot s's (o <= s) are read, and the labels are left alone.
  for (std::uint32_t s = 0; s < slots; ++s) {
    if (!dense) t.prefetchNeighbors(s + Triangulation::kScanAhead);
    const std::uint32_t o = t.label(s);
    if (o == kNone) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t g = t.twin[3 * s + i];
      mesh.neighbors[3 * o + i] = g == kNone ? kNoNeighbor : static_cast<std::int32_t>(dense ? g / 3 : t.label(g / 3));
      const std::uint32_t v = t.tv[3 * s + i];
      t.tv[3 * o + i] = shifted && v >= firstSteiner ? v + steinerShift : m.outputMap[v];
    }
  }
  mesh.triangles = t.takeCorners(count);
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
  const std::uint32_t outVertices = numberVertices(m);
  const std::uint32_t inputPoints = static_cast<std::uint32_t>(plc.points.size() / 2);
  const bool everySteinerKept = outVertices - inputPoints == m.tri.vertexCount() - m.inputCount;
  const std::uint32_t steinerShift = everySteinerKept ? inputPoints - m.inputCount : kNone;
  // Each part of the state goes once read (see writeTriangleArrays).
  std::vector<std::uint8_t> boundarySubsegment;
  scanTriangles(m, census, mesh, boundarySubsegment);
  if (m.options->exemptions) markExemptions(m, mesh);
  release(m.maxArea), release(m.inDomain);
  m.tri.releaseScratch();
  writeVertices(m, outVertices, mesh);
  copyAttributes(m, mesh);
  release(m.tri.xy), release(m.tri.vtri), release(m.kind), release(m.onSegment), release(m.attributes);
  writeTriangleArrays(m, steinerShift, mesh);
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
