// Gmsh's MSH 4.1 ASCII format, from the format's documentation (Gmsh reference manual, "MSH file
// format"): $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements.
//
// How a ruppert mesh maps onto it:
//   * Triangles are elements of type 2; subsegments (every input segment's pieces, and convex-hull
//     edges) are elements of type 1. Element tags: triangle t is t + 1, subsegment s is T + s + 1
//     (T triangles), so a solver can map elements back to mesh.triangles and mesh.segments.
//   * One surface entity per distinct region attribute, one curve entity per distinct subsegment
//     marker; each entity is its own physical group (same tag), named "attribute A" or "marker M".
//   * Physical tags: a marker or attribute that is a whole number from 1 to 2^31 - 1 is its own tag
//     (marker 5 is physical curve 5, what a solver's boundary condition names); the other values
//     (0, negatives, fractions) take the tags after the largest such, in increasing order of value.
//   * Nodes: node tag = point index + 1, every point (unused ones too, so indices match), in one
//     block classified on the first surface entity; z = 0.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ruppert/ruppert.h"
#include "output/subsegment_marker.h"
#include "io/write_common.h"

#include "cold_code.h"

RUPPERT_COLD_BEGIN
namespace ruppert {
namespace {

using detail::realText;
using detail::TextOut;

// The elements of one entity (and physical group): what they share, and their bounding box.
struct Group {
  double value = 0;
  std::int64_t tag = 0;
  std::vector<std::size_t> elements;  // triangle or subsegment indices
  double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
};

bool isOwnTag(double v) { return v >= 1 && v <= 2147483647.0 && v == std::floor(v); }

// Groups in increasing order of value, with the tags the header comment describes.
std::vector<Group> groupsOf(const std::map<double, std::vector<std::size_t>>& byValue) {
  std::vector<Group> groups;
  std::int64_t next = 1;
  for (const auto& [value, elements] : byValue) {
    if (isOwnTag(value)) next = std::max(next, static_cast<std::int64_t>(value) + 1);
  }
  for (const auto& [value, elements] : byValue) {
    Group g;
    g.value = value;
    g.tag = isOwnTag(value) ? static_cast<std::int64_t>(value) : next++;
    g.elements = elements;
    groups.push_back(std::move(g));
  }
  return groups;
}

void growBox(Group& g, const Mesh& mesh, std::uint32_t v) {
  const double x = mesh.points[2 * static_cast<std::size_t>(v)], y = mesh.points[2 * static_cast<std::size_t>(v) + 1];
  g.minX = std::min(g.minX, x);
  g.maxX = std::max(g.maxX, x);
  g.minY = std::min(g.minY, y);
  g.maxY = std::max(g.maxY, y);
}

std::vector<Group> surfaceGroups(const Mesh& mesh) {
  std::map<double, std::vector<std::size_t>> byValue;
  const std::size_t n = mesh.triangles.size() / 3;
  for (std::size_t t = 0; t < n; ++t) byValue[detail::triangleAttribute(mesh, t)].push_back(t);
  if (byValue.empty()) byValue[0];  // the nodes need an entity to be classified on
  std::vector<Group> groups = groupsOf(byValue);
  for (Group& g : groups) {
    for (std::size_t t : g.elements) {
      for (int k = 0; k < 3; ++k) growBox(g, mesh, mesh.triangles[3 * t + k]);
    }
  }
  return groups;
}

std::vector<Group> curveGroups(const Mesh& mesh, const Plc& input) {
  std::map<double, std::vector<std::size_t>> byValue;
  for (std::size_t s = 0; s < mesh.segments.size() / 2; ++s) {
    byValue[detail::subsegmentMarker(mesh, input, s)].push_back(s);
  }
  std::vector<Group> groups = groupsOf(byValue);
  for (Group& g : groups) {
    for (std::size_t s : g.elements) {
      growBox(g, mesh, mesh.segments[2 * s]);
      growBox(g, mesh, mesh.segments[2 * s + 1]);
    }
  }
  return groups;
}

// "5" for whole numbers, else %.17g: the names are for people reading Gmsh's tree.
std::string valueName(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<std::int64_t>(v));
  return realText(v);
}

std::string box(const Group& g) {
  const bool empty = !(g.minX <= g.maxX);
  return empty ? std::string("0 0 0 0 0 0")
               : realText(g.minX) + ' ' + realText(g.minY) + " 0 " + realText(g.maxX) + ' ' + realText(g.maxY) + " 0";
}

void printHeaderAndNames(TextOut& out, const std::vector<Group>& surfaces, const std::vector<Group>& curves) {
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n" << (surfaces.size() + curves.size()) << '\n';
  for (const Group& g : curves) out << "1 " << g.tag << " \"marker " << valueName(g.value) << "\"\n";
  for (const Group& g : surfaces) out << "2 " << g.tag << " \"attribute " << valueName(g.value) << "\"\n";
  out << "$EndPhysicalNames\n";
}

void printEntities(TextOut& out, const std::vector<Group>& surfaces, const std::vector<Group>& curves) {
  // Points, curves, surfaces, volumes; no entity lists a boundary (these are discrete entities).
  out << "$Entities\n0 " << curves.size() << ' ' << surfaces.size() << " 0\n";
  for (const Group& g : curves) out << g.tag << ' ' << box(g) << " 1 " << g.tag << " 0\n";
  for (const Group& g : surfaces) out << g.tag << ' ' << box(g) << " 1 " << g.tag << " 0\n";
  out << "$EndEntities\n";
}

void printNodes(TextOut& out, const Mesh& mesh, std::int64_t surfaceTag) {
  const std::size_t n = mesh.points.size() / 2;
  out << "$Nodes\n";
  if (n == 0) {
    out << "0 0 0 0\n$EndNodes\n";
    return;
  }
  out << "1 " << n << " 1 " << n << '\n' << "2 " << surfaceTag << " 0 " << n << '\n';
  for (std::size_t i = 0; i < n; ++i) out << (i + 1) << '\n';
  for (std::size_t i = 0; i < n; ++i) {
    out << realText(mesh.points[2 * i]) << ' ' << realText(mesh.points[2 * i + 1]) << " 0\n";
  }
  out << "$EndNodes\n";
}

void printElements(TextOut& out, const Mesh& mesh, const std::vector<Group>& surfaces,
                   const std::vector<Group>& curves) {
  const std::size_t triangles = mesh.triangles.size() / 3, lines = mesh.segments.size() / 2;
  std::size_t blocks = 0;
  for (const Group& g : surfaces) blocks += g.elements.empty() ? 0 : 1;
  blocks += curves.size();
  const std::size_t total = triangles + lines;
  out << "$Elements\n" << blocks << ' ' << total << ' ' << (total ? 1 : 0) << ' ' << total << '\n';
  for (const Group& g : surfaces) {
    if (g.elements.empty()) continue;
    out << "2 " << g.tag << " 2 " << g.elements.size() << '\n';
    for (std::size_t t : g.elements) {
      out << (t + 1) << ' ' << (mesh.triangles[3 * t] + 1ull) << ' ' << (mesh.triangles[3 * t + 1] + 1ull) << ' '
          << (mesh.triangles[3 * t + 2] + 1ull) << '\n';
    }
  }
  for (const Group& g : curves) {
    out << "1 " << g.tag << " 1 " << g.elements.size() << '\n';
    for (std::size_t s : g.elements) {
      out << (triangles + s + 1) << ' ' << (mesh.segments[2 * s] + 1ull) << ' ' << (mesh.segments[2 * s + 1] + 1ull)
          << '\n';
    }
  }
  out << "$EndElements\n";
}

void printMsh(TextOut& out, const Mesh& mesh, const Plc& input) {
  detail::requireFiniteValues(mesh.points, "points");
  detail::requireFiniteValues(mesh.triangleAttributes, "triangleAttributes");
  detail::requireTriangleIndices(mesh);
  detail::requireSegmentIndices(mesh);
  const std::vector<Group> surfaces = surfaceGroups(mesh);
  const std::vector<Group> curves = curveGroups(mesh, input);
  printHeaderAndNames(out, surfaces, curves);
  printEntities(out, surfaces, curves);
  printNodes(out, mesh, surfaces.front().tag);
  printElements(out, mesh, surfaces, curves);
}

}  // namespace

void writeMsh(std::ostream& out, const Mesh& mesh, const Plc& input) {
  detail::toStream(out, ".msh", [&](TextOut& t) { printMsh(t, mesh, input); });
}

std::string toMsh(const Mesh& mesh, const Plc& input) {
  return detail::toText([&](TextOut& t) { printMsh(t, mesh, input); });
}

}  // namespace ruppert
RUPPERT_COLD_END
