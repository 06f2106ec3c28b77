// Per-point attributes: read from the .node/.poly attribute columns, carried onto
// every new vertex by linear interpolation, written back in the output .node. A linear field
// a x + b y + c given at the input points must come back, to rounding, at every output vertex.
#include <catch2/catch.hpp>

#include <cmath>

#include "plc_generators.h"
#include "validator.h"

using namespace ruppert_test;

namespace {

// Two linear fields per point: 3x - 2y + 1 and -x + 5y + 0.25 (and their worst error at the output).
void addLinearFields(ruppert::Plc& plc) {
  plc.attributesPerPoint = 2;
  plc.pointAttributes.clear();
  for (std::size_t i = 0; i < plc.points.size() / 2; ++i) {
    const double x = plc.points[2 * i], y = plc.points[2 * i + 1];
    plc.pointAttributes.push_back(3 * x - 2 * y + 1);
    plc.pointAttributes.push_back(-x + 5 * y + 0.25);
  }
}

double worstError(const ruppert::Mesh& mesh) {
  REQUIRE(mesh.attributesPerPoint == 2);
  REQUIRE(mesh.pointAttributes.size() == mesh.points.size());
  double worst = 0;
  for (std::size_t i = 0; i < mesh.points.size() / 2; ++i) {
    const double x = mesh.points[2 * i], y = mesh.points[2 * i + 1];
    worst = std::max(worst, std::fabs(mesh.pointAttributes[2 * i] - (3 * x - 2 * y + 1)));
    worst = std::max(worst, std::fabs(mesh.pointAttributes[2 * i + 1] - (-x + 5 * y + 0.25)));
  }
  return worst;
}

}  // namespace

TEST_CASE("a linear field at the input points is reproduced at every output vertex", "[attributes]") {
  for (std::uint64_t seed = 1; seed <= 9; ++seed) {
    GeneratedPlc g = seed % 3 == 0 ? randomCrossingSegments(seed, 6)  // intersection vertices too
                     : seed % 3 == 1 ? randomStarPolygon(seed, 18, 2)
                                     : randomNonCrossingSegments(seed, 20);
    addLinearFields(g.plc);
    for (ruppert::Placement placement : {ruppert::Placement::OffCenter, ruppert::Placement::Circumcenter,
                                         ruppert::Placement::Optimal}) {
      ruppert::Options o;
      o.minAngle = placement == ruppert::Placement::Optimal ? 36 : 30;  // optimal also moves vertices
      o.maxArea = 0.002;
      o.placement = placement;
      const ruppert::Mesh mesh = ruppert::triangulate(g.plc, o);
      INFO("seed " << seed << ", placement " << int(placement) << ", " << mesh.points.size() / 2 << " vertices");
      CHECK(mesh.points.size() / 2 > g.plc.points.size() / 2 + 20);
      CHECK(worstError(mesh) < 1e-12);
    }
    // Ruppert's original variant refines a box around the domain too (its corners carry 0s, but no
    // vertex of the domain is interpolated from them).
    ruppert::Options box;
    box.maxArea = 0.002;
    box.variant = ruppert::Variant::BoundingBox;
    INFO("seed " << seed << ", bounding-box variant");
    CHECK(worstError(ruppert::triangulate(g.plc, box)) < 1e-12);
  }
}

TEST_CASE("attributes go through the .node columns: read, interpolated, written", "[attributes][io]") {
  const std::string text =
      "4 2 1 1\n"
      "0 0 0 10 1\n"
      "1 4 0 14 1\n"
      "2 4 4 18 1\n"
      "3 0 4 14 1\n"
      "4 1\n0 0 1 0\n1 1 2 0\n2 2 3 0\n3 3 0 0\n0\n";
  const ruppert::Plc plc = ruppert::parsePoly(text);
  REQUIRE(plc.attributesPerPoint == 1);
  REQUIRE(plc.pointAttributes == std::vector<double>{10, 14, 18, 14});
  ruppert::Options o;
  o.maxArea = 0.5;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, o);  // field 10 + x + y
  REQUIRE(mesh.pointAttributes.size() == mesh.points.size() / 2);
  for (std::size_t i = 0; i < mesh.points.size() / 2; ++i)
    CHECK(mesh.pointAttributes[i] == Approx(10 + mesh.points[2 * i] + mesh.points[2 * i + 1]).epsilon(1e-14));
  const ruppert::Plc back = ruppert::parseNode(ruppert::toNode(mesh));
  CHECK(back.attributesPerPoint == 1);
  CHECK(back.pointAttributes == mesh.pointAttributes);  // %.17g: bit-exact
  CHECK(back.pointMarkers == mesh.pointMarkers);        // the marker column stays after them
}

