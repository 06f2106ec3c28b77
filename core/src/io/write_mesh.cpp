// Writers: Triangle's .node/.ele/.poly, JSON and SVG.
//
// Coordinates are printed with %.17g: 17 significant digits identify every double uniquely, so a
// written file reads back bit-exact (strtod rounds correctly). Triangle formats print indices in
// mesh.indexBase so a 1-based input yields 1-based output. JSON indices are always 0-based, as the
// JSON shape in ruppert.h defines them (JavaScript indexes typed arrays from 0).
// Nothing here prints "nan": JSON writes null for a non-finite value, and the text formats refuse a
// non-finite coordinate (Internal error) before writing a byte.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "ruppert/ruppert.h"
#include "output/boundary_markers.h"
#include "io/text_out.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert {
namespace {

using detail::TextOut;
using detail::toStream;
using detail::toText;

// %.17g of a finite value.
std::string real(double v) { return detail::realText(v); }

std::string jsonReal(double v) { return std::isfinite(v) ? real(v) : "null"; }

int baseOf(const Mesh& mesh) { return mesh.indexBase == 1 ? 1 : 0; }

std::size_t pointCount(const Mesh& mesh) { return mesh.points.size() / 2; }

void requireFinite(const std::vector<double>& values, const char* what) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw Error(ErrorCode::Internal, std::string("cannot write a non-finite coordinate: ") + what + "[" +
                                           std::to_string(i) + "] = " + real(values[i]));
    }
  }
}

// The mesh's markers when it has one per point and per subsegment (every mesh triangulate()
// returns); otherwise, for what is missing, the markers Triangle's convention gives without input
// markers (1 on the boundary, 0 inside: a mesh handed back from JavaScript without them).
detail::Markers markersOf(const Mesh& mesh) {
  const bool points = mesh.pointMarkers.size() == pointCount(mesh);
  const bool segments = mesh.segmentMarkers.size() == mesh.segments.size() / 2;
  detail::Markers m = points && segments ? detail::Markers{} : detail::computeMarkers(mesh, Plc{});
  if (points) m.points = mesh.pointMarkers;
  if (segments) m.segments = mesh.segmentMarkers;
  return m;
}

void writePoints(TextOut& out, const Mesh& mesh) {
  requireFinite(mesh.points, "points");
  const std::vector<std::int32_t> markers = markersOf(mesh).points;
  const std::size_t base = static_cast<std::size_t>(baseOf(mesh));
  // Attribute columns (Plc::pointAttributes, interpolated onto new vertices) when there are any.
  const std::size_t k = mesh.pointAttributes.size() == mesh.attributesPerPoint * pointCount(mesh) ? mesh.attributesPerPoint : 0;
  if (k) requireFinite(mesh.pointAttributes, "pointAttributes");
  out << pointCount(mesh) << " 2 " << k << " 1\n";
  for (std::size_t i = 0; i < pointCount(mesh); ++i) {
    out << (i + base) << ' ' << real(mesh.points[2 * i]) << ' ' << real(mesh.points[2 * i + 1]) << ' ';
    for (std::size_t j = 0; j < k; ++j) out << real(mesh.pointAttributes[k * i + j]) << ' ';
    out << markers[i] << '\n';
  }
}

bool anyNonZero(const std::vector<double>& values) {
  return std::any_of(values.begin(), values.end(), [](double v) { return v != 0; });
}

// JSON string with the escapes RFC 8259 requires.
std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

template <typename T, typename Format>
void jsonArray(TextOut& out, const char* key, const std::vector<T>& values, Format format) {
  out << "  \"" << key << "\": [";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out << ',';
    out << format(values[i]);
  }
  out << "]";
}

template <typename T>
std::string integer(T v) { return std::to_string(v); }

const char* reasonName(ReasonKind kind) {
  switch (kind) {
    case ReasonKind::SmallInputAngle: return "smallInputAngle";
    case ReasonKind::SeditiousEdge: return "seditiousEdge";
    case ReasonKind::SteinerBudget: return "steinerBudget";
    case ReasonKind::PrecisionFloor: return "precisionFloor";
    case ReasonKind::Cancelled: return "cancelled";
    case ReasonKind::AngleUnreachable: return "angleUnreachable";
    case ReasonKind::SegmentSplitForbidden: return "segmentSplitForbidden";
  }
  return "unknown";
}

