// Readers and writers: Triangle's .node/.poly/.ele, JSON, SVG.
//
// The writer tests build a small mesh by hand so they test only the writers, not the mesher.
// Real inputs: every .poly in the shared data folder (../shared/data) is read and its counts are
// compared with the README table there (an independent record of each file's contents).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ruppert/ruppert.h"

using ruppert::ErrorCode;

namespace {

#ifdef RUPPERT_FIXTURES
const std::string kFixtures = std::string(RUPPERT_FIXTURES) + "/io/";
#else
const std::string kFixtures = "tests/fixtures/io/";
#endif

ruppert::Plc poly(const std::string& text, const std::string& name = "t.poly") {
  std::istringstream in(text);
  return ruppert::readPoly(in, name);
}
ruppert::Plc node(const std::string& text) {
  std::istringstream in(text);
  return ruppert::readNode(in, "t.node");
}
ruppert::Plc json(const std::string& text) {
  std::istringstream in(text);
  return ruppert::readJson(in, "t.json");
}

// The ruppert::Error that f throws; fails the test if it throws nothing or something else.
ruppert::Error errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ruppert::Error& e) {
    return e;
  }
  FAIL("expected a ruppert::Error");
  throw std::logic_error("unreachable");
}

// Bitwise equality, so -0.0 vs 0.0 and the last ulp both count.
bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

const char* kSquare =
    "4 2 0 0\n"
    "1 0 0\n"
    "2 1 0\n"
    "3 1 1\n"
    "4 0 1\n"
    "4 0\n"
    "1 1 2\n"
    "2 2 3\n"
    "3 3 4\n"
    "4 4 1\n"
    "0\n";

// A hand-built mesh: a square split into 4 triangles around an interior vertex, with coordinates that
// need all 17 digits (0.1 + 0.2, 1/3), a negative zero and tiny and huge magnitudes.
ruppert::Mesh handMesh(int indexBase) {
  ruppert::Mesh m;
  const double third = 1.0 / 3.0;
  m.points = {-0.0, 0.0, 1e-300 + 1.0, 0.1 + 0.2, 1.0, 1.0 + 1e-15, third, 1.0, 0.5, 0.5 - 1e-17 * 3};
  // Points 0..3 are the square's corners (counter-clockwise), 4 is inside.
  m.triangles = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  m.neighbors = {1, 3, ruppert::kNoNeighbor, 2, 0, ruppert::kNoNeighbor,
                 3, 1, ruppert::kNoNeighbor, 0, 2, ruppert::kNoNeighbor};
  m.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  m.segmentIds = {0, 1, ruppert::kNoInputSegment, 2};
  m.vertexKinds = {0, 0, 0, 0, 2};
  m.triangleAttributes = {0, 0, 0, 0};
  m.indexBase = indexBase;
  m.complete = false;
  m.reasons.push_back({ruppert::ReasonKind::SteinerBudget, 3, "budget \"100\" reached"});
  m.stats.vertices = 5;
  m.stats.triangles = 4;
  m.stats.minAngle = 28.5;
  m.stats.maxAngle = 95.25;
  m.stats.lfsIntegral = std::nan("");  // must never be printed as "nan"
  return m;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// .poly / .node reading
// ---------------------------------------------------------------------------------------------
TEST_CASE("readPoly reads a 1-based square and converts indices to 0-based", "[io]") {
  const ruppert::Plc p = poly(kSquare);
  CHECK(p.indexBase == 1);
  CHECK(p.points == std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1});
  CHECK(p.segments == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 0});
  CHECK(p.pointMarkers.empty());
  CHECK(p.segmentMarkers.empty());
  CHECK(p.holes.empty());
  CHECK(p.regions.empty());
}

TEST_CASE("readPoly: 0-based file with comments, attributes, markers, holes and regions", "[io]") {
  const ruppert::Plc p = ruppert::readFile(kFixtures + "zero-based-commented.poly");
  CHECK(p.indexBase == 0);
  REQUIRE(p.points.size() == 16);
  CHECK(p.points[2] == 4);  // point 1 x: the attribute 7.5 must not shift the fields
  CHECK(p.points[3] == 0);
  CHECK(p.points[14] == 1);  // point 7
  CHECK(p.points[15] == 3);
  CHECK(p.pointMarkers == std::vector<std::int32_t>{1, 2, 3, 4, 0, 0, 0, 0});
  CHECK(p.segments == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4});
  // The last segment line has no marker: Triangle reads that as 0.
  CHECK(p.segmentMarkers == std::vector<std::int32_t>{10, 20, 30, 40, 0, 0, 0, 0});
  CHECK(p.holes == std::vector<double>{2, 2});
  REQUIRE(p.regions.size() == 3);
  CHECK(p.regions[0].x == 0.5);
  CHECK(p.regions[0].y == 0.5);
  CHECK(p.regions[0].attribute == 1.5);
  CHECK(p.regions[0].maxArea == 0.25);
  CHECK(p.regions[1].attribute == 2);
  CHECK(p.regions[1].maxArea == 0);  // missing: no bound
  CHECK(p.regions[2].attribute == 3);
  CHECK(p.regions[2].maxArea == 0);  // negative: no bound
}

