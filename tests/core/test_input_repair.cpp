// Input repair and input errors: what the mesher fixes (with a notice naming the items) and what it
// rejects (with an ErrorCode and a message naming the item).
#include <catch2/catch.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "plc_generators.h"
#include "validator.h"

using namespace ruppert_test;
using ruppert::ErrorCode;
using ruppert::Mesh;
using ruppert::NoticeKind;
using ruppert::Plc;
using ruppert::VertexKind;

namespace {

ruppert::Options cdtOptions() {
  ruppert::Options o;
  o.minAngle = 0;
  return o;
}

Mesh cdt(const Plc& plc, const ruppert::Options& o = cdtOptions()) { return ruppert::triangulate(plc, o); }

// Square [0,s]^2 as points 0..3 and segments 0..3 (segment i runs from point i to point i+1).
Plc square(double s = 2) {
  Plc plc;
  plc.points = {0, 0, s, 0, s, s, 0, s};
  plc.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  return plc;
}

std::uint32_t addPoint(Plc& plc, double x, double y) {
  plc.points.insert(plc.points.end(), {x, y});
  return std::uint32_t(plc.points.size() / 2 - 1);
}

std::uint32_t addSegment(Plc& plc, double ax, double ay, double bx, double by) {
  const std::uint32_t a = addPoint(plc, ax, ay), b = addPoint(plc, bx, by);
  plc.segments.insert(plc.segments.end(), {a, b});
  return std::uint32_t(plc.segments.size() / 2 - 1);
}

ValidateOptions against(const Plc& plc, double area = -1) {
  ValidateOptions v;
  v.input = &plc;
  v.expectedArea = area;
  v.expectNoSteiner = true;
  return v;
}

std::string noticeList(const Mesh& m) {
  std::string text = std::to_string(m.notices.size()) + " notice(s)";
  for (const auto& n : m.notices)
    text += "\n  kind " + std::to_string(int(n.kind)) + " a=" + std::to_string(n.a) + " b=" + std::to_string(n.b) +
            ": " + n.message;
  return text;
}

const ruppert::Notice* findNotice(const Mesh& m, NoticeKind kind) {
  for (const auto& n : m.notices)
    if (n.kind == kind) return &n;
  return nullptr;
}

std::size_t countNotices(const Mesh& m, NoticeKind kind) {
  std::size_t count = 0;
  for (const auto& n : m.notices) count += n.kind == kind;
  return count;
}

// `number` occurs in text as a whole number (not as part of a longer number).
bool mentionsNumber(const std::string& text, const std::string& number) {
  for (std::size_t at = text.find(number); at != std::string::npos; at = text.find(number, at + 1)) {
    const bool before = at > 0 && (std::isdigit((unsigned char)text[at - 1]) || text[at - 1] == '.');
    const std::size_t end = at + number.size();
    const bool after = end < text.size() && (std::isdigit((unsigned char)text[end]) ||
                                             (text[end] == '.' && end + 1 < text.size() && std::isdigit((unsigned char)text[end + 1])));
    if (!before && !after) return true;
  }
  return false;
}

bool mentionsWord(std::string text, const std::string& lowerWord) {
  for (char& c : text) c = char(std::tolower((unsigned char)c));
  return text.find(lowerWord) != std::string::npos;
}

// Runs triangulate and returns the Error it threw; fails the test if it did not throw one.
ruppert::Error expectError(const Plc& plc, const ruppert::Options& o = cdtOptions()) {
  try {
    const Mesh mesh = ruppert::triangulate(plc, o);
    FAIL("expected ruppert::Error, got a mesh with " << mesh.triangles.size() / 3 << " triangles");
  } catch (const ruppert::Error& e) {
    INFO("code " << ruppert::errorCodeName(e.code()) << ": " << e.what());
    CHECK(std::string(e.what()).size() > 0);
    return e;
  }
  return ruppert::Error(ErrorCode::Internal, "unreachable");
}

std::size_t usedVerticesAt(const Mesh& m, double x, double y, double radius) {
  std::vector<bool> used(m.points.size() / 2, false);
  for (std::uint32_t v : m.triangles) used[v] = true;
  std::size_t count = 0;
  for (std::size_t v = 0; v < used.size(); ++v)
    count += used[v] && std::hypot(m.points[2 * v] - x, m.points[2 * v + 1] - y) <= radius;
  return count;
}

}  // namespace

