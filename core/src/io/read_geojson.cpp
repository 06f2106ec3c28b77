// GeoJSON (RFC 7946) polygons as a PLC: Polygon, MultiPolygon, Feature, FeatureCollection and
// GeometryCollection of them.
//
//   * Every ring becomes a closed chain of segments. A closing position equal to the first (RFC 7946
//     requires one) is dropped, as are repeated consecutive positions; an unclosed ring is closed.
//     A ring needs 3 distinct positions. Positions may carry a third number (altitude): ignored.
//   * Equal positions anywhere in the document are one point, and an edge shared by two rings (two
//     adjacent polygons) is one segment, so neighboring polygons mesh as one domain without notices.
//   * The domain is the union of the polygons: what an inner ring encloses is a hole unless another
//     polygon covers it (an island, or a polygon filling the hole, as GIS layers often have), and so
//     is an area enclosed by polygons but covered by none (a courtyard). Each such area gets a hole
//     seed (holeSeeds below): the caller needs none.
//   * Features with a null geometry have no shape and are skipped; any other geometry type is an
//     error. Properties, "bbox" and foreign members are ignored; coordinates are used as given.
// Errors name the path of the offending value (features[3].geometry.coordinates[1][4]) and its
// line and column: ParseError for text that is not JSON, MalformedInput for JSON of the wrong shape.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <istream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "io/json_tree.h"
#include "ruppert/ruppert.h"

#include "cold_code.h"