TEST_CASE("attributes that do not fit the points are refused with a clear error", "[attributes]") {
  ruppert::Plc plc;
  plc.points = {0, 0, 1, 0, 0, 1};
  plc.attributesPerPoint = 2;
  plc.pointAttributes = {1, 2, 3, 4, 5};
  try {
    ruppert::triangulate(plc);
    FAIL("no error");
  } catch (const ruppert::Error& e) {
    CHECK(e.code() == ruppert::ErrorCode::MalformedInput);
    CHECK_THAT(e.what(), Catch::Contains("5 values for 3 points"));
  }
  plc.pointAttributes = {1, 2, 3, 4, 5, NAN};
  try {
    ruppert::triangulate(plc);
    FAIL("no error");
  } catch (const ruppert::Error& e) {
    CHECK(e.code() == ruppert::ErrorCode::NonFiniteCoordinate);
    CHECK_THAT(e.what(), Catch::Contains("pointAttributes[5] (point 2)"));
  }
  // More attribute columns declared than ruppert keeps, with values given: named, not allocated.
  try {
    ruppert::parsePoly("3 2 70000 0\n0 0 0 5\n1 1 0 5\n2 0 1 5\n0 0\n0\n");
    FAIL("no error");
  } catch (const ruppert::Error& e) {
    CHECK(e.code() == ruppert::ErrorCode::TooLarge);
    CHECK_THAT(e.what(), Catch::Contains("70000 attributes per point"));
  }
}

#ifdef RUPPERT_CLI
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

TEST_CASE("cli: attribute columns, --jettison and --no-segment-steiner", "[attributes][jettison][cli]") {
  if (!std::filesystem::exists(RUPPERT_CLI)) {
    WARN("the ruppert executable is not built: skipping");
    return;
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ruppert-attributes-" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  // 10 + x + y as the attribute; point 5 duplicates point 2, point 6 lies outside the square.
  std::ofstream((dir / "in.poly").string()) << "6 2 1 0\n1 0 0 10\n2 4 0 14\n3 4 4 18\n4 0 4 14\n5 4 0 14\n6 9 9 28\n"
                                               "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
  const std::string base = (dir / "out").string();
  const std::string command = std::string("'") + RUPPERT_CLI + "' --quiet --min-angle 30 --max-area 0.5 --jettison " +
                              "--no-segment-steiner -o '" + base + "' '" + (dir / "in.poly").string() + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  const ruppert::Plc out = ruppert::readFile(base + ".node");
  REQUIRE(out.attributesPerPoint == 1);
  std::size_t onSides = 0;
  for (std::size_t i = 0; i < out.points.size() / 2; ++i) {
    const double x = out.points[2 * i], y = out.points[2 * i + 1];
    CHECK(out.pointAttributes[i] == Approx(10 + x + y).epsilon(1e-14));
    CHECK(!(x == 9 && y == 9));  // jettisoned
    onSides += x == 0 || y == 0 || x == 4 || y == 4;
  }
  CHECK(onSides == 4);  // the corners only: no vertex on a segment, the duplicate left out
  CHECK(out.points.size() / 2 > 20);
  std::filesystem::remove_all(dir);
}
#endif

TEST_CASE("JSON input carries markers and attributes, and the JSON output reads back with them", "[attributes][markers][io]") {
  const ruppert::Plc plc = ruppert::parseJson(
      "{\"points\": [0,0, 4,0, 4,4, 0,4], \"segments\": [0,1, 1,2, 2,3, 3,0],"
      " \"pointMarkers\": [0, -3, 0, 0], \"segmentMarkers\": [7, 0, 0, 0], \"pointAttributes\": [10,0, 14,1, 18,2, 14,3]}");
  REQUIRE(plc.attributesPerPoint == 2);  // 8 values for 4 points
  CHECK(plc.pointMarkers == std::vector<std::int32_t>{0, -3, 0, 0});
  CHECK(plc.segmentMarkers == std::vector<std::int32_t>{7, 0, 0, 0});
  ruppert::Options o;
  o.maxArea = 1;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, o);
  CHECK(mesh.pointMarkers[0] == 7);   // on segment 0 (marker 7)
  CHECK(mesh.pointMarkers[1] == -3);  // its own
  const ruppert::Plc back = ruppert::parseJson(ruppert::toJson(mesh, plc));
  CHECK(back.pointMarkers == mesh.pointMarkers);
  CHECK(back.segmentMarkers == mesh.segmentMarkers);
  CHECK(back.attributesPerPoint == 2);
  CHECK(back.pointAttributes == mesh.pointAttributes);
  for (const char* bad : {"{\"points\": [0,0, 1,0, 0,1], \"pointMarkers\": [1, 2]}",
                          "{\"points\": [0,0, 1,0, 0,1], \"segments\": [0,1], \"segmentMarkers\": [1, 2]}",
                          "{\"points\": [0,0, 1,0, 0,1], \"pointMarkers\": [1, 2.5, 3]}",
                          "{\"points\": [0,0, 1,0, 0,1], \"pointAttributes\": [1, 2, 3, 4]}",
                          "{\"points\": [0,0, 1,0, 0,1], \"pointAttributes\": [1, 2, 3], \"attributesPerPoint\": 2}"}) {
    INFO(bad);
    try {
      ruppert::parseJson(bad);
      FAIL("no error");
    } catch (const ruppert::Error& e) {
      CHECK(e.code() == ruppert::ErrorCode::MalformedInput);
      CHECK_THAT(e.what(), Catch::Contains("Markers") || Catch::Contains("pointAttributes"));
    }
  }
}