const char* noticeName(NoticeKind kind) {
  switch (kind) {
    case NoticeKind::DuplicatePoint: return "duplicatePoint";
    case NoticeKind::ZeroLengthSegment: return "zeroLengthSegment";
    case NoticeKind::DuplicateSegment: return "duplicateSegment";
    case NoticeKind::VertexOnSegment: return "vertexOnSegment";
    case NoticeKind::SegmentsCross: return "segmentsCross";
    case NoticeKind::SegmentsOverlap: return "segmentsOverlap";
    case NoticeKind::HoleOutsideDomain: return "holeOutsideDomain";
    case NoticeKind::RegionOutsideDomain: return "regionOutsideDomain";
    case NoticeKind::NothingEnclosed: return "nothingEnclosed";
  }
  return "unknown";
}

void jsonStats(TextOut& out, const Stats& s) {
  out << "  \"stats\": {\"vertices\": " << s.vertices << ", \"triangles\": " << s.triangles
      << ", \"minAngle\": " << jsonReal(s.minAngle) << ", \"maxAngle\": " << jsonReal(s.maxAngle)
      << ", \"reachedAngle\": " << jsonReal(s.reachedAngle)
      << ", \"angleHistogram\": [";
  for (std::size_t i = 0; i < s.angleHistogram.size(); ++i) out << (i ? "," : "") << s.angleHistogram[i];
  out << "], \"inputVertices\": " << s.inputVertices << ", \"segmentVertices\": " << s.segmentVertices
      << ", \"interiorVertices\": " << s.interiorVertices << ", \"offCenterVertices\": " << s.offCenterVertices
      << ", \"intersectionVertices\": " << s.intersectionVertices
      << ", \"rejectedCircumcenters\": " << s.rejectedCircumcenters << ", \"lfsIntegral\": " << jsonReal(s.lfsIntegral)
      << ", \"trianglesPerLfsIntegral\": " << jsonReal(s.trianglesPerLfsIntegral)
      << ", \"milliseconds\": " << jsonReal(s.milliseconds) << "}";
}


void printNode(TextOut& out, const Mesh& mesh) {
  writePoints(out, mesh);
}

void printEle(TextOut& out, const Mesh& mesh) {
  const std::size_t n = mesh.triangles.size() / 3;
  const std::size_t base = static_cast<std::size_t>(baseOf(mesh));
  // Region attributes are written (Triangle's -A output) only when some triangle has one.
  const bool attributes = mesh.triangleAttributes.size() == n && anyNonZero(mesh.triangleAttributes);
  if (attributes) requireFinite(mesh.triangleAttributes, "triangleAttributes");
  const bool six = mesh.triangles6.size() == 6 * n && n > 0;  // addQuadraticNodes' 6-node triangles
  out << n << (six ? " 6 " : " 3 ") << (attributes ? 1 : 0) << '\n';
  for (std::size_t t = 0; t < n; ++t) {
    out << (t + base) << ' ' << (mesh.triangles[3 * t] + base) << ' ' << (mesh.triangles[3 * t + 1] + base) << ' '
        << (mesh.triangles[3 * t + 2] + base);
    for (std::size_t i = 3; six && i < 6; ++i) out << ' ' << (mesh.triangles6[6 * t + i] + base);
    if (attributes) out << ' ' << real(mesh.triangleAttributes[t]);
    out << '\n';
  }
}

void printEdge(TextOut& out, const Mesh& mesh) {
  MeshEdges computed;
  const bool own = !mesh.edges.empty() && mesh.edgeMarkers.size() == mesh.edges.size() / 2;
  if (!own) computed = detail::edgesWith(mesh, markersOf(mesh).segments);
  const std::vector<std::uint32_t>& edges = own ? mesh.edges : computed.edges;
  const std::vector<std::int32_t>& markers = own ? mesh.edgeMarkers : computed.markers;
  const std::size_t base = static_cast<std::size_t>(baseOf(mesh));
  out << markers.size() << " 1\n";
  for (std::size_t e = 0; e < markers.size(); ++e)
    out << (e + base) << ' ' << (edges[2 * e] + base) << ' ' << (edges[2 * e + 1] + base) << ' ' << markers[e] << '\n';
}