RUPPERT_COLD_BEGIN
namespace ruppert {
namespace {

using detail::JsonValue;

struct Ring {
  std::vector<std::uint32_t> ids;  // point indices, closing vertex not repeated
  std::string path;
  std::size_t offset = 0;
  double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;  // its bounding box
};

struct Polygon {
  std::vector<Ring> rings;  // rings[0] is the exterior
};

class GeoJsonReader {
 public:
  GeoJsonReader(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  Plc read() {
    const JsonValue root = detail::parseJsonTree(text_, name_);
    if (root.kind != JsonValue::Kind::Object) {
      fail(root, "the top level", "must be a GeoJSON object (FeatureCollection, Feature, Polygon or MultiPolygon)");
    }
    object(root, "");
    if (polygons_.empty()) fail(root, "the document", "holds no Polygon or MultiPolygon");
    holeSeeds();
    plc_.indexBase = 0;
    return std::move(plc_);
  }

 private:
  [[noreturn]] void fail(const JsonValue& at, const std::string& path, const std::string& what) const {
    throw Error(ErrorCode::MalformedInput,
                name_ + ":" + detail::jsonPosition(text_, at.offset) + ": " + (path.empty() ? "the top level" : path) +
                    " " + what);
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  std::string typeOf(const JsonValue& v, const std::string& path) const {
    const JsonValue* type = v.find("type");
    if (type == nullptr) fail(v, path, "has no \"type\"");
    if (type->kind != JsonValue::Kind::String) fail(*type, join(path, "type"), "must be a string");
    return type->text;
  }

  const JsonValue& member(const JsonValue& v, const std::string& path, const char* key, JsonValue::Kind kind) const {
    const JsonValue* m = v.find(key);
    if (m == nullptr) fail(v, path, std::string("has no \"") + key + "\"");
    if (m->kind != kind) {
      fail(*m, join(path, key), std::string("must be ") + detail::jsonKindName(kind) + ", not " + detail::jsonKindName(m->kind));
    }
    return *m;
  }

  void object(const JsonValue& v, const std::string& path) {
    const std::string type = typeOf(v, path);
    if (type == "FeatureCollection") {
      const JsonValue& features = member(v, path, "features", JsonValue::Kind::Array);
      for (std::size_t i = 0; i < features.items.size(); ++i) {
        const std::string at = join(path, "features[" + std::to_string(i) + "]");
        const JsonValue& f = features.items[i];
        if (f.kind != JsonValue::Kind::Object || typeOf(f, at) != "Feature") fail(f, at, "must be a Feature object");
        object(f, at);
      }
      if (features.numeric && !features.numbers.empty()) fail(features, join(path, "features[0]"), "must be a Feature object");
    } else if (type == "Feature") {
      const JsonValue* g = v.find("geometry");
      if (g == nullptr) fail(v, path, "has no \"geometry\"");
      if (g->kind == JsonValue::Kind::Null) return;  // an unlocated feature: nothing to mesh
      if (g->kind != JsonValue::Kind::Object) fail(*g, join(path, "geometry"), "must be an object or null");
      geometry(*g, join(path, "geometry"));
    } else {
      geometry(v, path);
    }
  }

  void geometry(const JsonValue& g, const std::string& path) {
    const std::string type = typeOf(g, path);
    if (type == "Polygon") {
      polygon(member(g, path, "coordinates", JsonValue::Kind::Array), join(path, "coordinates"));
    } else if (type == "MultiPolygon") {
      const JsonValue& c = member(g, path, "coordinates", JsonValue::Kind::Array);
      const std::string at = join(path, "coordinates");
      if (c.numeric && !c.numbers.empty()) fail(c, at + "[0]", "must be a polygon (an array of rings)");
      for (std::size_t i = 0; i < c.items.size(); ++i) polygon(c.items[i], at + "[" + std::to_string(i) + "]");
    } else if (type == "GeometryCollection") {
      const JsonValue& gs = member(g, path, "geometries", JsonValue::Kind::Array);
      for (std::size_t i = 0; i < gs.items.size(); ++i) {
        const std::string at = join(path, "geometries[" + std::to_string(i) + "]");
        if (gs.items[i].kind != JsonValue::Kind::Object) fail(gs.items[i], at, "must be a geometry object");
        geometry(gs.items[i], at);
      }
    } else {
      fail(g, path, "has type \"" + type + "\"; only Polygon and MultiPolygon (in a Feature, FeatureCollection or "
                    "GeometryCollection) enclose a domain");
    }
  }

  void polygon(const JsonValue& c, const std::string& path) {
    if (c.kind != JsonValue::Kind::Array || c.numeric) {
      fail(c, path, c.kind == JsonValue::Kind::Array && c.numbers.empty() ? "has no rings; a polygon needs an exterior ring"
                                                                          : "must be an array of rings");
    }
    Polygon p;
    for (std::size_t r = 0; r < c.items.size(); ++r) p.rings.push_back(ring(c.items[r], path + "[" + std::to_string(r) + "]"));
    polygons_.push_back(std::move(p));
  }

  Ring ring(const JsonValue& c, const std::string& path) {
    if (c.kind != JsonValue::Kind::Array || (c.numeric && !c.numbers.empty())) {
      fail(c, path, "must be a ring: an array of positions [x, y]");
    }
    Ring ring;
    ring.path = path;
    ring.offset = c.offset;
    for (std::size_t k = 0; k < c.items.size(); ++k) {
      const JsonValue& pos = c.items[k];
      if (pos.kind != JsonValue::Kind::Array || !pos.numeric || pos.numbers.size() < 2) {
        fail(pos, path + "[" + std::to_string(k) + "]", "must be a position [x, y] of numbers");
      }
      const std::uint32_t id = pointId(pos.numbers[0], pos.numbers[1]);
      if (ring.ids.empty() || ring.ids.back() != id) ring.ids.push_back(id);
    }
    while (ring.ids.size() > 1 && ring.ids.back() == ring.ids.front()) ring.ids.pop_back();
    std::vector<std::uint32_t> distinct = ring.ids;
    std::sort(distinct.begin(), distinct.end());
    const std::size_t count = static_cast<std::size_t>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
    if (count < 3) {
      fail(c, path, "has " + std::to_string(count) + " distinct position" + (count == 1 ? "" : "s") +
                        "; a ring needs at least 3");
    }
    for (std::size_t k = 0; k < ring.ids.size(); ++k) {
      addSegment(ring.ids[k], ring.ids[(k + 1) % ring.ids.size()]);
      ring.minX = std::min(ring.minX, x(ring.ids[k]));
      ring.maxX = std::max(ring.maxX, x(ring.ids[k]));
      ring.minY = std::min(ring.minY, y(ring.ids[k]));
      ring.maxY = std::max(ring.maxY, y(ring.ids[k]));
    }
    return ring;
  }

  std::uint32_t pointId(double x, double y) {
    const auto [it, inserted] = pointIds_.emplace(std::make_pair(x, y), static_cast<std::uint32_t>(pointIds_.size()));
    if (inserted) {
      plc_.points.push_back(x);
      plc_.points.push_back(y);
    }
    return it->second;
  }

  void addSegment(std::uint32_t a, std::uint32_t b) {
    if (!segmentSet_.insert(std::minmax(a, b)).second) return;
    plc_.segments.push_back(a);
    plc_.segments.push_back(b);
  }

  double x(std::uint32_t id) const { return plc_.points[2 * static_cast<std::size_t>(id)]; }
  double y(std::uint32_t id) const { return plc_.points[2 * static_cast<std::size_t>(id) + 1]; }

  // Even-odd crossing test of (px, py) against one ring.
  bool insideRing(const Ring& r, double px, double py) const {
    // Outside the box is outside the ring: most rings are judged by four comparisons.
    if (px < r.minX || px > r.maxX || py < r.minY || py > r.maxY) return false;
    bool inside = false;
    for (std::size_t k = 0, j = r.ids.size() - 1; k < r.ids.size(); j = k++) {
      const double xi = x(r.ids[k]), yi = y(r.ids[k]), xj = x(r.ids[j]), yj = y(r.ids[j]);
      if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
  }

  bool insidePolygon(const Polygon& p, double px, double py) const {
    if (!insideRing(p.rings[0], px, py)) return false;
    for (std::size_t r = 1; r < p.rings.size(); ++r) {
      if (insideRing(p.rings[r], px, py)) return false;
    }
    return true;
  }

  bool covered(double px, double py) const {
    for (const Polygon& p : polygons_) {
      if (insidePolygon(p, px, py)) return true;
    }
    return false;
  }

  // The domain is the union of the polygons. The segments cut the plane into faces; a face that no
  // polygon covers but segments enclose (inside an inner ring, or a courtyard between polygons) gets
  // a hole seed. The faces are found on the constrained Delaunay triangulation of the segments'
  // convex hull: triangles joined across edges that are not subsegments. Each face is judged by the
  // centroid of its largest triangle, which lies strictly inside the face, as far from its edges as
  // that face's triangles allow; faces reaching the convex hull are outside the domain anyway.
  void holeSeeds() {
    Options cdt;
    cdt.minAngle = 0;
    cdt.convexHull = true;
    Mesh mesh;
    try {
      mesh = triangulate(plc_, cdt);
    } catch (const Error&) {
      return;  // input the mesher rejects: triangulate() will say why, with or without seeds
    }
    const std::size_t n = mesh.triangles.size() / 3;
    std::set<std::pair<std::uint32_t, std::uint32_t>> subsegments, hull;
    for (std::size_t s = 0; s < mesh.segments.size() / 2; ++s) {
      const auto edge = std::minmax(mesh.segments[2 * s], mesh.segments[2 * s + 1]);
      subsegments.insert(edge);
      if (mesh.segmentIds[s] == kNoInputSegment) hull.insert(edge);
    }
    std::vector<char> seen(n, 0);
    std::vector<std::size_t> stack;
    for (std::size_t start = 0; start < n; ++start) {
      if (seen[start]) continue;
      seen[start] = 1;
      stack.assign(1, start);
      std::size_t largest = start;
      double largestArea = -1;
      bool outer = false;
      while (!stack.empty()) {
        const std::size_t t = stack.back();
        stack.pop_back();
        const double area = triangleArea(mesh, t);
        if (area > largestArea) {
          largestArea = area;
          largest = t;
        }
        for (int i = 0; i < 3; ++i) {
          const auto edge = std::minmax(mesh.triangles[3 * t + (i + 1) % 3], mesh.triangles[3 * t + (i + 2) % 3]);
          const std::int32_t across = mesh.neighbors[3 * t + i];
          if (across == kNoNeighbor) {
            if (!subsegments.count(edge) || hull.count(edge)) outer = true;
            continue;
          }
          if (subsegments.count(edge) || seen[static_cast<std::size_t>(across)]) continue;
          seen[static_cast<std::size_t>(across)] = 1;
          stack.push_back(static_cast<std::size_t>(across));
        }
      }
      if (outer) continue;
      double cx = 0, cy = 0;
      for (int k = 0; k < 3; ++k) {
        cx += mesh.points[2 * static_cast<std::size_t>(mesh.triangles[3 * largest + k])] / 3;
        cy += mesh.points[2 * static_cast<std::size_t>(mesh.triangles[3 * largest + k]) + 1] / 3;
      }
      if (!covered(cx, cy)) {
        plc_.holes.push_back(cx);
        plc_.holes.push_back(cy);
      }
    }
  }

  static double triangleArea(const Mesh& m, std::size_t t) {
    const double* a = &m.points[2 * static_cast<std::size_t>(m.triangles[3 * t])];
    const double* b = &m.points[2 * static_cast<std::size_t>(m.triangles[3 * t + 1])];
    const double* c = &m.points[2 * static_cast<std::size_t>(m.triangles[3 * t + 2])];
    return ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
  }

  const std::string& text_;
  const std::string& name_;
  Plc plc_;
  std::vector<Polygon> polygons_;
  std::map<std::pair<double, double>, std::uint32_t> pointIds_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> segmentSet_;
};

}  // namespace

Plc parseGeoJson(const std::string& text, const std::string& name) { return GeoJsonReader(text, name).read(); }

Plc readGeoJson(std::istream& in, const std::string& name) {
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(ErrorCode::IoError, name + ": read failed");
  return parseGeoJson(text, name);
}

}  // namespace ruppert
RUPPERT_COLD_END
