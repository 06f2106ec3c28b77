// Inserting segments into the triangulation as constrained edges, repairing the input on the way:
// a vertex lying in a segment's interior splits it there; two segments that cross are both split at
// their intersection point (a new vertex); collinear overlaps share their common subsegments.
//
// One segment a-b at a time: walk from a towards b collecting the edges the segment crosses, then
// flip them away (Sloan's method: flip any crossing edge whose quadrilateral is strictly convex; the
// others wait their turn), mark a-b constrained, and restore the constrained Delaunay property by
// Lawson flips on the edges the flips created.
#include "cdt/segment_insertion.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cold_code.h"
#include "message.h"
#include "mesh_state.h"
#include "point_attributes.h"
#include "mesh/point_order.h"
#include "mesh/predicates.h"

namespace ruppert::detail {
namespace {

// A rounded crossing is off its segments by a few units in the last place of their coordinates
// (about 2^-52 of their magnitude) and of the shorter one's length, so a point counts as on a piece
// of a segment within 2^-48 (16 ulps) of that scale. Coarser tolerances let pieces of a cluster 1e-13
// across turn through its neighbors (at coordinates near 1, or near a segment 10^12 times longer),
// and the crossing repairs then looped or merged segments that only crossed. Along the segments a
// crossing of two at a small angle can be far less accurate, so a crossing counts as at a vertex
// within 2^-40 (internal coordinates lie within (-2, 2)) if that vertex is on the other segment.
constexpr double kOnPiece = 0x1p-48;
constexpr double kSnap = 0x1p-40;

struct Task {
  std::uint32_t a, b;
  std::int32_t id;
};

std::string segName(std::int32_t id) { return "segments[" + std::to_string(id) + "]"; }

class SegmentInserter {
 public:
  explicit SegmentInserter(MeshState& m) : m_(m), t_(m.tri) {}
  std::uint64_t repairs() const { return repairs_; }

  void insert(std::uint32_t a, std::uint32_t b, std::int32_t id) {
    tasks_.push_back({a, b, id});
    // Every task constrains an edge or splits its piece at a vertex or a new crossing, so a segment
    // takes a few tasks per vertex at most; more means two pieces keep splitting each other, which
    // must end in an error, not in a loop.
    for (std::uint64_t done = 0; !tasks_.empty(); ++done) {
      if (done > 8 * static_cast<std::uint64_t>(t_.vertexCount()) + 1000)
        throw Error(ErrorCode::Internal, "recovering " + segName(id) + " did not converge");
      const Task task = tasks_.back();
      tasks_.pop_back();
      if (task.a != task.b) insertOne(task.a, task.b, task.id);
    }
  }

 private:
  MeshState& m_;
  Triangulation& t_;
  std::vector<Task> tasks_;
  std::uint64_t repairs_ = 0;

  void constrain(std::uint32_t h, std::int32_t id) {
    const std::int32_t old = t_.con[h];
    if (old == kFree || old == kHullEdge || old == id) {
      t_.con[h] = id;
      if (t_.twin[h] != kNone) t_.con[t_.twin[h]] = id;
      return;
    }
    if (id < 0) return;  // a hull edge over an input segment: the input segment keeps it
    // Two input segments share this edge: the earlier segment keeps it; report once per pair.
    const std::uint32_t a0 = m_.segmentEnd(old, 0), b0 = m_.segmentEnd(old, 1);
    const std::uint32_t a1 = m_.segmentEnd(id, 0), b1 = m_.segmentEnd(id, 1);
    const bool same = (a0 == a1 && b0 == b1) || (a0 == b1 && b0 == a1);
    if (same) {
      for (const Notice& n : m_.notices)
        if (n.kind == NoticeKind::DuplicateSegment && n.a == id && n.b == old) return;
      Notice n{NoticeKind::DuplicateSegment, id, old, 0, 0, segName(id) + " duplicates " + segName(old) + "; merged"};
      m_.notices.push_back(std::move(n));
      return;
    }
    reportShared(id, old, t_.origin(h), t_.dest(h));
  }

  // Two segments share the edge u-w: collinear ones along a common piece, segments at a tiny angle
  // where one's vertex lies within rounding of the other (kOnPiece, kSnap). One notice per pair,
  // naming the whole stretch they share along the first segment (its extent grows with each edge).
  struct Shared {
    std::size_t notice;
    std::uint32_t lo, hi;  // the shared stretch's ends, ordered along segment `first`
  };
  std::vector<Shared> shared_;