TEST_CASE("duplicate points are merged with a notice", "[repair]") {
  Plc plc = square();
  const std::uint32_t dup = addPoint(plc, 2, 2);  // same as point 2
  const Mesh mesh = cdt(plc);
  INFO(noticeList(mesh));
  REQUIRE_VALID(mesh, against(plc, 4.0));
  const auto* n = findNotice(mesh, NoticeKind::DuplicatePoint);
  REQUIRE(n != nullptr);
  CHECK(n->a == dup);
  CHECK(n->b == 2);
  CHECK(mentionsNumber(n->message, std::to_string(dup)));
  CHECK(mesh.vertexKinds[dup] == std::uint8_t(VertexKind::Unused));
  CHECK(mesh.triangles.size() / 3 == 2);

  SECTION("a segment that refers to the duplicate uses the merged point") {
    plc.segments[4] = dup;  // segment 2 now runs from the duplicate of point 2 to point 3
    const Mesh merged = cdt(plc);
    INFO(noticeList(merged));
    REQUIRE_VALID(merged, against(plc, 4.0));
    CHECK(countNotices(merged, NoticeKind::DuplicatePoint) == 1);
  }
}

// Every point given twice (the copies after all originals, in reverse order, and the boundary's
// segments drawn between copies): the same mesh as the points given once, refinement included, and
// one notice per copy, in input order, naming the copy and its original.
TEST_CASE("points given twice mesh as given once, with a notice per copy", "[repair]") {
  const Plc once = randomPointsInSquare(11, 3000).plc;
  const std::uint32_t n = static_cast<std::uint32_t>(once.points.size() / 2);
  Plc twice = once;
  for (std::uint32_t i = n; i-- > 0;) addPoint(twice, once.points[2 * i], once.points[2 * i + 1]);
  const auto copyOf = [n](std::uint32_t i) { return 2 * n - 1 - i; };
  for (std::uint32_t& v : twice.segments) v = copyOf(v);
  for (double angle : {0.0, 30.0}) {
    ruppert::Options o;
    o.minAngle = angle;
    const Mesh a = ruppert::triangulate(once, o), b = ruppert::triangulate(twice, o);
    REQUIRE_VALID(b);
    // Steiner vertices are numbered after the input points: compare corners, not indices.
    const auto corners = [](const Mesh& m, const std::vector<std::uint32_t>& ids) {
      std::vector<double> xy;
      for (std::uint32_t v : ids) xy.push_back(m.points[2 * v]), xy.push_back(m.points[2 * v + 1]);
      return xy;
    };
    CHECK(a.triangles.size() == b.triangles.size());
    CHECK(corners(a, a.triangles) == corners(b, b.triangles));
    CHECK(corners(a, a.segments) == corners(b, b.segments));
    CHECK(a.segmentIds == b.segmentIds);
    REQUIRE(countNotices(b, NoticeKind::DuplicatePoint) == n);
    std::uint32_t k = 0;
    for (const auto& notice : b.notices) {
      if (notice.kind != NoticeKind::DuplicatePoint) continue;
      const std::uint32_t copy = n + k++, original = copyOf(copy);
      REQUIRE(notice.a == copy);
      REQUIRE(notice.b == original);
      REQUIRE(notice.x == once.points[2 * original]);
      REQUIRE(notice.y == once.points[2 * original + 1]);
      REQUIRE(mentionsNumber(notice.message, std::to_string(copy)));
      REQUIRE(mentionsNumber(notice.message, std::to_string(original)));
      REQUIRE(b.vertexKinds[copy] == std::uint8_t(VertexKind::Unused));
    }
  }
}

