// ruppert::triangulate: the pipeline (§6.1's generic Delaunay refinement, constrained as in §6.7),
// one call per stage, in order:
//   prepare (cdt/prepare_input.cpp: validate, scale, merge duplicates) -> Delaunay of the points
//   (cdt/build_delaunay.cpp) -> constraints (cdt/segment_insertion.cpp: hull, segments, with
//   repairs) -> classify (cdt/classify.cpp: exterior, holes, regions) -> refine (refine/, §6.2-6.6,
//   6.8) -> smooth (smooth/, Options::smooth) -> output (output/assemble_output.cpp).
// The decisions between stages are made here: the convex hull stands in for segments that enclose
// nothing, and the variant says when the outside goes (before refining, or after it in the box).
#include <optional>
#include <utility>
#if defined(__unix__) || defined(__APPLE__) || defined(__EMSCRIPTEN__)
#include <time.h>
#else
#include <chrono>
#endif

#include "output/assemble_output.h"
#include "cold_code.h"
#include "mesh_state.h"
#include "cdt/build_delaunay.h"
#include "cdt/classify.h"
#include "cdt/curves.h"
#include "cdt/old_mesh.h"
#include "cdt/prepare_input.h"
#include "cdt/segment_insertion.h"
#include "point_attributes.h"
#include "refine/refine.h"
#include "smooth/smooth.h"

namespace ruppert {

namespace detail {
namespace {

// Segments that enclose nothing (open polylines only, like Triangle's box.poly), or holes that take
// all they enclose: an empty mesh helps nobody. Unless the hull is already in (no segments, or
// Options::convexHull), the convex hull is meshed, with the segments inside it, and a notice says so.
bool hullCanStandIn(const MeshState& m, const Domain& domain) {
  return domain.empty() && !m.plc->segments.empty() && !m.options->convexHull;
}

Domain meshHullInstead(MeshState& m, const Domain& first) {
  m.notices.resize(first.noticesBefore);  // what the empty domain's holes reported no longer holds
  insertHull(m);
  m.notices.push_back(Notice{NoticeKind::NothingEnclosed, -1, -1, 0, 0,
                             "the segments leave no region enclosed; the convex hull of the points was meshed instead"});
  Domain domain = findDomain(m, /*hullStandsIn=*/true);
  domain.segmentsEncloseNothing = first.segmentsEncloseNothing;  // for EmptyDomain's message
  return domain;
}

}  // namespace
}  // namespace detail

// The steps, once per call (the work is in what they call): compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace {

// A monotonic clock in milliseconds, for Stats::milliseconds. Not std::chrono::steady_clock where
// POSIX's clock is there: libc++'s reports a failing clock with std::system_error, whose message
// formatting links printf's whole formatter into the WebAssembly module.
double nowMilliseconds() {
#if defined(__unix__) || defined(__APPLE__) || defined(__EMSCRIPTEN__)
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
#else
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

}  // namespace

Mesh triangulate(const Plc& userPlc, const Options& options) {
  using namespace detail;
  const double start = nowMilliseconds();
  const bool box = options.variant == Variant::BoundingBox;
  // The caller's indices and markers, before curves' pieces add points: a segment's index past the
  // input's points would name one of them (found by fuzz_mesh; tests/core/test_curves.cpp, "bad
  // curves are refused with the curve named").
  checkShape(userPlc);
  // Refining a mesh: its boundary edges join the segments, its triangles bound the domain and areas.
  Plc refining, withCurves;
  CurvePieces curves;
  const Plc* toMesh = &plcToMesh(userPlc, options, refining);
  // Curves become pieces, segments after the input's, that refinement splits on the curve.
  if (!toMesh->curves.empty()) withCurves = withCurvePieces(*toMesh, options, curves), toMesh = &withCurves;
  const Plc& plc = *toMesh;
  MeshState m;
  m.plc = &plc;
  m.options = &options;
  m.input = prepareInput(plc, options, m.notices);
  if (!curves.shapes.empty()) scaleCurves(curves, m.input), m.curves = &curves;
  std::optional<OldMesh> oldMesh;
  if (!plc.triangles.empty()) m.oldMesh = &oldMesh.emplace(plc, m.input);

  buildDelaunay(m);
  initAttributes(m);

  // The hull goes in after the segments, so that it runs through the crossings they made: a crossing
  // is rounded, so it can lie a hair outside the input points' hull, and a hull edge put in first
  // would then cross the pieces that end there, each repair rounding a new crossing outside again
  // (found by fuzzing: tests/hostile/crossings-rounded-outside-a-hull-inserted-first.poly).
  if (plc.segments.empty()) insertHull(m);
  insertSegments(m);
  if (!curves.shapes.empty()) rejectRepairedCurves(m.notices, curves);
  if (!plc.segments.empty() && options.convexHull) insertHull(m);
  if (box) constrainBoxSides(m);

  Domain domain = findDomain(m);
  if (hullCanStandIn(m, domain)) domain = meshHullInstead(m, domain);
  classifyTriangles(m, domain);
  release(domain.outside);  // 1 byte per slot, no longer read
  // §6.7: the constrained variant's triangulation holds only the domain from here on; Ruppert's
  // original (the box) refines the whole box and cuts the domain out at the end.
  if (!box) removeOutside(m);
  if (m.oldMesh != nullptr) keepOldMeshDomain(m);

  RefineOutcome outcome;
  if (refinementRequested(m)) outcome = refine(m);
  if (box) removeOutside(m);
  // After the box's outside is gone: only the domain's vertices move, within its triangles.
  if (options.smooth > 0) smoothMesh(m, options.smooth);
  if (box || options.smooth > 0) outcome.angles.reset();  // the census saw another mesh
  if (options.sizeMeasure) outcome.lfsIntegral = estimateLfsIntegral(m);

  Mesh mesh = assembleOutput(m, std::move(outcome));
  mesh.stats.milliseconds = nowMilliseconds() - start;
  return mesh;
}

RUPPERT_COLD_END

}  // namespace ruppert