  void reportShared(std::int32_t id, std::int32_t old, std::uint32_t u, std::uint32_t w) {
    const std::int32_t first = std::min(id, old), second = std::max(id, old);
    const double* s0 = t_.pt(m_.segmentEnd(first, 0));
    const double* s1 = t_.pt(m_.segmentEnd(first, 1));
    auto along = [&](std::uint32_t v) { return (t_.xy[2 * v] - s0[0]) * (s1[0] - s0[0]) + (t_.xy[2 * v + 1] - s0[1]) * (s1[1] - s0[1]); };
    if (along(w) < along(u)) std::swap(u, w);
    Shared* entry = nullptr;
    for (Shared& e : shared_)
      if (m_.notices[e.notice].a == first && m_.notices[e.notice].b == second) entry = &e;
    if (!entry) {
      Notice n{NoticeKind::SegmentsOverlap, first, second, 0, 0, ""};
      m_.notices.push_back(std::move(n));
      shared_.push_back({m_.notices.size() - 1, u, w});
      entry = &shared_.back();
    }
    if (along(u) < along(entry->lo)) entry->lo = u;
    if (along(w) > along(entry->hi)) entry->hi = w;
    const double* t0 = t_.pt(m_.segmentEnd(second, 0));
    const double* t1 = t_.pt(m_.segmentEnd(second, 1));
    const bool collinear = orient2d(s0, s1, t0) == 0 && orient2d(s0, s1, t1) == 0;
    Notice& n = m_.notices[entry->notice];
    n.x = m_.input.toUser(t_.xy[2 * entry->lo]), n.y = m_.input.toUser(t_.xy[2 * entry->lo + 1]);
    const std::string stretch = "between (" + formatNumber(n.x) + ", " + formatNumber(n.y) + ") and (" +
                                formatNumber(m_.input.toUser(t_.xy[2 * entry->hi])) + ", " +
                                formatNumber(m_.input.toUser(t_.xy[2 * entry->hi + 1])) + ")";
    n.message = collinear ? segName(first) + " and " + segName(second) + " overlap along a collinear piece " + stretch +
                                "; they share it"
                          : segName(first) + " and " + segName(second) + " meet at a tiny angle and lie within rounding of " +
                                "each other " + stretch + "; they share that stretch";
  }

  void vertexOnSegment(std::uint32_t w, std::int32_t id) {
    if (id < 0 || w >= m_.inputCount) return;  // hull edges and repair vertices need no report
    const std::uint32_t point = m_.input.inputIndex[w];  // the user's index, not the internal one
    Notice n{NoticeKind::VertexOnSegment, id, point, m_.input.toUser(t_.xy[2 * w]), m_.input.toUser(t_.xy[2 * w + 1]), ""};
    n.message = "points[" + std::to_string(point) + "] lies inside " + segName(id) + "; the segment is split there";
    m_.notices.push_back(std::move(n));
  }

