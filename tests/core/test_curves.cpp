// Curved boundaries (Plc::curves): refined on the curve. Every mesh is judged by the
// validator (Delaunay, the angle bound with the chapter's exemptions, the input) and by the
// independent curve check (curve_checks.h): vertices on their curves, pieces within the tolerance
// of them, and the mesh's area within the chords' error of the curved domain's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "curve_checks.h"
#include "curve_shapes.h"
#include "validator.h"

using ruppert::Mesh;
using ruppert::Options;
using ruppert::Plc;
using ruppert_test::CurvedShape;

namespace {

struct Meshed {
  Mesh mesh;
  ruppert_test::CurveCheck curves;
};

// Meshes the shape and requires everything the issue promises.
Meshed meshAndCheck(const CurvedShape& shape, double minAngle, double tolerance, double maxArea = 0, Options o = {}) {
  o.minAngle = minAngle, o.curveTolerance = tolerance, o.maxArea = maxArea;
  Meshed out{ruppert::triangulate(shape.plc, o), {}};
  INFO("min angle " << minAngle << ", tolerance " << tolerance << ", max area " << maxArea);
  REQUIRE(out.mesh.complete);
  ruppert_test::ValidateOptions v;
  v.input = &shape.plc, v.minAngle = minAngle, v.maxArea = maxArea;
  v.angleExempt = ruppert_test::chapterExemptions(out.mesh, shape.plc);
  REQUIRE_VALID(out.mesh, v);
  out.curves = ruppert_test::checkCurves(out.mesh, shape.plc, tolerance);
  INFO(ruppert_test::describeProblems(out.curves.problems));
  REQUIRE(out.curves.problems.empty());
  CHECK(std::fabs(ruppert_test::meshArea(out.mesh) - shape.area) <= out.curves.chordAreaBound + 1e-12);
  return out;
}

}  // namespace

TEST_CASE("a unit square with a round hole meshes on the circle at 30 degrees", "[curves]") {
  const CurvedShape shape = ruppert_test::squareWithRoundHole(0.25);
  const Meshed coarse = meshAndCheck(shape, 30, 1e-3);
  const Meshed fine = meshAndCheck(shape, 30, 1e-5);
  const std::size_t coarseEdges = coarse.curves.pieces[0] + coarse.curves.pieces[1];
  const std::size_t fineEdges = fine.curves.pieces[0] + fine.curves.pieces[1];
  INFO("hole edges: " << coarseEdges << " at 1e-3, " << fineEdges << " at 1e-5");
  CHECK(coarse.mesh.stats.minAngle >= 30);
  // The sagitta r (1 - cos(pi / n)) shrinks as 1/n^2: a hundredth of the tolerance, ten times the edges.
  CHECK(fineEdges >= 8 * coarseEdges);
  CHECK(coarse.curves.worstOffCurve <= 1e-12);
}

TEST_CASE("a quarter disk under an area bound keeps its arc's vertices on the arc", "[curves]") {
  const CurvedShape shape = ruppert_test::quarterDisk();
  for (double angle : {0.0, 20.0, 30.0, 33.0}) meshAndCheck(shape, angle, 1e-3, 1e-3);
  // The arc bulges out of its chords: the domain grows as they split (triangles beyond the chord).
  const Meshed m = meshAndCheck(shape, 30, 1e-4);
  CHECK(m.curves.pieces[0] >= 50);
}

TEST_CASE("input points between an arc and its first chords are meshed once the chords reach them", "[curves]") {
  // The quarter disk's arc bulges out of its chords: points just inside the arc lie beyond the first
  // chords, outside the first triangles. Found by fuzz_mesh: such a point was dropped with the
  // triangles outside, and a later split of the piece covered it with a triangle that did not use it.
  for (double tolerance : {0.05, 1e-3}) {
    CurvedShape shape = ruppert_test::quarterDisk();
    for (double angle = 0.05; angle < 1.55; angle += 0.1) {
      shape.plc.points.push_back(0.995 * std::cos(angle));
      shape.plc.points.push_back(0.995 * std::sin(angle));
    }
    // The area bound splits every piece of the arc: the validator finds any input point inside a
    // triangle that no triangle uses.
    meshAndCheck(shape, 30, tolerance, 1e-3);
    meshAndCheck(shape, 20, tolerance);
  }
}