TEST_CASE("zero-length segments are dropped with a notice", "[repair]") {
  Plc plc = square();
  plc.segments.insert(plc.segments.end(), {1, 1});  // segment 4
  const Mesh mesh = cdt(plc);
  INFO(noticeList(mesh));
  REQUIRE_VALID(mesh, against(plc, 4.0));
  const auto* n = findNotice(mesh, NoticeKind::ZeroLengthSegment);
  REQUIRE(n != nullptr);
  CHECK(n->a == 4);
  CHECK(mentionsNumber(n->message, "4"));

  SECTION("a segment between a point and its duplicate has zero length too") {
    Plc two = square();
    const std::uint32_t dup = addPoint(two, 0, 0);
    two.segments.insert(two.segments.end(), {0, dup});  // segment 4
    const Mesh m2 = cdt(two);
    INFO(noticeList(m2));
    REQUIRE_VALID(m2, against(two, 4.0));
    CHECK(findNotice(m2, NoticeKind::DuplicatePoint) != nullptr);
    const auto* z = findNotice(m2, NoticeKind::ZeroLengthSegment);
    REQUIRE(z != nullptr);
    CHECK(z->a == 4);
  }
}

TEST_CASE("duplicate segments are dropped with a notice naming both", "[repair]") {
  Plc plc = square();
  plc.segments.insert(plc.segments.end(), {2, 1});  // segment 4 = segment 1 reversed
  plc.segments.insert(plc.segments.end(), {3, 0});  // segment 5 = segment 3, same direction
  const Mesh mesh = cdt(plc);
  INFO(noticeList(mesh));
  REQUIRE_VALID(mesh, against(plc, 4.0));
  REQUIRE(countNotices(mesh, NoticeKind::DuplicateSegment) == 2);
  for (const auto& n : mesh.notices) {
    if (n.kind != NoticeKind::DuplicateSegment) continue;
    CHECK(((n.a == 4 && n.b == 1) || (n.a == 5 && n.b == 3)));
    CHECK(mentionsNumber(n.message, std::to_string(n.a)));
    CHECK(mentionsNumber(n.message, std::to_string(n.b)));
  }
  // The remaining copy carries the constraint: every subsegment belongs to segment 0..3.
  for (std::int32_t id : mesh.segmentIds) CHECK((id >= 0 && id <= 3));
}

TEST_CASE("a vertex in a segment's interior splits the segment", "[repair]") {
  Plc plc = square();
  const std::uint32_t p = addPoint(plc, 1, 0);  // inside segment 0 = (0,0)-(2,0)
  const Mesh mesh = cdt(plc);
  INFO(noticeList(mesh));
  REQUIRE_VALID(mesh, against(plc, 4.0));
  const auto* n = findNotice(mesh, NoticeKind::VertexOnSegment);
  REQUIRE(n != nullptr);
  CHECK(n->a == 0);
  CHECK(n->b == p);
  CHECK(mentionsNumber(n->message, std::to_string(p)));
  CHECK(mesh.vertexKinds[p] == std::uint8_t(VertexKind::Input));
  std::size_t pieces = 0;
  for (std::size_t k = 0; k < mesh.segmentIds.size(); ++k)
    if (mesh.segmentIds[k] == 0) {
      ++pieces;
      CHECK((mesh.segments[2 * k] == p || mesh.segments[2 * k + 1] == p));
    }
  CHECK(pieces == 2);
}