TEST_CASE("readPoly parses Fortran-style numbers exactly, including negative zero", "[io]") {
  const ruppert::Plc p = poly(
      "3 2 0 1\n"
      "1 0.418893E+02 -.000000E+00 101\n"
      "2 +1e-3 .5 0\n"
      "3 0x1p-2 7. 0\n"
      "0\n0\n");
  REQUIRE(p.points.size() == 6);
  CHECK(p.points[0] == 41.8893);
  CHECK(p.points[1] == 0);
  CHECK(std::signbit(p.points[1]));
  CHECK(p.points[2] == 0.001);
  CHECK(p.points[3] == 0.5);
  CHECK(p.points[4] == 0.25);
  CHECK(p.points[5] == 7);
  CHECK(p.pointMarkers == std::vector<std::int32_t>{101, 0, 0});
}

TEST_CASE("readPoly accepts CRLF, tabs, blank lines, and missing optional header fields and sections", "[io]") {
  const ruppert::Plc p = poly("# header\r\n\r\n3\r\n0\t0 0\r\n1\t1 0\r\n   \r\n2\t0 1\r\n3\r\n0 0 1\r\n1 1 2\r\n2 2 0\r\n");
  CHECK(p.indexBase == 0);
  CHECK(p.points.size() == 6);
  CHECK(p.segments == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 0});
  CHECK(p.holes.empty());  // no holes line at all
  CHECK(p.regions.empty());
}

TEST_CASE("readPoly ignores point numbers after the first (Triangle does)", "[io]") {
  const ruppert::Plc p = poly("3 2 0 0\n1 0 0\n1 1 0\n9 0 1\n1 0\n1 1 3\n0\n");
  CHECK(p.points == std::vector<double>{0, 0, 1, 0, 0, 1});
  CHECK(p.segments == std::vector<std::uint32_t>{0, 2});
}

TEST_CASE("readNode reads points only, with attributes and markers", "[io]") {
  const ruppert::Plc p = node("3 2 2 1\n0 1.5 2.5 9 9 4\n1 3 4 9 9 5\n2 5 6 9 9\n");
  CHECK(p.indexBase == 0);
  CHECK(p.points == std::vector<double>{1.5, 2.5, 3, 4, 5, 6});
  CHECK(p.pointMarkers == std::vector<std::int32_t>{4, 5, 0});
  CHECK(p.segments.empty());
}

TEST_CASE("readFile takes the points of a .poly declaring 0 points from the .node of the same name", "[io]") {
  const ruppert::Plc p = ruppert::readFile(kFixtures + "split-points.poly");
  CHECK(p.indexBase == 1);
  CHECK(p.points == std::vector<double>{0, 0, 2, 0, 2, 2, 0, 2});
  CHECK(p.pointMarkers == std::vector<std::int32_t>{5, 6, 7, 8});
  CHECK(p.segments == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 0});
  CHECK(p.holes.empty());
}

TEST_CASE("parsePolyWithNode takes the points of a .poly declaring 0 points from the .node text", "[io]") {
  const std::string poly = "# points live in the .node\n0 2 0 1\n2 0\n1 1 2\n2 2 3\n0\n";
  const std::string nodeText = "3 2 0 1\n1 0 0 5\n2 2 0 6\n3 0 2 7\n";
  const ruppert::Plc p = ruppert::parsePolyWithNode(poly, nodeText, "in.poly", "in.node");
  CHECK(p.indexBase == 1);
  CHECK(p.points == std::vector<double>{0, 0, 2, 0, 0, 2});
  CHECK(p.pointMarkers == std::vector<std::int32_t>{5, 6, 7});
  CHECK(p.segments == std::vector<std::uint32_t>{0, 1, 1, 2});
  // The .node's own errors name the .node; a segment past its points names the .poly.
  CHECK_THROWS_WITH(ruppert::parsePolyWithNode(poly, "3 2 0 1\n1 0 0\n", "in.poly", "in.node"),
                    Catch::Matchers::Contains("in.node:"));
  CHECK_THROWS_WITH(ruppert::parsePolyWithNode(poly, "1 2 0 0\n1 0 0\n", "in.poly", "in.node"),
                    Catch::Matchers::Contains("in.poly:"));
  // Without the .node text the message says what to pass.
  CHECK_THROWS_WITH(ruppert::parsePoly(poly, "in.poly"), Catch::Matchers::Contains("parsePoly(polyText, { node: nodeText })"));
}

