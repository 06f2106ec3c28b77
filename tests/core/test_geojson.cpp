// GeoJSON in (parseGeoJson) and out (toGeoJson), and the structure of the .msh and .vtu texts
// (their consumers judge them in test_consumers.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/json_tree.h"
#include "ruppert/ruppert.h"
#include "validator.h"

namespace {

// A ring of (x, y) pairs as GeoJSON text, optionally reversed and optionally closed.
std::string ringText(std::vector<double> xy, bool reverse, bool close) {
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) p.emplace_back(xy[i], xy[i + 1]);
  if (reverse) std::reverse(p.begin(), p.end());
  if (close) p.push_back(p.front());
  std::ostringstream out;
  out.precision(17);
  out << '[';
  for (std::size_t i = 0; i < p.size(); ++i) out << (i ? "," : "") << '[' << p[i].first << ',' << p[i].second << ']';
  return out.str() + ']';
}

std::vector<double> square(double x0, double y0, double size) {
  return {x0, y0, x0 + size, y0, x0 + size, y0 + size, x0, y0 + size};
}

double meshArea(const ruppert::Mesh& m) {
  double area = 0;
  for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
    const double* a = &m.points[2 * m.triangles[t]];
    const double* b = &m.points[2 * m.triangles[t + 1]];
    const double* c = &m.points[2 * m.triangles[t + 2]];
    area += ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
  }
  return area;
}

// True when some triangle's centroid lies strictly inside the axis-aligned square.
bool anyTriangleIn(const ruppert::Mesh& m, const std::vector<double>& sq) {
  for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
    double cx = 0, cy = 0;
    for (int k = 0; k < 3; ++k) {
      cx += m.points[2 * m.triangles[t + k]] / 3;
      cy += m.points[2 * m.triangles[t + k] + 1] / 3;
    }
    if (cx > sq[0] && cx < sq[2] && cy > sq[1] && cy < sq[5]) return true;
  }
  return false;
}

ruppert::ErrorCode codeOf(const std::string& text, std::string& message) {
  try {
    ruppert::parseGeoJson(text, "in.geojson");
  } catch (const ruppert::Error& e) {
    message = e.what();
    return e.code();
  }
  message = "";
  return ruppert::ErrorCode::Internal;
}

}  // namespace

TEST_CASE("geojson: a polygon with a hole meshes without hole seeds and the hole stays empty", "[geojson]") {
  const auto outer = square(0, 0, 4), hole = square(1, 1, 2);
  for (int variant = 0; variant < 4; ++variant) {
    const bool reverse = variant & 1, close = variant & 2;
    INFO("reversed rings: " << reverse << ", closed: " << close);
    const std::string text = "{\"type\": \"Polygon\", \"coordinates\": [" + ringText(outer, reverse, close) + ", " +
                             ringText(hole, !reverse, close) + "]}";
    const ruppert::Plc plc = ruppert::parseGeoJson(text);
    CHECK(plc.points.size() == 16);
    CHECK(plc.segments.size() == 16);
    REQUIRE(plc.holes.size() == 2);
    CHECK((plc.holes[0] > 1 && plc.holes[0] < 3 && plc.holes[1] > 1 && plc.holes[1] < 3));
    const ruppert::Mesh mesh = ruppert::triangulate(plc);
    ruppert_test::ValidateOptions v;
    v.input = &plc;
    v.expectedArea = 12;
    REQUIRE_VALID(mesh, v);
    CHECK_FALSE(anyTriangleIn(mesh, square(1, 1, 2)));
  }
}