TEST_CASE("two crossing segments are split at an intersection vertex", "[repair]") {
  SECTION("crossing at an exactly representable point") {
    Plc plc = square();
    const std::uint32_t s0 = addSegment(plc, 0.5, 0.5, 1.5, 1.5);
    const std::uint32_t s1 = addSegment(plc, 0.5, 1.5, 1.5, 0.5);
    const Mesh mesh = cdt(plc);
    INFO(noticeList(mesh));
    REQUIRE_VALID(mesh, against(plc, 4.0));
    const auto* n = findNotice(mesh, NoticeKind::SegmentsCross);
    REQUIRE(n != nullptr);
    CHECK(((n->a == s0 && n->b == s1) || (n->a == s1 && n->b == s0)));
    CHECK(n->x == 1.0);
    CHECK(n->y == 1.0);
    CHECK(mentionsNumber(n->message, std::to_string(s0)));
    CHECK(mentionsNumber(n->message, std::to_string(s1)));
    std::size_t intersections = 0;
    for (std::size_t v = plc.points.size() / 2; v < mesh.vertexKinds.size(); ++v)
      if (mesh.vertexKinds[v] == std::uint8_t(VertexKind::Intersection)) {
        ++intersections;
        CHECK(mesh.points[2 * v] == 1.0);
        CHECK(mesh.points[2 * v + 1] == 1.0);
      }
    CHECK(intersections == 1);
    CHECK(mesh.stats.intersectionVertices == 1);
  }
  SECTION("crossing at a point that doubles cannot represent") {
    Plc plc = square();
    addSegment(plc, 0.1, 0.2, 1.7, 1.3);
    addSegment(plc, 0.3, 1.9, 1.6, 0.15);
    const Mesh mesh = cdt(plc);
    INFO(noticeList(mesh));
    REQUIRE_VALID(mesh, against(plc, 4.0));
    const auto* n = findNotice(mesh, NoticeKind::SegmentsCross);
    REQUIRE(n != nullptr);
    // Intersection of the two lines, solved in long double as an independent reference.
    const long double ax = 0.1L, ay = 0.2L, bx = 1.7L, by = 1.3L, cx = 0.3L, cy = 1.9L, dx = 1.6L, dy = 0.15L;
    const long double den = (bx - ax) * (dy - cy) - (by - ay) * (dx - cx);
    const long double t = ((cx - ax) * (dy - cy) - (cy - ay) * (dx - cx)) / den;
    const double ix = double(ax + t * (bx - ax)), iy = double(ay + t * (by - ay));
    CHECK(std::fabs(n->x - ix) < 1e-12);
    CHECK(std::fabs(n->y - iy) < 1e-12);
    CHECK(usedVerticesAt(mesh, ix, iy, 1e-12) == 1);
  }
}

TEST_CASE("three and four segments crossing at one point make one vertex", "[repair]") {
  for (int count : {3, 4}) {
    INFO(count << " segments through (1, 1)");
    Plc plc = square();
    addSegment(plc, 0.5, 0.5, 1.5, 1.5);
    addSegment(plc, 0.5, 1.5, 1.5, 0.5);
    addSegment(plc, 1, 0.25, 1, 1.75);
    if (count == 4) addSegment(plc, 0.25, 1, 1.75, 1);
    const Mesh mesh = cdt(plc);
    INFO(noticeList(mesh));
    REQUIRE_VALID(mesh, against(plc, 4.0));
    CHECK(findNotice(mesh, NoticeKind::SegmentsCross) != nullptr);
    CHECK(usedVerticesAt(mesh, 1, 1, 0) == 1);
    CHECK(usedVerticesAt(mesh, 1, 1, 1e-9) == 1);  // no near-duplicate intersection vertices
    // 2 * count spokes meet at the center.
    std::size_t around = 0;
    for (std::uint32_t v : mesh.triangles) around += mesh.points[2 * v] == 1 && mesh.points[2 * v + 1] == 1;
    CHECK(around >= std::size_t(2 * count));
  }
}