TEST_CASE("readFile dispatches on the extension and reports unreadable files", "[io]") {
  CHECK(ruppert::readFile(kFixtures + "split-points.node").points.size() == 8);
  CHECK(ruppert::readFile(kFixtures + "square-with-hole.json").points.size() == 16);

  const ruppert::Error missing = errorOf([] { ruppert::readFile(kFixtures + "no-such-file.poly"); });
  CHECK(missing.code() == ErrorCode::IoError);
  CHECK_THAT(missing.what(), Catch::Contains("no-such-file.poly"));

  const ruppert::Error ext = errorOf([] { ruppert::readFile(kFixtures + "square.txt"); });
  CHECK(ext.code() == ErrorCode::IoError);
  CHECK_THAT(ext.what(), Catch::Contains("extension"));
}

TEST_CASE("readPoly errors name the file, line and field", "[io]") {
  SECTION("a segment with one endpoint") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2\n3 3 1\n0\n", "la.poly"); });
    CHECK(e.code() == ErrorCode::ParseError);
    CHECK(std::string(e.what()) == "la.poly:7: segment 2: expected 2 endpoint indices, found 1");
  }
  SECTION("an endpoint beyond the last point") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n2 2 12\n0\n"); });
    CHECK(e.code() == ErrorCode::IndexOutOfRange);
    CHECK_THAT(e.what(), Catch::StartsWith("t.poly:7: segment 2 refers to point 12 but there are 3 points"));
  }
  SECTION("index 0 in a 1-based file") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 0 2\n0\n"); });
    CHECK(e.code() == ErrorCode::IndexOutOfRange);
    CHECK_THAT(e.what(), Catch::Contains("segment 1 refers to point 0") && Catch::Contains("numbered from 1"));
  }
  SECTION("a negative endpoint") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 -1 2\n0\n"); });
    CHECK(e.code() == ErrorCode::IndexOutOfRange);
    CHECK_THAT(e.what(), Catch::Contains("refers to point -1"));
  }
  SECTION("a non-integer endpoint") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 1.5 2\n0\n"); });
    CHECK(e.code() == ErrorCode::ParseError);
    CHECK_THAT(e.what(), Catch::Contains("t.poly:6: segment 0: endpoint '1.5' is not an integer"));
  }
  SECTION("nan and inf are not coordinates") {
    const ruppert::Error nan = errorOf([] { poly("2 2 0 0\n1 0 0\n2 1 nan\n0 0\n"); });
    CHECK(nan.code() == ErrorCode::ParseError);
    CHECK(std::string(nan.what()) == "t.poly:3: point 2: y 'nan' is not a finite number");
    const ruppert::Error inf = errorOf([] { poly("2 2 0 0\n1 -inf 0\n2 1 1\n0 0\n"); });
    CHECK(std::string(inf.what()) == "t.poly:2: point 1: x '-inf' is not a finite number");
    const ruppert::Error overflow = errorOf([] { poly("2 2 0 0\n1 1e999 0\n2 1 1\n0 0\n"); });
    CHECK_THAT(overflow.what(), Catch::Contains("'1e999' is not a finite number"));
  }
  SECTION("trailing junk in a number") {
    const ruppert::Error e = errorOf([] { poly("2 2 0 0\n1 0 0\n2 1x 1\n0 0\n"); });
    CHECK(std::string(e.what()) == "t.poly:3: point 2: x '1x' is not a finite number");
  }
  SECTION("a point line with too few fields") {
    const ruppert::Error e = errorOf([] { poly("2 2 0 0\n1 0 0\n2 1\n0 0\n"); });
    CHECK(std::string(e.what()) == "t.poly:3: point 2: expected an index, x and y, found 2 fields");
    // The first point is named in the base it declares.
    const ruppert::Error first = errorOf([] { poly("2 2 0 0\n1 0\n2 1 1\n0 0\n"); });
    CHECK(std::string(first.what()) == "t.poly:2: point 1: expected an index, x and y, found 2 fields");
  }
  SECTION("the file ends inside the points") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n1 0 0\n2 1 0\n"); });
    CHECK(e.code() == ErrorCode::ParseError);
    CHECK_THAT(e.what(), Catch::Contains("expected point 3, found end of file"));
  }
  SECTION("the segment section is missing") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n# nothing else\n"); });
    CHECK_THAT(e.what(), Catch::Contains("expected the segment count line, found end of file"));
  }
  SECTION("dimension other than 2") {
    const ruppert::Error e = errorOf([] { poly("3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n0 0\n"); });
    CHECK(std::string(e.what()) == "t.poly:1: dimension must be 2, found '3'");
  }
  SECTION("marker count other than 0 or 1") {
    const ruppert::Error e = errorOf([] { poly("1 2 0 2\n1 0 0\n0 0\n"); });
    CHECK_THAT(e.what(), Catch::Contains("t.poly:1: number of point boundary markers must be 0 or 1"));
  }
  SECTION("a negative or non-numeric count") {
    CHECK_THAT(errorOf([] { poly("-3 2 0 0\n"); }).what(), Catch::Contains("point count '-3' is not a non-negative integer"));
    CHECK_THAT(errorOf([] { poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\nfour\n"); }).what(),
               Catch::Contains("t.poly:5: segment count 'four'"));
  }
  SECTION("the first point is numbered neither 0 nor 1") {
    const ruppert::Error e = errorOf([] { poly("2 2 0 0\n5 0 0\n6 1 0\n0 0\n"); });
    CHECK_THAT(e.what(), Catch::Contains("t.poly:2: first point: index '5' must be 0 or 1"));
  }
  SECTION("a region without its attribute") {
    const ruppert::Error e = errorOf([] { poly(std::string(kSquare) + "1\n1 0.5 0.5\n"); });
    CHECK(std::string(e.what()) == "t.poly:13: region 1: expected an index, x, y and attribute, found 3 fields");
  }
  SECTION("a hole with a bad coordinate") {
    const ruppert::Error e = errorOf([] { poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n0 0\n1\n0 0.2 zz\n"); });
    CHECK(std::string(e.what()) == "t.poly:7: hole 0: y 'zz' is not a finite number");
  }
  SECTION("text after the regions section") {
    const ruppert::Error e = errorOf([] { poly(std::string(kSquare) + "0\nextra\n"); });
    CHECK(std::string(e.what()) == "t.poly:13: unexpected 'extra' after the regions section");
  }
  SECTION("a .poly from a stream cannot fetch its .node") {
    const ruppert::Error e = errorOf([] { poly("0 2 0 0\n1 0\n1 1 2\n0\n", "x.poly"); });
    CHECK(e.code() == ErrorCode::ParseError);
    CHECK_THAT(e.what(), Catch::StartsWith("x.poly:1:") && Catch::Contains(".node"));
  }
  SECTION("readFile names the missing .node") {
    const std::string path = (std::filesystem::temp_directory_path() / "ruppert-io-orphan.poly").string();
    std::ofstream(path) << "0 2 0 0\n1 0\n1 1 2\n0\n";
    const ruppert::Error e = errorOf([&] { ruppert::readFile(path); });
    std::filesystem::remove(path);
    CHECK(e.code() == ErrorCode::IoError);
    CHECK_THAT(e.what(), Catch::Contains("ruppert-io-orphan.node"));
  }
}

TEST_CASE("readPoly rejects absurd counts before allocating", "[io]") {
  // 10^12 points would need terabytes; the check against the text length must fire first.
  const ruppert::Error points = errorOf([] { poly("1000000000000 2 0 0\n1 0 0\n"); });
  CHECK(points.code() == ErrorCode::TooLarge);
  CHECK_THAT(points.what(), Catch::StartsWith("t.poly:1: point count 1000000000000"));

  const ruppert::Error segments = errorOf([] { poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n999999999999 0\n1 1 2\n"); });
  CHECK(segments.code() == ErrorCode::TooLarge);
  CHECK_THAT(segments.what(), Catch::Contains("t.poly:5: segment count 999999999999"));

  const ruppert::Error holes = errorOf([] { poly(std::string("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n") + "77777777777\n"); });
  CHECK(holes.code() == ErrorCode::TooLarge);

  const ruppert::Error regions = errorOf([] { poly(std::string(kSquare) + "50\n1 0.5 0.5 1\n"); });
  CHECK(regions.code() == ErrorCode::TooLarge);
  CHECK_THAT(regions.what(), Catch::Contains("t.poly:12: region count 50"));

  // A count the text cannot hold but not absurdly so is a truncated file: ParseError at the end.
  const ruppert::Error truncated = errorOf([] { poly(std::string(kSquare) + "5\n1 0.5 0.5 1\n"); });
  CHECK(truncated.code() == ErrorCode::ParseError);
  CHECK_THAT(truncated.what(), Catch::Contains("expected region 2, found end of file"));

  const ruppert::Error huge = errorOf([] { poly("123456789012345678901234567890 2 0 0\n"); });
  CHECK(huge.code() == ErrorCode::TooLarge);

  const ruppert::Error nodeCount = errorOf([] { node("4294967296 2 0 0\n"); });
  CHECK(nodeCount.code() == ErrorCode::TooLarge);

  // A count the remaining text can hold is fine, even when every record is as short as possible.
  CHECK(poly("3\n0 0 0\n1 1 0\n2 0 1\n0").points.size() == 6);
}

// ---------------------------------------------------------------------------------------------
// JSON reading
// ---------------------------------------------------------------------------------------------
TEST_CASE("readJson reads the documented shape and ignores unknown keys", "[io]") {
  const ruppert::Plc p = ruppert::readFile(kFixtures + "square-with-hole.json");
  CHECK(p.indexBase == 0);
  CHECK(p.points == std::vector<double>{0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3});
  CHECK(p.segments == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4});
  CHECK(p.holes == std::vector<double>{2, 2});
  REQUIRE(p.regions.size() == 2);
  CHECK(p.regions[0].attribute == 1.5);
  CHECK(p.regions[0].maxArea == 0.25);
  CHECK(p.regions[1].x == 3.5);
  CHECK(p.regions[1].y == 3.5);
  CHECK(p.regions[1].attribute == 0);
  CHECK(p.regions[1].maxArea == 0);
}

TEST_CASE("readJson handles the JSON grammar", "[io]") {
  const ruppert::Plc p = json(
      " \n{\"extra\": {\"nested\": [true, false, null, \"s\\\"\\u00e9\\ud83d\\ude00\", -0.5e+2, {}]},"
      "\"points\":[-0,1E2,2.5e-1,3],\"segments\":[0,1.0e0],\"regions\":[]}\n\t");
  REQUIRE(p.points.size() == 4);
  CHECK(std::signbit(p.points[0]));
  CHECK(p.points[1] == 100);
  CHECK(p.points[2] == 0.25);
  CHECK(p.segments == std::vector<std::uint32_t>{0, 1});
  CHECK(json("{\"points\": []}").points.empty());
}

TEST_CASE("readJson errors name the path of the offending value", "[io]") {
  auto check = [](const std::string& text, ErrorCode code, const std::string& message) {
    const ruppert::Error e = errorOf([&] { json(text); });
    CHECK(e.code() == code);
    CHECK_THAT(e.what(), Catch::Contains(message));
  };
  check("{\"points\": [0, 0, 1, 0, 0, 1, 2, \"x\"]}", ErrorCode::MalformedInput, "t.json:1:34: points[7] is not a number");
  check("{\"points\": [0, 0, 1]}", ErrorCode::MalformedInput, "points has 3 numbers");
  check("{\"points\": [0, 0, 1, 0, 0, 1], \"segments\": [0, 1, 2, 2.5]}", ErrorCode::MalformedInput,
        "segments[3] = 2.5 is not an integer index");
  check("{\"points\": [0, 0, 1, 0, 0, 1], \"segments\": [0, -1]}", ErrorCode::MalformedInput,
        "segments[1] = -1 is not an integer index");
  check("{\"points\": [0, 0, 1, 0, 0, 1], \"segments\": [0, 1, 2]}", ErrorCode::MalformedInput, "segments has 3 indices");
  check("{\"points\": [0, 0, 1, 0, 0, 1], \"segments\": [0, 1, 2, 3]}", ErrorCode::IndexOutOfRange,
        "segment 1 (segments[3]) refers to point 3 but there are 3 points");
  check("{\"points\": [0, 0], \"segments\": [0, 1e10]}", ErrorCode::IndexOutOfRange, "segments[1] = 1e10");
  check("{\"points\": [0, 0], \"holes\": [1]}", ErrorCode::MalformedInput, "holes has 1 numbers");
  check("{\"points\": [0, 0], \"holes\": {}}", ErrorCode::MalformedInput, "holes must be an array");
  check("{\"points\": [0, 0], \"regions\": [{\"y\": 1}]}", ErrorCode::MalformedInput, "regions[0] has no \"x\"");
  check("{\"points\": [0, 0], \"regions\": [{\"x\": 1, \"y\": 1}, {\"x\": 1, \"y\": 1, \"maxArea\": \"big\"}]}",
        ErrorCode::MalformedInput, "regions[1].maxArea is not a number");
  check("{\"points\": [0, 0], \"regions\": [3]}", ErrorCode::MalformedInput, "regions[0] is not an object");
  check("{\"segments\": []}", ErrorCode::MalformedInput, "missing \"points\"");
  check("{\"points\": [0, 0], \"points\": [1, 1]}", ErrorCode::MalformedInput, "duplicate key \"points\"");
  check("[0, 0]", ErrorCode::MalformedInput, "the top level must be an object");
  // Not JSON at all:
  check("", ErrorCode::ParseError, "the input is empty");
  check("{\"points\": [0, 0]} x", ErrorCode::ParseError, "t.json:1:20: unexpected text after the top-level object");
  check("{\"points\": [0 0]}", ErrorCode::ParseError, "expected ']' or ',' in an array, found '0'");
  check("{\"points\": [01]}", ErrorCode::ParseError, "found '1'");
  check("{\"points\": [1.]}", ErrorCode::ParseError, "points[0]: expected digits after the decimal point");
  check("{\"points\": [NaN]}", ErrorCode::MalformedInput, "points[0] is not a number");
  check("{\"points\": [1e999]}", ErrorCode::ParseError, "points[0] = 1e999 is outside the range of doubles");
  check("{\"points\": [0, 0], \"note\": \"abc", ErrorCode::ParseError, "unterminated string");
  check("{\"points\": [0, 0], \"note\": \"a\\qb\"}", ErrorCode::ParseError, "invalid escape");
  check("{\"points\": [0, 0], \"note\": tru}", ErrorCode::ParseError, "expected a value");
  check("{\"points\": [0, 0],}", ErrorCode::ParseError, "expected a quoted key");
  check("{\n\"points\": [0, 0]\n\"segments\": []}", ErrorCode::ParseError, "t.json:3:1: expected '}' or ','");
}

TEST_CASE("readJson limits nesting instead of overflowing the stack", "[io]") {
  const std::string deep = "{\"points\": [0, 0], \"deep\": " + std::string(1000000, '[') + std::string(1000000, ']') + "}";
  const ruppert::Error e = errorOf([&] { json(deep); });
  CHECK(e.code() == ErrorCode::ParseError);
  CHECK_THAT(e.what(), Catch::Contains("nesting deeper than"));
  // Moderate nesting in an ignored key is fine.
  const std::string ok = "{\"points\": [0, 0], \"deep\": " + std::string(100, '[') + std::string(100, ']') + "}";
  CHECK(json(ok).points.size() == 2);
}

// ---------------------------------------------------------------------------------------------
// Writers
// ---------------------------------------------------------------------------------------------
TEST_CASE("writeNode then readNode gives back the points bit-exact, in either index base", "[io]") {
  for (int base : {0, 1}) {
    const ruppert::Mesh m = handMesh(base);
    std::ostringstream out;
    ruppert::writeNode(out, m);
    const std::vector<std::string> text = lines(out.str());
    REQUIRE(text.size() == 6);
    CHECK(text[0] == "5 2 0 1");
    CHECK(text[1].rfind(std::to_string(base) + " ", 0) == 0);
    const ruppert::Plc back = node(out.str());
    CHECK(back.indexBase == base);
    CHECK(sameBits(back.points, m.points));
    // No markers in the mesh: vertices on subsegments get 1, the interior vertex 0.
    CHECK(back.pointMarkers == std::vector<std::int32_t>{1, 1, 1, 1, 0});
  }
}

TEST_CASE("writeNode prints the mesh's own point markers when it has them", "[io]") {
  ruppert::Mesh m = handMesh(0);
  m.pointMarkers = {7, 8, 9, 10, 0};
  std::ostringstream out;
  ruppert::writeNode(out, m);
  CHECK(node(out.str()).pointMarkers == m.pointMarkers);
}

TEST_CASE("writeEle prints one CCW triple per triangle in the index base", "[io]") {
  for (int base : {0, 1}) {
    ruppert::Mesh m = handMesh(base);
    std::ostringstream out;
    ruppert::writeEle(out, m);
    const std::vector<std::string> text = lines(out.str());
    REQUIRE(text.size() == 5);
    CHECK(text[0] == "4 3 0");
    for (std::size_t t = 0; t < 4; ++t) {
      std::istringstream row(text[t + 1]);
      std::uint32_t id, a, b, c;
      row >> id >> a >> b >> c;
      CHECK(id == t + base);
      CHECK(a == m.triangles[3 * t] + base);
      CHECK(b == m.triangles[3 * t + 1] + base);
      CHECK(c == m.triangles[3 * t + 2] + base);
    }
  }
  SECTION("region attributes add a column") {
    ruppert::Mesh m = handMesh(0);
    m.triangleAttributes = {0, 2.5, 0, 0};
    std::ostringstream out;
    ruppert::writeEle(out, m);
    const std::vector<std::string> text = lines(out.str());
    CHECK(text[0] == "4 3 1");
    CHECK(text[2] == "1 1 2 4 2.5");
  }
}

TEST_CASE("writePoly then readPoly round-trips points, subsegments, holes and regions", "[io]") {
  for (int base : {0, 1}) {
    const ruppert::Mesh m = handMesh(base);
    ruppert::Plc input;
    input.holes = {0.1, 1.0 / 7.0};
    input.regions.push_back({0.25, 0.3, 4.0 / 3.0, 0.01});
    input.regions.push_back({0.75, 0.3, 2.0, 0.0});
    std::ostringstream out;
    ruppert::writePoly(out, m, input);
    const ruppert::Plc back = poly(out.str());
    CHECK(back.indexBase == base);
    CHECK(sameBits(back.points, m.points));
    CHECK(back.segments == m.segments);
    // No markers in the mesh: Triangle's convention, 1 on the boundary (these four subsegments are).
    CHECK(back.segmentMarkers == std::vector<std::int32_t>{1, 1, 1, 1});
    // The mesh's own markers are written as they are (not the input segment's index).
    ruppert::Mesh marked = m;
    marked.segmentMarkers = {5, 0, 7, -2};
    CHECK(poly(ruppert::toPoly(marked, input)).segmentMarkers == marked.segmentMarkers);
    CHECK(sameBits(back.holes, input.holes));
    REQUIRE(back.regions.size() == 2);
    CHECK(back.regions[0].x == input.regions[0].x);
    CHECK(back.regions[0].y == input.regions[0].y);
    CHECK(back.regions[0].attribute == input.regions[0].attribute);
    CHECK(back.regions[0].maxArea == input.regions[0].maxArea);
    CHECK(back.regions[1].maxArea == 0);
    CHECK(out.str().find("nan") == std::string::npos);
  }
}

TEST_CASE("writeJson then readJson round-trips, with the mesh arrays alongside", "[io]") {
  ruppert::Mesh m = handMesh(1);  // JSON is 0-based whatever the input's base
  ruppert::Plc input;
  input.holes = {0.1, 0.2};
  input.regions.push_back({0.25, 0.3, 4.0 / 3.0, 0.01});
  m.notices.push_back({ruppert::NoticeKind::DuplicatePoint, 5, 2, 0, 0, "point 5 \"dup\"\nmerged"});
  std::ostringstream out;
  ruppert::writeJson(out, m, input);
  const std::string text = out.str();
  const ruppert::Plc back = json(text);
  CHECK(sameBits(back.points, m.points));
  CHECK(back.segments == m.segments);
  CHECK(sameBits(back.holes, input.holes));
  REQUIRE(back.regions.size() == 1);
  CHECK(back.regions[0].attribute == input.regions[0].attribute);
  CHECK(back.regions[0].maxArea == input.regions[0].maxArea);
  CHECK_THAT(text, Catch::Contains("\"triangles\": [0,1,4,1,2,4,2,3,4,3,0,4]"));
  CHECK_THAT(text, Catch::Contains("\"neighbors\": [1,3,-1,2,0,-1,3,1,-1,0,2,-1]"));
  CHECK_THAT(text, Catch::Contains("\"segmentIds\": [0,1,-1,2]"));
  CHECK_THAT(text, Catch::Contains("\"vertexKinds\": [0,0,0,0,2]"));
  CHECK_THAT(text, Catch::Contains("\"triangleAttributes\": [0,0,0,0]"));
  // No markers in the hand-made mesh: Triangle's convention (the outer square is the boundary).
  CHECK_THAT(text, Catch::Contains("\"pointMarkers\": [1,1,1,1,0]"));
  CHECK_THAT(text, Catch::Contains("\"segmentMarkers\": [1,1,1,1]"));
  CHECK(text.find("\"edges\"") == std::string::npos);
  CHECK_THAT(text, Catch::Contains("\"complete\": false"));
  CHECK_THAT(text, Catch::Contains("{\"kind\": \"steinerBudget\", \"count\": 3, \"message\": \"budget \\\"100\\\" reached\"}"));
  CHECK_THAT(text, Catch::Contains("\"message\": \"point 5 \\\"dup\\\"\\nmerged\""));
  CHECK_THAT(text, Catch::Contains("\"minAngle\": 28.5"));
  CHECK_THAT(text, Catch::Contains("\"lfsIntegral\": null"));
  CHECK(text.find("nan") == std::string::npos);
}

TEST_CASE("writeSvg draws triangles and subsegments with y pointing up", "[io]") {
  ruppert::Mesh m = handMesh(0);
  m.points[1] = 2.0;  // point 0 at (-0, 2): printed as y = -2
  std::ostringstream out;
  ruppert::writeSvg(out, m);
  const std::string svg = out.str();
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"", 0) == 0);
  CHECK(svg.find("nan") == std::string::npos);
  CHECK_THAT(svg, Catch::Contains("M-0 -2L"));  // first triangle starts at point 0, flipped
  // One path of triangles (one 'Z' each), then one bolder path of subsegments (one 'M' each).
  const std::size_t first = svg.find("<path");
  const std::size_t second = svg.find("<path", first + 1);
  REQUIRE(second != std::string::npos);
  const std::string triangles = svg.substr(first, second - first);
  const std::string subsegments = svg.substr(second);
  CHECK(std::count(triangles.begin(), triangles.end(), 'Z') == 4);
  CHECK(std::count(subsegments.begin(), subsegments.end(), 'M') == 4);
  CHECK_THAT(subsegments, Catch::Contains("stroke-width=\"2\""));
  CHECK_THAT(triangles, Catch::Contains("stroke-width=\"0.6\""));
  // Points span x in [0, 1], y in [0.3, 2]; flipped, the viewBox covers y in [-2, -0.3] with a margin.
  std::istringstream box(svg.substr(svg.find("viewBox=\"") + 9));
  double x, y, w, h;
  box >> x >> y >> w >> h;
  CHECK(y < -2);
  CHECK(y + h > -0.3);
  CHECK(x < 0);
  CHECK(x + w > 1.0);
}

TEST_CASE("writers refuse non-finite coordinates instead of printing nan", "[io]") {
  ruppert::Mesh m = handMesh(0);
  m.points[3] = std::nan("");
  std::ostringstream out;
  CHECK(errorOf([&] { ruppert::writeNode(out, m); }).code() == ErrorCode::Internal);
  CHECK(errorOf([&] { ruppert::writeSvg(out, m); }).code() == ErrorCode::Internal);
  CHECK(out.str().empty());
  std::ostringstream js;
  ruppert::writeJson(js, m, ruppert::Plc{});
  CHECK(js.str().find("nan") == std::string::npos);
  CHECK_THAT(js.str(), Catch::Contains("\"points\": [-0,0,1,null,"));
}

TEST_CASE("writers report a failed stream as IoError", "[io]") {
  std::ostringstream out;
  out.setstate(std::ios::badbit);
  CHECK(errorOf([&] { ruppert::writeEle(out, handMesh(0)); }).code() == ErrorCode::IoError);
}

// ---------------------------------------------------------------------------------------------
// Real inputs
// ---------------------------------------------------------------------------------------------
TEST_CASE("every shared .poly reads without error and matches its README counts", "[io]") {
#ifndef RUPPERT_SHARED_DATA
  WARN("RUPPERT_SHARED_DATA not defined: skipping the shared-data test");
#else
  namespace fs = std::filesystem;
  const fs::path dir(RUPPERT_SHARED_DATA);
  if (!fs::exists(dir / "README.md")) {
    WARN("shared data not found at " << dir.string() << ": skipping");
    return;
  }
  // README rows: | file | vertices | segments | holes | regions | ... (first table: files in dir itself).
  std::map<std::string, std::vector<std::uint64_t>> expected;
  std::ifstream readme(dir / "README.md");
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("## crossing", 0) == 0) break;
    if (line.rfind("| ", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    if (cells.size() < 5 || cells[0].size() < 6 || cells[0].substr(cells[0].size() - 5) != ".poly") continue;
    expected[cells[0]] = {std::stoull(cells[1]), std::stoull(cells[2]), std::stoull(cells[3]), std::stoull(cells[4])};
  }
  REQUIRE(expected.size() > 10);

  std::size_t files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".poly") continue;
    const std::string name = entry.path().filename().string();
    INFO(name);
    ruppert::Plc plc;
    REQUIRE_NOTHROW(plc = ruppert::readFile(entry.path().string()));
    // The header's first field is the point count.
    std::ifstream file(entry.path());
    std::uint64_t declared = 0;
    for (std::string line; std::getline(file, line);) {
      line = line.substr(0, line.find('#'));
      std::istringstream fields(line);
      if (fields >> declared) break;
    }
    CHECK(plc.points.size() / 2 == declared);
    REQUIRE(expected.count(name) == 1);
    CHECK(plc.points.size() / 2 == expected[name][0]);
    CHECK(plc.segments.size() / 2 == expected[name][1]);
    CHECK(plc.holes.size() / 2 == expected[name][2]);
    CHECK(plc.regions.size() == expected[name][3]);
    const std::uint32_t largest = plc.segments.empty() ? 0 : *std::max_element(plc.segments.begin(), plc.segments.end());
    CHECK(largest < plc.points.size() / 2);
    ++files;
  }
  CHECK(files == expected.size());
#endif
}