void printPoly(TextOut& out, const Mesh& mesh, const Plc& input) {
  const std::vector<std::int32_t> segmentMarkers = markersOf(mesh).segments;
  requireFinite(input.holes, "holes");
  for (std::size_t i = 0; i < input.regions.size(); ++i) {
    const Region& r = input.regions[i];
    requireFinite({r.x, r.y, r.attribute, r.maxArea}, ("regions[" + std::to_string(i) + "]").c_str());
  }
  writePoints(out, mesh);
  const std::size_t base = static_cast<std::size_t>(baseOf(mesh));
  const std::size_t n = mesh.segments.size() / 2;
  out << n << " 1\n";
  for (std::size_t s = 0; s < n; ++s) {
    // The boundary marker (ruppert.h, "Boundary markers"): the input segment's, or 1 / 0.
    out << (s + base) << ' ' << (mesh.segments[2 * s] + base) << ' ' << (mesh.segments[2 * s + 1] + base) << ' '
        << segmentMarkers[s] << '\n';
  }
  const std::size_t holes = input.holes.size() / 2;
  out << holes << '\n';
  for (std::size_t h = 0; h < holes; ++h) {
    out << (h + base) << ' ' << real(input.holes[2 * h]) << ' ' << real(input.holes[2 * h + 1]) << '\n';
  }
  out << input.regions.size() << '\n';
  for (std::size_t i = 0; i < input.regions.size(); ++i) {
    const Region& r = input.regions[i];
    // Triangle reads a negative area as "no bound"; Plc spells that as <= 0.
    out << (i + base) << ' ' << real(r.x) << ' ' << real(r.y) << ' ' << real(r.attribute) << ' '
        << (r.maxArea > 0 ? real(r.maxArea) : "-1") << '\n';
  }
}

void printJson(TextOut& out, const Mesh& mesh, const Plc& input) {
  auto number = [](double v) { return jsonReal(v); };
  auto whole = [](auto v) { return integer(v); };
  out << "{\n";
  jsonArray(out, "points", mesh.points, number);
  out << ",\n";
  jsonArray(out, "segments", mesh.segments, whole);
  out << ",\n";
  jsonArray(out, "holes", input.holes, number);
  out << ",\n  \"regions\": [";
  for (std::size_t i = 0; i < input.regions.size(); ++i) {
    const Region& r = input.regions[i];
    out << (i ? ", " : "") << "{\"x\": " << jsonReal(r.x) << ", \"y\": " << jsonReal(r.y)
        << ", \"attribute\": " << jsonReal(r.attribute) << ", \"maxArea\": " << jsonReal(r.maxArea) << "}";
  }
  out << "],\n";
  jsonArray(out, "triangles", mesh.triangles, whole);
  out << ",\n";
  jsonArray(out, "neighbors", mesh.neighbors, whole);
  out << ",\n";
  jsonArray(out, "segmentIds", mesh.segmentIds, whole);
  out << ",\n";
  jsonArray(out, "vertexKinds", mesh.vertexKinds, [](std::uint8_t v) { return integer(static_cast<int>(v)); });
  out << ",\n";
  jsonArray(out, "triangleAttributes", mesh.triangleAttributes, number);
  // Boundary markers always; edges, attributes and jettison's numbering when present.
  const detail::Markers markers = markersOf(mesh);
  out << ",\n";
  jsonArray(out, "pointMarkers", markers.points, whole);
  out << ",\n";
  jsonArray(out, "segmentMarkers", markers.segments, whole);
  if (!mesh.edges.empty()) {
    out << ",\n";
    jsonArray(out, "edges", mesh.edges, whole);
    out << ",\n";
    jsonArray(out, "edgeMarkers", mesh.edgeMarkers, whole);
  }
  if (!mesh.pointAttributes.empty()) {
    out << ",\n  \"attributesPerPoint\": " << mesh.attributesPerPoint << ",\n";
    jsonArray(out, "pointAttributes", mesh.pointAttributes, number);
  }
  if (!mesh.inputToOutput.empty()) {
    out << ",\n";
    jsonArray(out, "inputToOutput", mesh.inputToOutput, whole);
  }
  out << ",\n  \"complete\": " << (mesh.complete ? "true" : "false") << ",\n  \"reasons\": [";
  for (std::size_t i = 0; i < mesh.reasons.size(); ++i) {
    const Reason& r = mesh.reasons[i];
    out << (i ? ", " : "") << "{\"kind\": \"" << reasonName(r.kind) << "\", \"count\": " << r.count
        << ", \"message\": " << jsonString(r.message) << "}";
  }
  out << "],\n  \"notices\": [";
  for (std::size_t i = 0; i < mesh.notices.size(); ++i) {
    const Notice& n = mesh.notices[i];
    out << (i ? ", " : "") << "{\"kind\": \"" << noticeName(n.kind) << "\", \"a\": " << n.a << ", \"b\": " << n.b
        << ", \"x\": " << jsonReal(n.x) << ", \"y\": " << jsonReal(n.y) << ", \"message\": " << jsonString(n.message)
        << "}";
  }
  out << "],\n";
  jsonStats(out, mesh.stats);
  out << "\n}\n";
}