  void insertOne(std::uint32_t a, std::uint32_t b, std::int32_t id) {
    std::uint32_t h = t_.findEdge(a, b);
    if (h != kNone) {
      constrain(h, id);
      return;
    }
    const double* pa = t_.pt(a);
    const double* pb = t_.pt(b);
    // A piece off its input segment's line (it ends at a rounded crossing) can pass a hair beside a
    // vertex that is on the segment; a piece on the line meets such a vertex with orientation 0.
    const bool bent = !onInputSegment(a, id) || !onInputSegment(b, id);
    // Find the triangle at a whose corner contains the direction to b.
    std::uint32_t cross = kNone;  // first crossed half-edge, oriented right -> left of a->b
    const std::uint32_t start = t_.vtri[a];
    std::uint32_t tri = start;
    for (std::uint32_t guard = 0;; ++guard) {
      if (guard > t_.slotCount()) throw Error(ErrorCode::Internal, "lost around a vertex of " + segName(id));
      const std::uint32_t i = t_.tv[3 * tri] == a ? 0 : t_.tv[3 * tri + 1] == a ? 1 : 2;
      const std::uint32_t v1 = t_.tv[3 * tri + (i + 1) % 3], v2 = t_.tv[3 * tri + (i + 2) % 3];
      const double o1 = orient2d(pa, pb, t_.pt(v1)), o2 = orient2d(pa, pb, t_.pt(v2));
      if ((o1 == 0 && between(a, b, v1)) || (bent && onInputSegment(v1, id) && between(a, b, v1, id)))
        return splitAt(a, b, v1, id);
      if ((o2 == 0 && between(a, b, v2)) || (bent && onInputSegment(v2, id) && between(a, b, v2, id)))
        return splitAt(a, b, v2, id);
      if (o1 < 0 && o2 > 0) {
        cross = 3 * tri + i;
        break;
      }
      const std::uint32_t g = t_.twin[3 * tri + (i + 2) % 3];  // rotate across a -> v1
      if (g == kNone) throw Error(ErrorCode::Internal, "segment walk left the triangulation at " + segName(id));
      tri = g / 3;
    }
    // Walk across the triangles the segment passes through.
    std::vector<std::uint32_t> crossed;  // vertex pairs of crossed edges
    for (;;) {
      if (t_.con[cross] != kFree) return crossConstraint(a, b, id, cross);
      crossed.push_back(t_.origin(cross));
      crossed.push_back(t_.dest(cross));
      const std::uint32_t g = t_.twin[cross];
      if (g == kNone) throw Error(ErrorCode::Internal, segName(id) + " leaves the triangulation");
      const std::uint32_t w = t_.apex(g);
      if (w == b) break;
      const double o = orient2d(pa, pb, t_.pt(w));
      // A vertex on the input segment but not between a and b (its far end, when a piece was bent
      // back past it) is passed like any other: splitting there made two pieces that split each
      // other forever (found by a sweep of tiny crossing clusters).
      if (o == 0 || (bent && onInputSegment(w, id) && between(a, b, w, id))) return splitAt(a, b, w, id);
      cross = o > 0 ? next3(g) : prev3(g);
    }
    flipAway(a, b, crossed);
    h = t_.findEdge(a, b);
    if (h == kNone) throw Error(ErrorCode::Internal, "flips did not recover " + segName(id));
    constrain(h, id);
    // The flips may have left the new edges not locally Delaunay: Lawson from where they are now.
    legalizeFrom_.clear();
    for (std::size_t k = 0; k < newEdges_.size(); k += 2) {
      const std::uint32_t e = t_.findEdge(newEdges_[k], newEdges_[k + 1]);
      if (e != kNone) legalizeFrom_.push_back(e);
    }
    t_.legalize(legalizeFrom_);
  }

  // True if v lies exactly on input segment `id` (not a hull edge). A piece of the segment that
  // starts at a rounded crossing is a hair off the segment's line, so a vertex exactly on the segment
  // can lie a hair off the piece; it must still split it (found by fuzzing,
  // tests/hostile/subsegment-skipped-a-vertex-on-its-segment.poly: a subsegment skipped an input
  // vertex in the middle of its segment, and a later split left that stretch uncovered).
  bool onInputSegment(std::uint32_t v, std::int32_t id) const {
    if (id < 0) return false;
    return orient2d(t_.pt(m_.segmentEnd(id, 0)), t_.pt(m_.segmentEnd(id, 1)), t_.pt(v)) == 0;
  }

  // True if v's projection onto a -> b falls strictly between a and b: measured along input segment
  // `id` when there is one, since its pieces can be bent far off its direction (by a crossing
  // rounded to the nearest double, within a cluster a few ulps across), and a vertex ahead along the
  // piece may be behind along the segment. Splitting there turned the chain back on itself and
  // the repairs looped (found by a sweep of tiny clusters).
  bool between(std::uint32_t a, std::uint32_t b, std::uint32_t v, std::int32_t id = -1) const {
    const double* pa = t_.pt(a);
    const double* pb = t_.pt(b);
    const double* pv = t_.pt(v);
    double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
    if (id >= 0) {
      const double* s0 = t_.pt(m_.segmentEnd(id, 0));
      const double* s1 = t_.pt(m_.segmentEnd(id, 1));
      const double sx = s1[0] - s0[0], sy = s1[1] - s0[1];
      const double sign = sx * dx + sy * dy < 0 ? -1 : 1;
      dx = sign * sx, dy = sign * sy;
    }
    // Measured from both ends: a vertex an ulp from b on a piece of length 1 is ahead of a by an
    // amount that rounds to the piece's length, but behind b by one that does not round to 0.
    return (pv[0] - pa[0]) * dx + (pv[1] - pa[1]) * dy > 0 && (pb[0] - pv[0]) * dx + (pb[1] - pv[1]) * dy > 0;
  }