TEST_CASE("three segments crossing at a point doubles cannot represent make one vertex", "[repair]") {
  // All three pass through (4/3, 2/3).
  Plc plc = square(4);
  addSegment(plc, 0.5, 0.25, 1.8, 0.9);
  addSegment(plc, 1.8, 0.2, 0.4, 1.6);
  addSegment(plc, 1.1, 0.2, 1.9, 1.8);
  const Mesh mesh = cdt(plc);
  INFO(noticeList(mesh));
  REQUIRE_VALID(mesh, against(plc, 16.0));
  CHECK(usedVerticesAt(mesh, 4.0 / 3, 2.0 / 3, 1e-9) == 1);
}

TEST_CASE("a duplicate segment crossed at a point doubles cannot represent", "[repair]") {
  // tests/fixtures/duplicate-segment-crossed-inexactly.poly: segment 6 is segment 4 reversed, and
  // segment 5 (a diagonal of the square) crosses both at (4/3, 2/3).
  Plc plc = square(2);
  addPoint(plc, 1, 0);  // point 4, inside segment 0
  plc.segments.insert(plc.segments.end(), {4, 2, 3, 1, 2, 4});
  const Mesh mesh = cdt(plc);
  INFO(noticeList(mesh));
  REQUIRE_VALID(mesh, against(plc, 4.0));
  const auto* n = findNotice(mesh, NoticeKind::DuplicateSegment);
  REQUIRE(n != nullptr);
  CHECK(n->a == 6);
  CHECK(n->b == 4);
  CHECK(usedVerticesAt(mesh, 4.0 / 3, 2.0 / 3, 1e-9) == 1);
}

// Clusters of segments 10 to 10^10 times shorter than the domain, crossing each other among input
// points as little as 10^5 ulps apart: crossing repair used to bend chains through their neighbors
// on a tenth of these (and stop with "too many crossing repairs" on smaller clusters), and an
// intermediate version looped. Options vary with the input (angle, placement, convex hull, budget).
// Smaller clusters mesh without error too (a scratch sweep down to 1e-19), but there the validator's
// tolerance (64 ulps) is as wide as their features and it cannot tell a covered segment from not.
TEST_CASE("random clusters of tiny crossing segments are meshed validly", "[repair]") {
  using ruppert::Placement;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    const Plc plc = crossingClusters(seed, 10).plc;
    ruppert::Options o;
    o.minAngle = std::vector<double>{0, 20, 30, 34}[seed % 4];
    o.placement = std::vector<Placement>{Placement::Optimal, Placement::OffCenter, Placement::Circumcenter,
                                         Placement::Petal}[seed / 4 % 4];
    o.convexHull = seed / 12 % 3 == 0;
    o.autoHoles = true;
    o.maxSteiner = std::vector<std::uint64_t>{0, 10, 2000}[seed / 36 % 3];
    INFO("seed " << seed << ", angle " << o.minAngle << ", placement " << int(o.placement) << ", hull "
                 << o.convexHull << ", budget " << o.maxSteiner);
    Mesh mesh;
    REQUIRE_NOTHROW(mesh = ruppert::triangulate(plc, o));
    ValidateOptions v;
    v.input = &plc;
    const auto problems = validateMesh(mesh, v);
    INFO(describeProblems(problems));
    REQUIRE(problems.empty());
  }
}

TEST_CASE("overlapping collinear segments are merged with a notice", "[repair]") {
  Plc plc = square(4);
  const std::uint32_t s0 = addSegment(plc, 1, 1, 3, 1);
  const std::uint32_t s1 = addSegment(plc, 2, 1, 3.5, 1);  // shares [2, 3] with s0
  const Mesh mesh = cdt(plc);
  INFO(noticeList(mesh));
  REQUIRE_VALID(mesh, against(plc, 16.0));
  const auto* n = findNotice(mesh, NoticeKind::SegmentsOverlap);
  REQUIRE(n != nullptr);
  CHECK(((n->a == s0 && n->b == s1) || (n->a == s1 && n->b == s0)));

  SECTION("one segment inside another") {
    Plc inside = square(4);
    addSegment(inside, 1, 1, 3, 1);
    addSegment(inside, 1.5, 1, 2.5, 1);
    const Mesh m2 = cdt(inside);
    INFO(noticeList(m2));
    REQUIRE_VALID(m2, against(inside, 16.0));
    CHECK(!m2.notices.empty());
  }
}

