// VTK's XML UnstructuredGrid (.vtu), ASCII, from VTK's "VTK File Formats" documentation: what
// ParaView and VisIt open.
//
//   Points     x y 0 per point (every point, unused ones too, so indices match mesh.points)
//   Cells      one VTK_TRIANGLE (type 5) per triangle, in mesh.triangles order; with
//              VtuOptions::segmentCells, then one VTK_LINE (type 3) per subsegment, in mesh.segments order
//   PointData  "vertexKind" (UInt8, ruppert::VertexKind); "pointMarker" (Int32) when the mesh has
//              one marker per point
//   CellData   "regionAttribute" (Float64) and "minAngle" (Float64, the triangle's smallest angle in
//              degrees), 0 for lines; with segmentCells "segmentMarker" (Int32: a line's marker, 0 for
//              triangles)
// Offsets and connectivity are Int64 (header_type UInt64), so no count can overflow.
#include <cstdint>
#include <string>
#include <vector>

#include "ruppert/ruppert.h"
#include "io/write_common.h"

#include "cold_code.h"

RUPPERT_COLD_BEGIN
namespace ruppert {
namespace {

using detail::realText;
using detail::TextOut;

constexpr int kVtkTriangle = 5;
constexpr int kVtkLine = 3;

template <class Each>
void dataArray(TextOut& out, const char* type, const char* name, std::size_t count, Each&& each) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < count; ++i) {
    out << (i % 8 == 0 ? "          " : " ");
    each(i);
    if (i % 8 == 7 || i + 1 == count) out << '\n';
  }
  out << "        </DataArray>\n";
}

void printPointData(TextOut& out, const Mesh& mesh, std::size_t n) {
  out << "      <PointData>\n";
  if (mesh.pointMarkers.size() == n) {
    dataArray(out, "Int32", "pointMarker", n, [&](std::size_t i) { out << mesh.pointMarkers[i]; });
  }
  dataArray(out, "UInt8", "vertexKind", n, [&](std::size_t i) {
    out << static_cast<int>(i < mesh.vertexKinds.size() ? mesh.vertexKinds[i] : 0);
  });
  out << "      </PointData>\n";
}

// t triangles, then `lines` subsegments (0 without VtuOptions::segmentCells).
void printCellData(TextOut& out, const Mesh& mesh, std::size_t t, std::size_t lines) {
  out << "      <CellData>\n";
  dataArray(out, "Float64", "regionAttribute", t + lines,
            [&](std::size_t i) { out << (i < t ? realText(detail::triangleAttribute(mesh, i)) : "0"); });
  dataArray(out, "Float64", "minAngle", t + lines,
            [&](std::size_t i) { out << (i < t ? realText(detail::smallestAngleDegrees(mesh, i)) : "0"); });
  if (lines > 0) {
    dataArray(out, "Int32", "segmentMarker", t + lines,
              [&](std::size_t i) { out << (i < t || i - t >= mesh.segmentMarkers.size() ? 0 : mesh.segmentMarkers[i - t]); });
  }
  out << "      </CellData>\n";
}

void printPoints(TextOut& out, const Mesh& mesh, std::size_t n) {
  out << "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    out << "          " << realText(mesh.points[2 * i]) << ' ' << realText(mesh.points[2 * i + 1]) << " 0\n";
  }
  out << "        </DataArray>\n      </Points>\n";
}

void printCells(TextOut& out, const Mesh& mesh, std::size_t t, std::size_t lines) {
  out << "      <Cells>\n";
  dataArray(out, "Int64", "connectivity", 3 * t + 2 * lines,
            [&](std::size_t i) { out << (i < 3 * t ? mesh.triangles[i] : mesh.segments[i - 3 * t]); });
  dataArray(out, "Int64", "offsets", t + lines,
            [&](std::size_t i) { out << (i < t ? 3 * (i + 1) : 3 * t + 2 * (i - t + 1)); });
  dataArray(out, "UInt8", "types", t + lines, [&](std::size_t i) { out << (i < t ? kVtkTriangle : kVtkLine); });
  out << "      </Cells>\n";
}

void printVtu(TextOut& out, const Mesh& mesh, const VtuOptions& options) {
  detail::requireFiniteValues(mesh.points, "points");
  detail::requireFiniteValues(mesh.triangleAttributes, "triangleAttributes");
  detail::requireTriangleIndices(mesh);
  const std::size_t n = mesh.points.size() / 2, t = mesh.triangles.size() / 3;
  const std::size_t lines = options.segmentCells ? mesh.segments.size() / 2 : 0;
  if (lines > 0) detail::requireSegmentIndices(mesh);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << t + lines << "\">\n";
  printPointData(out, mesh, n);
  printCellData(out, mesh, t, lines);
  printPoints(out, mesh, n);
  printCells(out, mesh, t, lines);
  out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void writeVtu(std::ostream& out, const Mesh& mesh, const VtuOptions& options) {
  detail::toStream(out, ".vtu", [&](TextOut& t) { printVtu(t, mesh, options); });
}

std::string toVtu(const Mesh& mesh, const VtuOptions& options) {
  return detail::toText([&](TextOut& t) { printVtu(t, mesh, options); });
}

}  // namespace ruppert
RUPPERT_COLD_END