TEST_CASE("an input point on an arc where a piece would end becomes that piece's end", "[curves]") {
  // The lower half of the circle of radius 2 around (-2, 0) passes through (-2, -2) at its
  // parameter midpoint, where a halving of its pieces lands to rounding (x = -2 - 4e-16). Found by
  // fuzz_mesh: the halving's own point there and the input point were near-duplicates joined by an
  // edge; the piece now ends at the input point.
  CurvedShape shape;
  shape.plc.points = {-4, 0, 0, 0, -2, -2};
  shape.plc.segments = {1, 0};
  ruppert::Curve c;
  c.type = ruppert::CurveType::Arc, c.from = 0, c.to = 1, c.center[0] = -2, c.center[1] = 0;
  shape.plc.curves.push_back(c);
  shape.area = 2 * std::acos(-1.0);
  // 1e-3: a first cut of 50 pieces ends one there; 1: a halving of the middle one of three does.
  for (double tolerance : {1e-3, 1.0}) {
    const Meshed m = meshAndCheck(shape, 30, tolerance);
    CHECK(std::count(m.mesh.triangles.begin(), m.mesh.triangles.end(), 2u) > 0);
  }
}

TEST_CASE("a region under a cubic Bezier meshes on the curve", "[curves]") {
  for (double h : {0.5, 1.0, 2.0}) {
    const CurvedShape shape = ruppert_test::underBezier(h);
    meshAndCheck(shape, 30, 1e-3);
    meshAndCheck(shape, 25, 1e-4, 1e-3);
  }
}

TEST_CASE("generated curved shapes mesh on their curves within the tolerance", "[curves]") {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    INFO("seed " << seed);
    meshAndCheck(ruppert_test::diskWithHoles(int(seed) + 1, seed), 30, 1e-3);
  }
  for (double r : {0.05, 0.2, 0.5}) meshAndCheck(ruppert_test::roundedRectangle(2, 1, r), 30, 1e-3 * r);
  for (double d : {0.3, 0.9, 0.97}) meshAndCheck(ruppert_test::lens(d), 30, 1e-3);
  for (double r2 : {0.75, 0.9}) meshAndCheck(ruppert_test::crescent(0.3, r2), 30, 1e-3);
  meshAndCheck(ruppert_test::crescent(0.3, 0.75), 33, 1e-4);
  for (int teeth : {6, 12, 24}) meshAndCheck(ruppert_test::gear(teeth, 0.8), 30, 1e-3);
  meshAndCheck(ruppert_test::gear(12, 0.8), 33, 1e-4);
}

TEST_CASE("curves hold under every variant, placement and encroachment rule", "[curves]") {
  const CurvedShape shapes[] = {ruppert_test::squareWithRoundHole(0.25), ruppert_test::quarterDisk(),
                                ruppert_test::crescent(0.3, 0.75), ruppert_test::underBezier(1)};
  for (const CurvedShape& shape : shapes) {
    for (ruppert::Variant variant : {ruppert::Variant::Constrained, ruppert::Variant::BoundingBox})
      for (ruppert::Placement placement : {ruppert::Placement::Circumcenter, ruppert::Placement::OffCenter,
                                           ruppert::Placement::Petal, ruppert::Placement::Optimal})
        for (ruppert::Encroachment rule : {ruppert::Encroachment::DiametralDisk, ruppert::Encroachment::DiametralLens}) {
          Options o;
          o.variant = variant, o.placement = placement, o.encroachment = rule;
          INFO(enumName(variant) << ' ' << enumName(placement) << ' ' << enumName(rule));
          meshAndCheck(shape, 30, 1e-4, 0, o);
        }
    // Above 34 degrees refinement runs in stages and slides vertices along segments (never along curves).
    meshAndCheck(shape, 38, 1e-3);
  }
}

TEST_CASE("a curve between two regions keeps both sides meshed and its pieces on it", "[curves]") {
  // The unit square split by a quarter circle of radius 0.5 around (1, 1), which meets its sides at
  // right angles, into two regions with attributes 1 and 2.
  CurvedShape shape;
  shape.plc.points = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0.5, 0.5, 1};
  shape.plc.segments = {0, 1, 1, 4, 4, 2, 2, 5, 5, 3, 3, 0};
  ruppert::Curve arc;
  arc.type = ruppert::CurveType::Arc, arc.from = 5, arc.to = 4, arc.center[0] = 1, arc.center[1] = 1;
  shape.plc.curves.push_back(arc);
  shape.plc.regions = {{0.1, 0.1, 1, 0}, {0.9, 0.9, 2, 0}};
  shape.area = 1;
  const Meshed m = meshAndCheck(shape, 30, 1e-3);
  double inner = 0;
  for (std::size_t t = 0; t < m.mesh.triangleAttributes.size(); ++t) {
    const std::uint32_t* v = &m.mesh.triangles[3 * t];
    const double* p[3] = {&m.mesh.points[2 * v[0]], &m.mesh.points[2 * v[1]], &m.mesh.points[2 * v[2]]};
    const double a = ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1])) / 2;
    if (m.mesh.triangleAttributes[t] == 2) inner += a;
  }
  // Region 2 is the quarter disk of radius 0.5 around (1, 1).
  CHECK(std::fabs(inner - 3.14159265358979323846 / 16) <= m.curves.chordAreaBound + 1e-12);
}