TEST_CASE("geojson: islands in lakes, filled holes and shared edges", "[geojson]") {
  const auto outer = square(0, 0, 10), lake = square(2, 2, 6), island = square(4, 4, 2);
  SECTION("an island inside a hole stays meshed") {
    const std::string text = "{\"type\": \"MultiPolygon\", \"coordinates\": [[" + ringText(outer, false, true) + "," +
                             ringText(lake, true, true) + "], [" + ringText(island, false, true) + "]]}";
    const ruppert::Plc plc = ruppert::parseGeoJson(text);
    REQUIRE(plc.holes.size() == 2);
    const ruppert::Mesh mesh = ruppert::triangulate(plc);
    CHECK(meshArea(mesh) == Approx(100 - 36 + 4));
    CHECK(anyTriangleIn(mesh, island));
  }
  SECTION("a hole that another feature fills is not a hole") {
    const std::string text =
        "{\"type\": \"FeatureCollection\", \"features\": ["
        "{\"type\": \"Feature\", \"properties\": {\"name\": \"donut\"}, \"geometry\": {\"type\": \"Polygon\", "
        "\"coordinates\": [" + ringText(outer, false, true) + "," + ringText(lake, true, true) + "]}},"
        "{\"type\": \"Feature\", \"properties\": null, \"geometry\": null},"
        "{\"type\": \"Feature\", \"properties\": {}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [" +
        ringText(lake, false, true) + "]}}]}";
    const ruppert::Plc plc = ruppert::parseGeoJson(text);
    CHECK(plc.holes.empty());
    CHECK(plc.points.size() == 16);
    CHECK(plc.segments.size() == 16);  // the lake's edges are shared, not doubled
    const ruppert::Mesh mesh = ruppert::triangulate(plc);
    CHECK(mesh.notices.empty());
    CHECK(meshArea(mesh) == Approx(100));
  }
}

TEST_CASE("geojson: a courtyard enclosed by four polygons and covered by none is a hole", "[geojson]") {
  auto polygon = [](std::vector<double> xy) {
    return "{\"type\":\"Feature\",\"properties\":{},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[" +
           ringText(xy, false, true) + "]}}";
  };
  const std::string text = "{\"type\":\"FeatureCollection\",\"features\":[" + polygon({0, 0, 6, 0, 6, 2, 0, 2}) + "," +
                           polygon({0, 4, 6, 4, 6, 6, 0, 6}) + "," + polygon({0, 2, 2, 2, 2, 4, 0, 4}) + "," +
                           polygon({4, 2, 6, 2, 6, 4, 4, 4}) + "]}";
  const ruppert::Plc plc = ruppert::parseGeoJson(text);
  REQUIRE(plc.holes.size() == 2);
  const ruppert::Mesh mesh = ruppert::triangulate(plc);
  CHECK(meshArea(mesh) == Approx(32));
  CHECK_FALSE(anyTriangleIn(mesh, square(2, 2, 2)));
}

TEST_CASE("geojson: degenerate and self-crossing rings are segments like any other", "[geojson]") {
  // An inner ring on one line encloses nothing: its segments are meshed as constraints, no hole.
  const ruppert::Plc flat = ruppert::parseGeoJson(
      "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[9,0],[9,9],[0,9]],[[1,1],[2,2],[3,3]]]}");
  CHECK(flat.holes.empty());
  CHECK(meshArea(ruppert::triangulate(flat)) == Approx(81));
  // A bowtie: its crossing is repaired (a notice), both lobes are domain.
  const ruppert::Plc bowtie = ruppert::parseGeoJson("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,4],[4,0],[0,4],[0,0]]]}");
  const ruppert::Mesh mesh = ruppert::triangulate(bowtie);
  CHECK(meshArea(mesh) == Approx(8));
  REQUIRE(mesh.notices.size() == 1);
  CHECK(mesh.notices[0].kind == ruppert::NoticeKind::SegmentsCross);
}