// The string forms (what the WebAssembly binding uses) print exactly what the stream forms print,
// including across TextOut's 64 KiB pieces, and the text readers read what the stream readers read.
TEST_CASE("string writers and readers match the stream ones", "[io]") {
  const ruppert::Plc plc = ruppert::readFile(kFixtures + "zero-based-commented.poly");
  ruppert::Options options;
  options.maxArea = 0.0005;  // thousands of triangles: the texts span many 64 KiB pieces
  const ruppert::Mesh mesh = ruppert::triangulate(plc, options);
  REQUIRE(mesh.triangles.size() / 3 > 2000);
  auto streamed = [](auto&& write) {
    std::ostringstream out;
    write(out);
    return out.str();
  };
  const std::string node = ruppert::toNode(mesh), json = ruppert::toJson(mesh, plc);
  CHECK(json.size() > 3 * 65536);
  CHECK(node == streamed([&](std::ostream& o) { ruppert::writeNode(o, mesh); }));
  CHECK(ruppert::toEle(mesh) == streamed([&](std::ostream& o) { ruppert::writeEle(o, mesh); }));
  CHECK(ruppert::toPoly(mesh, plc) == streamed([&](std::ostream& o) { ruppert::writePoly(o, mesh, plc); }));
  CHECK(json == streamed([&](std::ostream& o) { ruppert::writeJson(o, mesh, plc); }));
  CHECK(ruppert::toSvg(mesh) == streamed([&](std::ostream& o) { ruppert::writeSvg(o, mesh); }));

  const std::string poly = ruppert::toPoly(mesh, plc);
  std::istringstream polyStream(poly), jsonStream(json), nodeStream(node);
  const ruppert::Plc fromText = ruppert::parsePoly(poly, "m.poly"), fromStream = ruppert::readPoly(polyStream, "m.poly");
  CHECK(fromText.points == fromStream.points);
  CHECK(fromText.segments == fromStream.segments);
  CHECK(fromText.points == mesh.points);
  CHECK(ruppert::parseJson(json, "m.json").points == ruppert::readJson(jsonStream, "m.json").points);
  CHECK(ruppert::parseNode(node, "m.node").points == ruppert::readNode(nodeStream, "m.node").points);
}
