// VTK's XML UnstructuredGrid (.vtu), ASCII, from VTK's "VTK File Formats" documentation: what
// ParaView and VisIt open.
//
//   Points     x y 0 per point (every point, unused ones too, so indices match mesh.points)
//   Cells      one VTK_TRIANGLE (type 5) per triangle, in mesh.triangles order
//   PointData  "vertexKind" (UInt8, ruppert::VertexKind); "pointMarker" (Int32) when the mesh has
//              one marker per point
//   CellData   "regionAttribute" (Float64) and "minAngle" (Float64, the triangle's smallest angle in
//              degrees)
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

void printCellData(TextOut& out, const Mesh& mesh, std::size_t t) {
  out << "      <CellData>\n";
  dataArray(out, "Float64", "regionAttribute", t,
            [&](std::size_t i) { out << realText(detail::triangleAttribute(mesh, i)); });
  dataArray(out, "Float64", "minAngle", t,
            [&](std::size_t i) { out << realText(detail::smallestAngleDegrees(mesh, i)); });
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

void printCells(TextOut& out, const Mesh& mesh, std::size_t t) {
  out << "      <Cells>\n";
  dataArray(out, "Int64", "connectivity", 3 * t, [&](std::size_t i) { out << mesh.triangles[i]; });
  dataArray(out, "Int64", "offsets", t, [&](std::size_t i) { out << 3 * (i + 1); });
  dataArray(out, "UInt8", "types", t, [&](std::size_t) { out << kVtkTriangle; });
  out << "      </Cells>\n";
}

void printVtu(TextOut& out, const Mesh& mesh) {
  detail::requireFiniteValues(mesh.points, "points");
  detail::requireFiniteValues(mesh.triangleAttributes, "triangleAttributes");
  detail::requireTriangleIndices(mesh);
  const std::size_t n = mesh.points.size() / 2, t = mesh.triangles.size() / 3;
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << t << "\">\n";
  printPointData(out, mesh, n);
  printCellData(out, mesh, t);
  printPoints(out, mesh, n);
  printCells(out, mesh, t);
  out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void writeVtu(std::ostream& out, const Mesh& mesh) {
  detail::toStream(out, ".vtu", [&](TextOut& t) { printVtu(t, mesh); });
}

std::string toVtu(const Mesh& mesh) { return detail::toText([&](TextOut& t) { printVtu(t, mesh); }); }

}  // namespace ruppert
RUPPERT_COLD_END