TEST_CASE("hole seeds outside the domain or on a segment", "[repair]") {
  SECTION("outside: a notice, nothing removed") {
    Plc plc = square(1);
    plc.holes = {5, 5};
    const Mesh mesh = cdt(plc);
    INFO(noticeList(mesh));
    REQUIRE_VALID(mesh, against(plc, 1.0));
    const auto* n = findNotice(mesh, NoticeKind::HoleOutsideDomain);
    REQUIRE(n != nullptr);
    CHECK(n->a == 0);
  }
  SECTION("exactly on a segment: HoleOnSegment naming the hole") {
    Plc plc = square(1);
    plc.holes = {7, 7, 0.375, 0};  // hole 1 lies on segment 0
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::HoleOnSegment);
    CHECK(mentionsNumber(e.what(), "1"));
    CHECK(mentionsWord(e.what(), "hole"));
  }
  SECTION("exactly on a vertex: HoleOnSegment") {
    Plc plc = square(1);
    plc.holes = {1, 1};
    CHECK(expectError(plc).code() == ErrorCode::HoleOnSegment);
  }
  SECTION("inside an open inner polyline, reaching everything: EmptyDomain naming the hole") {
    Plc plc;
    plc.points = {0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 6, 4, 4, 6};
    plc.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 4};
    plc.holes = {5, 5};
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::EmptyDomain);
    CHECK(mentionsWord(e.what(), "holes[0]"));
    CHECK(std::string(e.what()).find("only region the segments enclose") != std::string::npos);
  }
  SECTION("inside the only closed polygon: the message says so, not that the boundary is open") {
    Plc plc = square(1);
    plc.holes = {0.5, 0.5};
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::EmptyDomain);
    INFO(e.what());
    CHECK(std::string(e.what()).find("only region the segments enclose") != std::string::npos);
    CHECK(std::string(e.what()).find("not closed") == std::string::npos);
  }
  SECTION("among segments that enclose nothing: the hull is the hole's region") {
    Plc plc;
    plc.points = {0, 0, 10, 0, 10, 10, 0, 10};
    plc.segments = {0, 1, 1, 2};
    plc.holes = {5, 5};
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::EmptyDomain);
    INFO(e.what());
    CHECK(std::string(e.what()).find("enclose no region") != std::string::npos);
  }
}

TEST_CASE("non-finite coordinates are rejected naming the item", "[repair]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  SECTION("NaN in a point") {
    Plc plc = square();
    addPoint(plc, 0.5, 0.5);
    addPoint(plc, 1.5, nan);  // point 5
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::NonFiniteCoordinate);
    CHECK(mentionsNumber(e.what(), "5"));
    CHECK(mentionsWord(e.what(), "point"));
  }
  SECTION("-Inf in a point") {
    Plc plc = square();
    plc.points[6] = -inf;  // point 3's x
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::NonFiniteCoordinate);
    CHECK(mentionsNumber(e.what(), "3"));
  }
  SECTION("Inf in a hole seed") {
    Plc plc = square();
    plc.holes = {1, 1, 3, 3, inf, 0};  // hole 2
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::NonFiniteCoordinate);
    CHECK(mentionsNumber(e.what(), "2"));
    CHECK(mentionsWord(e.what(), "hole"));
  }
  SECTION("NaN in a region seed") {
    Plc plc = square();
    plc.regions.push_back({nan, 1, 1, 0});
    const auto e = expectError(plc);
    CHECK(e.code() == ErrorCode::NonFiniteCoordinate);
    CHECK(mentionsWord(e.what(), "region"));
  }
}