TEST_CASE("geojson: generated polygons with random square holes", "[geojson]") {
  std::mt19937_64 random(16);
  for (int round = 0; round < 20; ++round) {
    // Holes on a 4x4 grid of cells of a 16x16 square, each a random dyadic square inside its cell.
    std::string rings = ringText(square(0, 0, 16), round % 2, true);
    double area = 256;
    std::vector<std::vector<double>> holes;
    for (int cell = 0; cell < 16; ++cell) {
      if (random() % 2) continue;
      const double size = 1 + static_cast<double>(random() % 8) / 4;     // 1 .. 2.75
      const double x = 4 * (cell % 4) + 0.5 + static_cast<double>(random() % 3) / 4;
      const double y = 4 * (cell / 4) + 0.5 + static_cast<double>(random() % 3) / 4;
      holes.push_back(square(x, y, size));
      rings += "," + ringText(holes.back(), random() % 2, random() % 2);
      area -= size * size;
    }
    INFO("round " << round << ": " << holes.size() << " holes");
    const ruppert::Plc plc = ruppert::parseGeoJson("{\"type\":\"Polygon\",\"coordinates\":[" + rings + "]}");
    CHECK(plc.holes.size() == 2 * holes.size());
    const ruppert::Mesh mesh = ruppert::triangulate(plc);
    ruppert_test::ValidateOptions v;
    v.input = &plc;
    v.expectedArea = area;
    CHECK_VALID(mesh, v);
    for (const auto& h : holes) CHECK_FALSE(anyTriangleIn(mesh, h));
  }
}

TEST_CASE("geojson: bad input names the feature and what is wrong", "[geojson]") {
  std::string message;
  CHECK(codeOf("{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0]", message) == ruppert::ErrorCode::ParseError);
  CHECK_THAT(message, Catch::StartsWith("in.geojson:1:"));
  CHECK(codeOf("[1, 2]", message) == ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("top level"));
  const std::string good = "{\"type\":\"Feature\",\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,1]]]}}";
  CHECK(codeOf("{\"type\":\"FeatureCollection\",\"features\":[" + good +
                   ",\n{\"type\":\"Feature\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":[[0,0],[1,1]]}}]}",
               message) == ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("in.geojson:2:") && Catch::Contains("features[1].geometry") &&
                          Catch::Contains("LineString"));
  CHECK(codeOf("{\"type\":\"FeatureCollection\",\"features\":[" + good +
                   ",{\"type\":\"Feature\",\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,0]]]}}]}",
               message) == ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("features[1].geometry.coordinates[0]") && Catch::Contains("2 distinct positions"));
  CHECK(codeOf("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,\"1\"]]]}", message) ==
        ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("coordinates[0][2]") && Catch::Contains("position"));
  CHECK(codeOf("{\"type\":\"Polygon\"}", message) == ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("no \"coordinates\""));
  CHECK(codeOf("{\"type\":\"Polygon\",\"coordinates\":[]}", message) == ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("no rings"));
  CHECK(codeOf("{\"type\":\"FeatureCollection\",\"features\":{}}", message) == ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("features must be an array"));
  CHECK(codeOf("{\"type\":\"FeatureCollection\",\"features\":[]}", message) == ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("holds no Polygon"));
  CHECK(codeOf("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,1],[0,0],[1,1]]]}", message) ==
        ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("coordinates[0] has 2 distinct positions"));
  CHECK(codeOf("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,1]]],\"type\":\"Point\"}", message) ==
        ruppert::ErrorCode::MalformedInput);
  CHECK_THAT(message, Catch::Contains("duplicate key \"type\""));
  std::string deep(300, '[');
  CHECK(codeOf(deep, message) == ruppert::ErrorCode::ParseError);
  CHECK_THAT(message, Catch::Contains("nesting"));
}