void printSvg(TextOut& out, const Mesh& mesh) {
  requireFinite(mesh.points, "points");
  const std::size_t n = pointCount(mesh);
  // Fit the view to the vertices the triangles use (an unused far-away input point would shrink the
  // drawing to a dot); with no triangles, to all points.
  std::vector<char> used(n, mesh.triangles.empty() ? 1 : 0);
  for (std::uint32_t v : mesh.triangles) {
    if (v < n) used[v] = 1;
  }
  double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    if (!used[i]) continue;
    minX = std::min(minX, mesh.points[2 * i]);
    maxX = std::max(maxX, mesh.points[2 * i]);
    minY = std::min(minY, mesh.points[2 * i + 1]);
    maxY = std::max(maxY, mesh.points[2 * i + 1]);
  }
  if (!(minX <= maxX)) minX = maxX = minY = maxY = 0;  // nothing to draw
  double w = maxX - minX, h = maxY - minY;
  const double size = std::max(w, h) > 0 ? std::max(w, h) : 1;
  const double margin = 0.02 * size;
  if (w <= 0) w = size;
  if (h <= 0) h = size;
  // SVG's y axis points down; printing -y makes the picture y-up like the mesh.
  const double viewX = minX - margin, viewY = -maxY - margin, viewW = w + 2 * margin, viewH = h + 2 * margin;
  const double pixels = 1000;
  const double pixelW = viewW >= viewH ? pixels : pixels * viewW / viewH;
  const double pixelH = viewW >= viewH ? pixels * viewH / viewW : pixels;
  auto xy = [&mesh](std::uint32_t v) { return real(mesh.points[2 * v]) + ' ' + real(-mesh.points[2 * v + 1]); };

  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << real(viewX) << ' ' << real(viewY) << ' '
      << real(viewW) << ' ' << real(viewH) << "\" width=\"" << std::lround(pixelW) << "\" height=\""
      << std::lround(pixelH) << "\">\n";
  out << "<title>" << n << " vertices, " << mesh.triangles.size() / 3 << " triangles</title>\n";
  // non-scaling-stroke: line widths in screen pixels whatever the coordinate scale.
  out << "<path fill=\"#dfe9f5\" stroke=\"#3a5a80\" stroke-width=\"0.6\" stroke-linejoin=\"round\" "
         "vector-effect=\"non-scaling-stroke\" d=\"";
  for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
    const std::uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
    if (a >= n || b >= n || c >= n) continue;
    out << 'M' << xy(a) << 'L' << xy(b) << 'L' << xy(c) << 'Z';
  }
  out << "\"/>\n";
  out << "<path fill=\"none\" stroke=\"#111\" stroke-width=\"2\" stroke-linecap=\"round\" "
         "vector-effect=\"non-scaling-stroke\" d=\"";
  for (std::size_t s = 0; s + 1 < mesh.segments.size(); s += 2) {
    const std::uint32_t a = mesh.segments[s], b = mesh.segments[s + 1];
    if (a >= n || b >= n) continue;
    out << 'M' << xy(a) << 'L' << xy(b);
  }
  out << "\"/>\n</svg>\n";
}

}  // namespace

void writeNode(std::ostream& out, const Mesh& mesh) { toStream(out, ".node", [&](TextOut& t) { printNode(t, mesh); }); }
void writeEle(std::ostream& out, const Mesh& mesh) { toStream(out, ".ele", [&](TextOut& t) { printEle(t, mesh); }); }
void writePoly(std::ostream& out, const Mesh& mesh, const Plc& input) {
  toStream(out, ".poly", [&](TextOut& t) { printPoly(t, mesh, input); });
}
void writeJson(std::ostream& out, const Mesh& mesh, const Plc& input) {
  toStream(out, "JSON", [&](TextOut& t) { printJson(t, mesh, input); });
}
void writeEdge(std::ostream& out, const Mesh& mesh) { toStream(out, ".edge", [&](TextOut& t) { printEdge(t, mesh); }); }
std::string toEdge(const Mesh& mesh) { return toText([&](TextOut& t) { printEdge(t, mesh); }); }
void writeSvg(std::ostream& out, const Mesh& mesh) { toStream(out, "SVG", [&](TextOut& t) { printSvg(t, mesh); }); }

std::string toNode(const Mesh& mesh) { return toText([&](TextOut& t) { printNode(t, mesh); }); }
std::string toEle(const Mesh& mesh) { return toText([&](TextOut& t) { printEle(t, mesh); }); }
std::string toPoly(const Mesh& mesh, const Plc& input) { return toText([&](TextOut& t) { printPoly(t, mesh, input); }); }
std::string toJson(const Mesh& mesh, const Plc& input) { return toText([&](TextOut& t) { printJson(t, mesh, input); }); }
std::string toSvg(const Mesh& mesh) { return toText([&](TextOut& t) { printSvg(t, mesh); }); }

}  // namespace ruppert
RUPPERT_COLD_END