TEST_CASE("a curve inside a hole leaves no vertex of its own in the mesh", "[curves]") {
  // The unit square with a square hole [0.2, 0.8]^2, and in the hole a circle of radius 0.1 with a
  // hole seed inside it too: every piece of the circle lies in the hole (found by fuzz_mesh).
  Plc plc;
  plc.points = {0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.2, 0.8, 0.2, 0.8, 0.8, 0.2, 0.8};
  plc.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  ruppert_test::addCircle(plc, 0.5, 0.5, 0.1);
  plc.holes = {0.3, 0.3, 0.5, 0.5};
  for (const bool jettison : {false, true}) {
    Options o;
    o.minAngle = 30, o.jettison = jettison;
    const Mesh mesh = ruppert::triangulate(plc, o);
    INFO("jettison " << jettison);
    REQUIRE(mesh.complete);
    ruppert_test::ValidateOptions v;
    // With jettison the output renumbers the input's points, which the validator's input checks
    // do not follow; then no point at all may be Unused.
    v.input = jettison ? nullptr : &plc, v.minAngle = 30;
    REQUIRE_VALID(mesh, v);
    if (jettison)
      for (std::uint8_t kind : mesh.vertexKinds) CHECK(kind != static_cast<std::uint8_t>(ruppert::VertexKind::Unused));
    for (std::size_t k = 0; k < mesh.segmentIds.size(); ++k) CHECK(mesh.segmentIds[k] < 8);
  }
}

TEST_CASE("a curve and a hull edge between the same two points: shells from the nearer end", "[curves]") {
  // A Bezier from (1, 35) to (0, 0) that meets the hull edge between them at 1.5 degrees at (1, 35)
  // (found by fuzz_mesh). Its shortest edges near (1, 35) are seditious or not by their distances
  // from (1, 35); from (0, 0) any two nearby vertices look like one shell, and a 29.56-degree
  // triangle was left as seditious in a mesh called complete.
  CurvedShape shape;
  shape.plc.points = {0, 0, 1, 35};
  ruppert::Curve c;
  c.type = ruppert::CurveType::Bezier, c.from = 1, c.to = 0;
  c.controls[0] = c.controls[1] = c.controls[2] = c.controls[3] = -1;
  shape.plc.curves.push_back(c);
  Options o;
  o.minAngle = 30, o.curveTolerance = 0.0010685511108405516, o.maxSteiner = 1000;
  const Mesh mesh = ruppert::triangulate(shape.plc, o);
  REQUIRE(mesh.complete);
  ruppert_test::ValidateOptions v;
  v.input = &shape.plc, v.minAngle = 30;
  v.angleExempt = ruppert_test::chapterExemptions(mesh, shape.plc);
  REQUIRE_VALID(mesh, v);
}

TEST_CASE("curve pieces carry their curve's segmentId and marker", "[curves]") {
  CurvedShape shape = ruppert_test::quarterDisk();
  shape.plc.curves[0].marker = 7;
  const Mesh mesh = ruppert::triangulate(shape.plc, Options{});
  std::size_t pieces = 0;
  for (std::size_t k = 0; k < mesh.segmentIds.size(); ++k) {
    CHECK(mesh.segmentIds[k] >= 0);
    CHECK(mesh.segmentIds[k] <= 2);
    if (mesh.segmentIds[k] != 2) continue;
    ++pieces;
    CHECK(mesh.segmentMarkers[k] == 7);
  }
  CHECK(pieces >= 6);
}