  void splitAt(std::uint32_t a, std::uint32_t b, std::uint32_t w, std::int32_t id) {
    vertexOnSegment(w, id);
    tasks_.push_back({w, b, id});
    tasks_.push_back({a, w, id});
  }

  // Segment a-b (id) crosses the constrained edge `h` (another segment): split both at the crossing.
  void crossConstraint(std::uint32_t a, std::uint32_t b, std::int32_t id, std::uint32_t h) {
    if (++repairs_ > 4 * static_cast<std::uint64_t>(m_.segmentCount()) * m_.segmentCount() + 1000)
      throw Error(ErrorCode::Internal, "too many crossing repairs near " + segName(id));
    const std::uint32_t l = t_.origin(h), r = t_.dest(h);
    const std::int32_t other = t_.con[h];
    const double shorter = std::sqrt(std::min(length2(a, b), length2(l, r)));
    double q[2];
    crossingPoint(a, b, id, l, r, other, shorter, q);
    // Segments crossing a hair from an axis can round the crossing to a coordinate below the exact
    // predicates' range (y = 5e-40 with the extent 1.5). The point is rounded anyway, so 0 serves;
    // and it must be one the output's user units hold exactly (inputs near the subnormal range).
    for (double& c : q) {
      if (std::fabs(c) < kSafeMinMagnitude) c = 0;
      c = m_.input.toInternal(m_.input.toUser(c));
    }
    // A crossing within rounding distance of an existing vertex (typically the crossing of a third
    // segment through the same point) is that vertex: a second vertex 1e-16 away would only leave
    // needle triangles behind. The nearest such vertex is taken, and only if the other segment may
    // pass through it: within its rounding of its line, and ahead along it. A vertex off the other
    // segment left that segment uncovered (found by fuzzing,
    // tests/hostile/crossing-snapped-to-a-vertex-left-a-segment-uncovered.poly: four input points
    // within 1e-19 of the extent, and a crossing moved onto the one off the shorter segment); one
    // behind it turned the chain back on itself, and the repairs looped (found by a sweep of tiny
    // clusters, tests/hostile/crossing-snapped-behind-its-piece.poly).
    std::uint32_t w = kNone;
    double nearest = kSnap;
    for (std::uint32_t c : {l, r, a, b}) {
      const double d = std::max(std::fabs(t_.xy[2 * c] - q[0]), std::fabs(t_.xy[2 * c + 1] - q[1]));
      const bool onOther = (c == l || c == r) ? between(a, b, c, id) && onPiece(t_.pt(c), a, b, shorter)
                                              : between(l, r, c, other) && onPiece(t_.pt(c), l, r, shorter);
      if (d <= nearest && onOther) w = c, nearest = d;
    }
    // Free the crossed edge, insert the crossing point where it lies (it is rounded, so it need not
    // be exactly on either segment), then rebuild both constraints through it.
    t_.con[h] = kFree;
    if (t_.twin[h] != kNone) t_.con[t_.twin[h]] = kFree;
    if (w == kNone) {
      const Location loc = t_.locate(q, h / 3);
      if (loc.kind == Location::OnVertex) {
        w = loc.vertex;
      } else {
        w = m_.addVertex(q[0], q[1], VertexKind::Intersection, -1);
        interpolateOnSegment(m_, w, a, b);
        if ((loc.kind != Location::InTriangle && loc.kind != Location::OnEdge) ||
            (!t_.insertVertex(w, loc) && !t_.insertVertexByFlips(w, loc)))
          throw Error(ErrorCode::Internal, "could not insert the crossing of " + segName(id) + " at (" +
                                               formatNumber(m_.input.toUser(q[0])) + ", " +
                                               formatNumber(m_.input.toUser(q[1])) + ")");
      }
    }
    if (id >= 0 && other >= 0) {
      Notice n{NoticeKind::SegmentsCross, std::min(id, other), std::max(id, other), m_.input.toUser(q[0]),
               m_.input.toUser(q[1]), ""};
      n.message = segName(n.a) + " and " + segName(n.b) + " cross at (" + formatNumber(n.x) + ", " +
                  formatNumber(n.y) + "); both are split there";
      m_.notices.push_back(std::move(n));
    }
    tasks_.push_back({w, b, id});
    tasks_.push_back({a, w, id});
    tasks_.push_back({w, r, other});
    tasks_.push_back({l, w, other});
  }