TEST_CASE("segment indices out of range are rejected naming segment and index", "[repair]") {
  Plc plc = square();
  addPoint(plc, 1, 1);
  plc.segments.insert(plc.segments.end(), {1, 17});  // segment 4 refers to point 17 of 5
  const auto e = expectError(plc);
  CHECK(e.code() == ErrorCode::IndexOutOfRange);
  CHECK(mentionsNumber(e.what(), "4"));
  CHECK(mentionsNumber(e.what(), "17"));
  CHECK(mentionsWord(e.what(), "segment"));
  CHECK(std::string(ruppert::errorCodeName(e.code())) == "INDEX_OUT_OF_RANGE");
}

TEST_CASE("empty and degenerate inputs are rejected", "[repair]") {
  SECTION("no points") {
    CHECK(expectError(Plc{}).code() == ErrorCode::EmptyInput);
  }
  SECTION("all points equal") {
    Plc plc;
    plc.points = {3, 4, 3, 4, 3, 4, 3, 4};
    CHECK(expectError(plc).code() == ErrorCode::DegenerateInput);
  }
  SECTION("two distinct points") {
    Plc plc;
    plc.points = {0, 0, 1, 1};
    plc.segments = {0, 1};
    CHECK(expectError(plc).code() == ErrorCode::DegenerateInput);
  }
  SECTION("all points collinear, with segments") {
    Plc plc;
    for (int i = 0; i < 10; ++i) plc.points.insert(plc.points.end(), {0.5 * i, 0.25 * i});
    plc.segments = {0, 9};
    CHECK(expectError(plc).code() == ErrorCode::DegenerateInput);
  }
}

TEST_CASE("invalid options are rejected naming the option", "[repair]") {
  const Plc plc = square();
  SECTION("negative maxArea") {
    auto o = cdtOptions();
    o.maxArea = -1;
    const auto e = expectError(plc, o);
    CHECK(e.code() == ErrorCode::InvalidOption);
    CHECK(mentionsWord(e.what(), "area"));
  }
  SECTION("minAngle above 60") {
    auto o = cdtOptions();
    o.minAngle = 61;
    const auto e = expectError(plc, o);
    CHECK(e.code() == ErrorCode::InvalidOption);
    CHECK(mentionsWord(e.what(), "angle"));
  }
  SECTION("minAngle just outside the option table's range, in a message stating that range") {
    using Angle = ruppert::option::minAngle;
    const auto text = [](double v) {
      char s[32];
      std::snprintf(s, sizeof s, "%g", v);
      return std::string(s);
    };
    for (double bad : {Angle::low - 1, Angle::high + 1}) {
      auto o = cdtOptions();
      o.minAngle = bad;
      const auto e = expectError(plc, o);
      CHECK(e.code() == ErrorCode::InvalidOption);
      CHECK(std::string(e.what()) == std::string(Angle::key) + " = " + text(bad) + " is outside [" + text(Angle::low) +
                                         ", " + text(Angle::high) + "] " + Angle::unit);
    }
  }
  SECTION("negative or NaN minAngle") {
    for (double bad : {-1.0, std::numeric_limits<double>::quiet_NaN()}) {
      auto o = cdtOptions();
      o.minAngle = bad;
      CHECK(expectError(plc, o).code() == ErrorCode::InvalidOption);
    }
  }
}

TEST_CASE("coordinates beyond the predicates' dynamic range are rejected or meshed validly", "[repair]") {
  // 1e300 and 1e-300 in one input: no power-of-two scaling brings both into the safe range.
  Plc plc;
  plc.points = {0, 0, 1e300, 0, 0, 1e300, 1e-300, 1e-300};
  try {
    const Mesh mesh = cdt(plc);
    ValidateOptions v;
    v.input = &plc;
    CHECK_VALID(mesh, v);
  } catch (const ruppert::Error& e) {
    INFO(e.what());
    CHECK(e.code() == ErrorCode::CoordinateRange);
  }
}