TEST_CASE("bad curves are refused with the curve named", "[curves][errors]") {
  auto refused = [](Plc plc, ruppert::ErrorCode code, const std::string& words) {
    try {
      ruppert::triangulate(plc, Options{});
      FAIL("no error");
    } catch (const ruppert::Error& e) {
      INFO(e.what());
      CHECK(e.code() == code);
      CHECK(std::string(e.what()).find(words) != std::string::npos);
    }
  };
  const Plc quarter = ruppert_test::quarterDisk().plc;
  Plc p = quarter;
  p.curves[0].to = 9;
  refused(p, ruppert::ErrorCode::IndexOutOfRange, "curve 0: to = 9");
  p = quarter, p.curves[0].center[0] = 0.01;
  refused(p, ruppert::ErrorCode::MalformedInput, "curve 0: from and to lie at distances");
  p = quarter, p.curves[0].type = ruppert::CurveType::Bezier, p.curves[0].controls[1] = NAN;
  refused(p, ruppert::ErrorCode::NonFiniteCoordinate, "curve 0: a control coordinate");
  p = quarter, p.curves[0].type = static_cast<ruppert::CurveType>(7);
  refused(p, ruppert::ErrorCode::MalformedInput, "curve 0: unknown type");
  p = quarter, p.curves[0].to = 1;
  refused(p, ruppert::ErrorCode::MalformedInput, "curve 0: from and to are the same point");
  // Two points at one place are merged into one: a curve between them is closed too (fuzz_mesh).
  p = quarter, p.points.insert(p.points.end(), {1, 0}), p.curves[0].to = 3;
  refused(p, ruppert::ErrorCode::MalformedInput, "curve 0: from = 1 and to = 3 lie at the same place (1, 0)");
  // The input's own checks come before the pieces' points are appended: a segment's index past the
  // points would otherwise name one of them (fuzz_mesh).
  REQUIRE(quarter.points.size() == 6);
  p = quarter, p.segments.back() = 3;
  refused(p, ruppert::ErrorCode::IndexOutOfRange, "refers to point 3 but there are 3 points");
  p = quarter, p.points.push_back(2);
  refused(p, ruppert::ErrorCode::MalformedInput, "points has odd length 7");
  // Markers one per point and per segment, or none: the pieces' points take theirs after the input's.
  p = quarter, p.pointMarkers = {1};
  refused(p, ruppert::ErrorCode::MalformedInput, "pointMarkers has length 1 for 3 points");
  p = quarter, p.segmentMarkers = {1, 2, 3};
  refused(p, ruppert::ErrorCode::MalformedInput, "segmentMarkers has length 3 for 2 segments");
  // A segment across the arc, and a second arc crossing the first.
  p = quarter, p.points.insert(p.points.end(), {0.5, 0.5, 1, 1}), p.segments.insert(p.segments.end(), {3, 4});
  refused(p, ruppert::ErrorCode::MalformedInput, "curve 0 crosses or touches segment 2");
  p = quarter, p.points.insert(p.points.end(), {1, 1, 0.2, 0.2});
  ruppert::Curve crossing;
  crossing.from = 3, crossing.to = 4, crossing.center[0] = 1, crossing.center[1] = 0.2;
  p.curves.push_back(crossing);
  refused(p, ruppert::ErrorCode::MalformedInput, "crosses or touches curve");
  // A cubic that loops over itself.
  p = ruppert_test::underBezier(1).plc;
  const double loop[4] = {-1, 1, 2, 1};
  std::copy(loop, loop + 4, p.curves[0].controls);
  refused(p, ruppert::ErrorCode::MalformedInput, "curve 0 crosses itself");
}

TEST_CASE("curves are read from JSON and refused there with their path", "[curves][io]") {
  const Plc plc = ruppert::parseJson(R"({"points": [0,0, 1,0, 0,1], "segments": [0,1, 2,0],
    "curves": [{"type": "arc", "from": 1, "to": 2, "center": [0, 0], "marker": 3},
               {"type": "bezier", "from": 2, "to": 1, "controls": [0.5, 2, 2, 0.5]}]})");
  REQUIRE(plc.curves.size() == 2);
  CHECK(plc.curves[0].type == ruppert::CurveType::Arc);
  CHECK(plc.curves[0].marker == 3);
  CHECK(plc.curves[1].type == ruppert::CurveType::Bezier);
  CHECK(plc.curves[1].controls[1] == 2);
  for (const char* bad : {R"({"points": [0,0, 1,0], "curves": [{"type": "spline", "from": 0, "to": 1}]})",
                          R"({"points": [0,0, 1,0], "curves": [{"type": "arc", "from": 0, "to": 1}]})",
                          R"({"points": [0,0, 1,0], "curves": [{"type": "arc", "to": 1, "center": [0, 0]}]})",
                          R"({"points": [0,0, 1,0], "curves": [{"type": "arc", "from": -1, "to": 1, "center": [0, 0]}]})"}) {
    INFO(bad);
    CHECK_THROWS_WITH(ruppert::parseJson(bad), Catch::Contains("curves[0]"));
  }
}