  double length2(std::uint32_t u, std::uint32_t w) const {
    const double dx = t_.xy[2 * w] - t_.xy[2 * u], dy = t_.xy[2 * w + 1] - t_.xy[2 * u + 1];
    return dx * dx + dy * dy;
  }

  // True if p lies on the piece u-w, up to rounding (see kOnPiece): that of the piece's coordinates
  // and of the crossing's, computed along the shorter of the two segments (length `shorter`). The
  // longer one's length must not count: a segment 1e12 times longer than a cluster it passes would
  // count the whole cluster as on it.
  bool onPiece(const double* p, std::uint32_t u, std::uint32_t w, double shorter) const {
    const double* pu = t_.pt(u);
    const double* pw = t_.pt(w);
    const double tol =
        kOnPiece * (shorter + std::max({std::fabs(pu[0]), std::fabs(pu[1]), std::fabs(pw[0]), std::fabs(pw[1])}));
    return p[0] >= std::min(pu[0], pw[0]) - tol && p[0] <= std::max(pu[0], pw[0]) + tol &&
           p[1] >= std::min(pu[1], pw[1]) - tol && p[1] <= std::max(pu[1], pw[1]) + tol &&
           std::fabs(orient2d(pu, pw, p)) <= tol * std::hypot(pw[0] - pu[0], pw[1] - pu[1]);
  }

  // Where segment `id` (now the piece a-b) crosses segment `other` (the piece l-r; `shorter` is the
  // shorter piece's length, as in crossConstraint). Computed from
  // the two whole input segments, lower index first, so the point does not depend on the order
  // of insertion.
  void crossingPoint(std::uint32_t a, std::uint32_t b, std::int32_t id, std::uint32_t l, std::uint32_t r,
                     std::int32_t other, double shorter, double q[2]) const {
    std::uint32_t p0 = a, p1 = b, q0 = l, q1 = r;
    if (id >= 0 && other >= 0) {
      // Canonical by geometry, not by index: the same crossing gets the same rounding however the
      // input is ordered or numbered.
      auto less = [&](std::uint32_t u, std::uint32_t v) {
        return t_.xy[2 * u] != t_.xy[2 * v] ? t_.xy[2 * u] < t_.xy[2 * v] : t_.xy[2 * u + 1] < t_.xy[2 * v + 1];
      };
      p0 = m_.segmentEnd(id, 0), p1 = m_.segmentEnd(id, 1);
      q0 = m_.segmentEnd(other, 0), q1 = m_.segmentEnd(other, 1);
      if (less(p1, p0)) std::swap(p0, p1);
      if (less(q1, q0)) std::swap(q0, q1);
      if (less(q0, p0) || (q0 == p0 && less(q1, p1))) std::swap(p0, q0), std::swap(p1, q1);
    }
    // Interpolated along the shorter segment: the rounding of the point grows with the length of the
    // segment it is measured along, and it must stay small next to the other one.
    auto intersect = [&](std::uint32_t u0, std::uint32_t u1, std::uint32_t w0, std::uint32_t w1, double out[2]) {
      if (length2(w0, w1) < length2(u0, u1)) std::swap(u0, w0), std::swap(u1, w1);
      const double* pa = t_.pt(u0);
      const double* pb = t_.pt(u1);
      const double da = orient2d(t_.pt(w0), t_.pt(w1), pa), db = orient2d(t_.pt(w0), t_.pt(w1), pb);
      const double s = da / (da - db);
      if (!(s >= 0 && s <= 1)) return false;
      out[0] = pa[0] + s * (pb[0] - pa[0]);
      out[1] = pa[1] + s * (pb[1] - pa[1]);
      return true;
    };
    // The whole-segment crossing is used only if it lies on both pieces (up to rounding); after
    // earlier repairs bent a chain, the pieces' own crossing is the right one.
    if (intersect(p0, p1, q0, q1, q) && onPiece(q, a, b, shorter) && onPiece(q, l, r, shorter)) return;
    if (intersect(a, b, l, r, q)) return;
    q[0] = (t_.xy[2 * a] + t_.xy[2 * b]) / 2;  // degenerate: the walk said they cross; use the middle
    q[1] = (t_.xy[2 * a + 1] + t_.xy[2 * b + 1]) / 2;
  }

