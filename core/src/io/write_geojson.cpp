// The mesh as GeoJSON (RFC 7946): a FeatureCollection with one Feature per triangle, in
// mesh.triangles order, each a Polygon of one closed ring (counter-clockwise, as RFC 7946 asks of
// exterior rings) with properties
//   "triangle"         its index in mesh.triangles
//   "vertices"         its three point indices (0-based), so shared vertices can be recovered
//   "regionAttribute"  its region's attribute
//   "minAngle"         its smallest angle in degrees
// Coordinates are written as the mesh has them: no projection is assumed or applied.
#include <cstdint>
#include <string>

#include "ruppert/ruppert.h"
#include "io/write_common.h"

#include "cold_code.h"

RUPPERT_COLD_BEGIN
namespace ruppert {
namespace {

using detail::realText;
using detail::TextOut;

void position(TextOut& out, const Mesh& mesh, std::uint32_t v) {
  out << '[' << realText(mesh.points[2 * static_cast<std::size_t>(v)]) << ','
      << realText(mesh.points[2 * static_cast<std::size_t>(v) + 1]) << ']';
}

void printGeoJson(TextOut& out, const Mesh& mesh) {
  detail::requireFiniteValues(mesh.points, "points");
  detail::requireFiniteValues(mesh.triangleAttributes, "triangleAttributes");
  detail::requireTriangleIndices(mesh);
  const std::size_t n = mesh.triangles.size() / 3;
  out << "{\"type\": \"FeatureCollection\", \"features\": [";
  for (std::size_t t = 0; t < n; ++t) {
    const std::uint32_t a = mesh.triangles[3 * t], b = mesh.triangles[3 * t + 1], c = mesh.triangles[3 * t + 2];
    out << (t ? ",\n" : "\n") << "{\"type\": \"Feature\", \"properties\": {\"triangle\": " << t
        << ", \"vertices\": [" << a << ',' << b << ',' << c
        << "], \"regionAttribute\": " << realText(detail::triangleAttribute(mesh, t))
        << ", \"minAngle\": " << realText(detail::smallestAngleDegrees(mesh, t))
        << "}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[";
    position(out, mesh, a);
    out << ',';
    position(out, mesh, b);
    out << ',';
    position(out, mesh, c);
    out << ',';
    position(out, mesh, a);
    out << "]]}}";
  }
  out << "\n]}\n";
}

}  // namespace

void writeGeoJson(std::ostream& out, const Mesh& mesh) {
  detail::toStream(out, "GeoJSON", [&](TextOut& t) { printGeoJson(t, mesh); });
}

std::string toGeoJson(const Mesh& mesh) {
  return detail::toText([&](TextOut& t) { printGeoJson(t, mesh); });
}

}  // namespace ruppert
RUPPERT_COLD_END