TEST_CASE("geojson: toGeoJson writes one closed counter-clockwise ring per triangle", "[geojson]") {
  const std::string text = "{\"type\": \"Polygon\", \"coordinates\": [" + ringText(square(0, 0, 4), false, true) + "," +
                           ringText(square(1, 1, 2), false, true) + "]}";
  const ruppert::Plc plc = ruppert::parseGeoJson(text);
  ruppert::Options options;
  options.maxArea = 0.5;
  const ruppert::Mesh mesh = ruppert::triangulate(plc, options);
  const ruppert::detail::JsonValue doc = ruppert::detail::parseJsonTree(ruppert::toGeoJson(mesh), "out");
  REQUIRE(doc.find("type")->text == "FeatureCollection");
  const auto& features = doc.find("features")->items;
  REQUIRE(features.size() == mesh.triangles.size() / 3);
  for (std::size_t t = 0; t < features.size(); ++t) {
    const auto& ring = features[t].find("geometry")->find("coordinates")->items.at(0).items;
    REQUIRE(ring.size() == 4);
    CHECK(ring[0].numbers == ring[3].numbers);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[3 * t + k];
      CHECK(ring[k].numbers == std::vector<double>{mesh.points[2 * v], mesh.points[2 * v + 1]});
      CHECK(features[t].find("properties")->find("vertices")->numbers.at(k) == v);
    }
    const double cross = (ring[1].numbers[0] - ring[0].numbers[0]) * (ring[2].numbers[1] - ring[0].numbers[1]) -
                         (ring[1].numbers[1] - ring[0].numbers[1]) * (ring[2].numbers[0] - ring[0].numbers[0]);
    CHECK(cross > 0);
    const double angle = features[t].find("properties")->find("minAngle")->number;
    CHECK((angle >= 30 - 1e-9 && angle <= 60));
  }
  // The triangles, read back as polygons, cover the same area: the mesh as a GIS layer.
  const ruppert::Plc again = ruppert::parseGeoJson(ruppert::toGeoJson(mesh));
  CHECK(again.points.size() / 2 <= mesh.points.size() / 2);
  CHECK(meshArea(ruppert::triangulate(again, ruppert::Options{})) == Approx(12));
}

TEST_CASE("formats: .msh and .vtu headers and counts", "[geojson][formats]") {
  ruppert::Plc plc = ruppert::parseGeoJson("{\"type\": \"Polygon\", \"coordinates\": [" +
                                           ringText(square(0, 0, 4), false, true) + "]}");
  plc.segmentMarkers = {5, 5, 0, -2};
  plc.pointMarkers = {1, 2, 3, 4};
  plc.regions = {{1, 1, 2.5, 0}};
  const ruppert::Mesh mesh = ruppert::triangulate(plc);
  const std::string msh = ruppert::toMsh(mesh, plc);
  CHECK_THAT(msh, Catch::StartsWith("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n"));
  // Marker 5 keeps its tag; the unmarked boundary segment carries 1 (Triangle's rule, which
  // Mesh::segmentMarkers follows) and keeps that tag; -2 takes the tag after the largest;
  // attribute 2.5 takes tag 1.
  CHECK_THAT(msh, Catch::Contains("1 5 \"marker 5\"\n") && Catch::Contains("1 6 \"marker -2\"\n") &&
                      Catch::Contains("1 1 \"marker 1\"\n") && !Catch::Contains("\"marker 0\"") &&
                      Catch::Contains("2 1 \"attribute 2.5\"\n"));
  const std::size_t n = mesh.points.size() / 2, t = mesh.triangles.size() / 3, l = mesh.segments.size() / 2;
  CHECK_THAT(msh, Catch::Contains("$Nodes\n1 " + std::to_string(n) + " 1 " + std::to_string(n) + "\n"));
  CHECK_THAT(msh, Catch::Contains("$Elements\n4 " + std::to_string(t + l) + " 1 " + std::to_string(t + l) + "\n"));
  const std::string vtu = ruppert::toVtu(mesh);
  CHECK_THAT(vtu, Catch::Contains("<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" +
                                  std::to_string(t) + "\">"));
  CHECK_THAT(vtu, Catch::Contains("Name=\"pointMarker\"") && Catch::Contains("Name=\"minAngle\""));
  ruppert::Mesh broken = mesh;
  broken.triangles[4] = static_cast<std::uint32_t>(n + 3);
  CHECK_THROWS_WITH(ruppert::toVtu(broken), Catch::Contains("triangles[4]"));
  CHECK_THROWS_WITH(ruppert::toMsh(broken, plc), Catch::Contains("triangles[4]"));
  broken = mesh;
  broken.points[3] = NAN;
  CHECK_THROWS_WITH(ruppert::toGeoJson(broken), Catch::Contains("points[3]"));
}