  std::vector<std::uint32_t> newEdges_;  // vertex pairs: edges move between slots while flipping
  std::vector<std::uint32_t> legalizeFrom_;

  void flipAway(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& crossed) {
    const double* pa = t_.pt(a);
    const double* pb = t_.pt(b);
    // A first-in first-out queue of vertex pairs: queue[head..] waits (a vector read from the front,
    // compacted when half is read).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> queue;
    std::size_t head = 0;
    for (std::size_t k = 0; k < crossed.size(); k += 2) queue.emplace_back(crossed[k], crossed[k + 1]);
    newEdges_.clear();
    const std::uint64_t limit = 1000 + 100ull * queue.size() * queue.size();
    for (std::uint64_t step = 0; head < queue.size(); ++step) {
      if (step > limit) throw Error(ErrorCode::Internal, "segment recovery did not converge");
      const auto [u, v] = queue[head++];
      if (head > 64 && 2 * head > queue.size()) queue.erase(queue.begin(), queue.begin() + std::ptrdiff_t(head)), head = 0;
      const std::uint32_t h = t_.findEdge(u, v);
      if (h == kNone) continue;
      const std::uint32_t x = t_.apex(h), y = t_.apex(t_.twin[h]);
      const double ox = orient2d(t_.pt(x), t_.pt(y), t_.pt(u)), oy = orient2d(t_.pt(x), t_.pt(y), t_.pt(v));
      if (!((ox > 0 && oy < 0) || (ox < 0 && oy > 0))) {  // not strictly convex: try again later
        queue.emplace_back(u, v);
        continue;
      }
      t_.flip(h);
      const double sx = orient2d(pa, pb, t_.pt(x)), sy = orient2d(pa, pb, t_.pt(y));
      if ((sx > 0 && sy < 0) || (sx < 0 && sy > 0)) {
        queue.emplace_back(x, y);
      } else {
        newEdges_.push_back(x);
        newEdges_.push_back(y);
      }
    }
  }
};

// The points insertHull takes (input points and crossings), less those strictly left of every
// edge of the polygon through the extreme points in eight directions (Akl and Toussaint): such a
// point winds inside that polygon, so inside the hull, and is on no hull edge. The chain finds the
// same hull from what is left, and a plain CDT of 10^6 points sorts a few hundred points instead
// of all. (Rounded sums only change which points are extreme, never the test's safety.)
// Once per call, a pass over the points: compiled for size (cold_code.h), as insertHull below.
RUPPERT_COLD_BEGIN
std::vector<KeyedPoint> hullCandidates(const MeshState& m) {
  const Triangulation& t = m.tri;
  auto takes = [&m](std::uint32_t v) { return v < m.inputCount || m.kind[v] == VertexKind::Intersection; };
  // Directions counter-clockwise from west: the extremes lie around the hull in this order.
  constexpr double dir[8][2] = {{-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}};
  std::uint32_t ext[8];
  double best[8];
  std::fill(ext, ext + 8, kNone), std::fill(best, best + 8, -HUGE_VAL);
  for (std::uint32_t v = 0; v < t.vertexCount(); ++v) {
    if (!takes(v)) continue;
    const double* p = t.pt(v);
    for (int i = 0; i < 8; ++i)
      if (const double d = dir[i][0] * p[0] + dir[i][1] * p[1]; d > best[i]) best[i] = d, ext[i] = v;
  }
  auto inside = [&](std::uint32_t v) {
    for (int i = 0; i < 8; ++i) {
      const std::uint32_t a = ext[i], b = ext[(i + 1) % 8];
      if (a != b && !(orient2d(t.pt(a), t.pt(b), t.pt(v)) > 0)) return false;
    }
    return true;
  };
  std::vector<KeyedPoint> kept;
  for (std::uint32_t v = 0; v < t.vertexCount(); ++v)
    if (takes(v) && !inside(v)) kept.push_back({0, v, t.xy[2 * v], t.xy[2 * v + 1]});
  return kept;
}

}  // namespace

void insertHull(MeshState& m) {
  // Andrew's monotone chain with exact orientation on the distinct points and the crossings that
  // segment insertion added: a crossing is rounded, so it can lie a hair outside the input points'
  // hull, and a hull edge would then cross the constrained pieces that end there; each repair of
  // such a crossing rounds a new one outside again, and the repairs looped (a sweep of careless
  // PLCs, seed 29317: crossings within 1e-19 of each other). Around every vertex, no hull edge
  // crosses a constrained edge in exact arithmetic. Collinear points on the hull are skipped here
  // and picked up by segment insertion (they split the hull edge).
  // By x then y (one key for all; the vertices' points are distinct).
  std::vector<KeyedPoint> sorted = hullCandidates(m);
  const Triangulation& t = m.tri;
  sortPoints(sorted);
  std::vector<std::uint32_t> pts(sorted.size());
  for (std::size_t k = 0; k < sorted.size(); ++k) pts[k] = sorted[k].index;
  std::vector<std::uint32_t> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (std::uint32_t p : pts) {
      while (hull.size() >= base + 2 &&
             orient2d(t.pt(hull[hull.size() - 2]), t.pt(hull.back()), t.pt(p)) <= 0)
        hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // the last point starts the other chain
    std::reverse(pts.begin(), pts.end());
  }
  SegmentInserter inserter(m);
  for (std::size_t k = 0; k < hull.size(); ++k) inserter.insert(hull[k], hull[(k + 1) % hull.size()], kHullEdge);
  // After the segments (no region enclosed), hull edges a few ulps from nearly collinear segments
  // can cross their chains; those repairs need the same last Lawson pass as insertSegments' (a
  // careless PLC whose points all lay within rounding of one line kept a non-Delaunay edge).
  if (inserter.repairs() > 0) m.tri.legalizeAll();
}
RUPPERT_COLD_END

void insertSegments(MeshState& m) {
  SegmentInserter inserter(m);
  const Plc& plc = *m.plc;
  // Identical segments (after merging duplicate points) are found up front: inserted twice, a
  // crossing of both would be computed twice with different rounding.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
  keys.reserve(plc.segments.size() / 2);
  for (std::size_t s = 0; s < plc.segments.size() / 2; ++s) {
    std::uint64_t a = m.segmentEnd(s, 0), b = m.segmentEnd(s, 1);
    if (a > b) std::swap(a, b);
    keys.emplace_back(a << 32 | b, static_cast<std::uint32_t>(s));
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::int64_t> duplicateOf(plc.segments.size() / 2, -1);
  for (std::size_t k = 1; k < keys.size(); ++k)
    if (keys[k].first == keys[k - 1].first)
      duplicateOf[keys[k].second] = duplicateOf[keys[k - 1].second] >= 0 ? duplicateOf[keys[k - 1].second]
                                                                          : keys[k - 1].second;
  for (std::size_t s = 0; s < plc.segments.size() / 2; ++s) {
    const std::uint32_t a = m.segmentEnd(s, 0), b = m.segmentEnd(s, 1);
    const std::int32_t id = static_cast<std::int32_t>(s);
    if (a == b) {
      Notice n{NoticeKind::ZeroLengthSegment, id, -1, 0, 0, ""};
      n.message = segName(id) + " joins points[" + std::to_string(plc.segments[2 * s]) + "] and points[" +
                  std::to_string(plc.segments[2 * s + 1]) + "], which coincide; it is dropped";
      m.notices.push_back(std::move(n));
      continue;
    }
    if (duplicateOf[s] >= 0) {
      Notice n{NoticeKind::DuplicateSegment, id, duplicateOf[s], 0, 0, ""};
      n.message = segName(id) + " duplicates " + segName(static_cast<std::int32_t>(duplicateOf[s])) + "; merged";
      m.notices.push_back(std::move(n));
      continue;
    }
    inserter.insert(a, b, id);
  }
  // Crossing repairs free and rebuild constraints; a last Lawson pass over every edge guarantees
  // the result is constrained Delaunay whatever order the repairs happened in.
  if (inserter.repairs() > 0) m.tri.legalizeAll();
}

void constrainBoxSides(MeshState& m) {
  // The box's sides are boundary edges of the triangulation; they bound what is refined.
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t h = m.tri.findEdge(m.boxFirst + i, m.boxFirst + (i + 1) % 4);
    m.tri.con[h] = kHullEdge;
  }
}

}  // namespace ruppert::detail
