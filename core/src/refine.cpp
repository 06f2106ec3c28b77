// Constrained Delaunay refinement: Ruppert's algorithm as in Cheng, Dey & Shewchuk, "Delaunay Mesh
// Generation", chapter 6, with
//   §6.2  encroachment = a vertex in a subsegment's closed diametral disk; encroached subsegments are
//         split first; a skinny triangle's circumcenter is rejected if it encroaches a subsegment,
//         which is split instead;
//   §6.3  a queue of encroached subsegments and bucketed bad-triangle queues (smallest shortest
//         edge first, see checkTriangle), both lazily invalidated; only new triangles and their edges are checked; O(1) encroachment test
//         (the angle opposite a subsegment is >= 90 degrees);
//   §6.4  size bounds: triangles larger than the region's / global / user-function area are split too;
//   §6.6  concentric-shell splitting of subsegments at acute input corners; triangles nestled in a
//         small input angle and triangles whose shortest edge is seditious are not split;
//   §6.7  the CDT holds only the domain, so refinement never leaves it;
//   §6.8  off-centers (Üngör): the new vertex sits on the shortest edge's bisector, no farther than
//         where the triangle it forms with that edge just meets the bound; Placement::Petal goes on
//         to search the shortest edge's petal for a point that makes no new skinny triangle.
// Termination for any input: besides §6.6, a Steiner budget and a floor on subsegment length below
// which doubles cannot place new points; hitting either ends refinement with complete = false.
//
// Terminology: "subsegment" = constrained edge (con != kFree); "corner" = an input or intersection
// vertex where two constrained edges meet at less than 90 degrees; rho = circumradius / shortest edge.
#include "refine.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>

#include "predicates.h"
#include "triangle_shape.h"

namespace ruppert::detail {

bool refinementRequested(const MeshState& m) {
  const Options& o = *m.options;
  bool regionArea = false;
  for (const Region& r : m.input.regions) regionArea = regionArea || r.maxArea > 0;
  return o.minAngle > 0 || o.maxArea > 0 || regionArea || static_cast<bool>(o.sizeFunction);
}

namespace {

constexpr double kPi = 3.14159265358979323846;
// No vertex is placed closer than this to another (internal units: coordinates lie within (-2, 2),
// where it is over 10^4 ulps): subsegments shorter than 3 floors and triangles whose shortest edge is
// under 2 floors are not split, and a split point this close to a vertex is refused.
constexpr double kLengthFloor = 0x1p-38;
constexpr double kPetalReach = 4;  // see Refiner::petalMayHelp
// Bad-triangle priority classes: four per power of two of the squared shortest edge, from 2^-80 (below
// the length floor) to 2^4 (above the scaled input's extent), and one last class for size alone.
constexpr int kLowestExponent = -80;
constexpr int kBuckets = 4 * (4 - kLowestExponent) + 1;
constexpr int kAngleClasses = 64;  // queued triangles counted by smallest angle, for progress
// Segments meeting below this angle can make seditious edges. Prop. 6.14 proves termination with
// 60 degrees; §6.6 advises a smaller angle in practice (fewer triangles left skinny), which threatens
// termination only well below 20 degrees, and the Steiner budget bounds the work regardless. 45
// degrees lets earcut_earcut.poly reach 30 degrees where 60 left a 26.96-degree triangle.
constexpr double kSeditiousAngle = kPi / 4;

struct BadTriangle {
  std::uint32_t slot, a, b, c;
  std::uint8_t angleClass;  // sin^2 of the smallest angle in kAngleClasses steps
};

// Plain sqrt(x^2 + y^2) rather than hypot (several times slower, and a library call in WebAssembly):
// internal coordinates lie within (-2, 2), so no square overflows, and every length this file
// compares or divides by is at least the length floor (2^-38), whose square is far above underflow.
double length(double x, double y) { return std::sqrt(x * x + y * y); }
double dist(const double* p, const double* q) { return length(p[0] - q[0], p[1] - q[1]); }
double sq(const double* p, const double* q) { return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]); }

// A cavity already computed by Triangulation::cavity, handed to the insertion so it is not searched
// twice (both null: none).
struct CavityRef {
  const std::vector<std::uint32_t>* tris = nullptr;
  const std::vector<std::uint32_t>* boundary = nullptr;
};

class Refiner {
 public:
  explicit Refiner(MeshState& m) : m_(m), t_(m.tri), o_(*m.options) {
    theta_ = o_.minAngle * kPi / 180.0;
    sin2Theta_ = std::sin(theta_) * std::sin(theta_) * (1 - 1e-12);
    // Lens apex angle 180 - 2 theta, never below the disk's 90 degrees: cos(180 - 2 theta) = -cos(2 theta).
    if (o_.encroachment == Encroachment::DiametralLens && theta_ < kPi / 4)
      lensCos2_ = std::cos(2 * theta_) * std::cos(2 * theta_);
    buckets_.resize(kBuckets);
    if (o_.placement == Placement::Petal && theta_ > 0) preparePetal();
  }

  RefineOutcome run() {
    markCorners();
    setBudget();
    // Initial queues: every subsegment and every triangle (linear in the mesh size, §6.3).
    for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
      if (!t_.alive(s)) continue;
      checkTriangle(s);
      for (std::uint32_t i = 0; i < 3; ++i) checkSubsegment(3 * s + i);
    }
    bool stop = false;
    while (!stop) {
      while (!encroached_.empty() && !stop) {
        const EdgeRef e = encroached_.back();
        encroached_.pop_back();
        const std::uint32_t h = edgeOf(e);
        if (h == kNone || t_.con[h] == kFree || !isEncroached(h)) continue;
        splitSubsegment(h, nullptr, nullptr);
        stop = outOfBudget();
      }
      if (stop) break;
      BadTriangle bt;
      if (!popNext(bt)) break;
      if (!current(bt)) continue;  // stale entry: the triangle is gone
      splitTriangle(bt);
      stop = outOfBudget();
    }
    finish();
    return std::move(out_);
  }

 private:
  MeshState& m_;
  Triangulation& t_;
  const Options& o_;
  RefineOutcome out_;
  double theta_ = 0;  // radians
  double sin2Theta_ = 0;
  double lensCos2_ = 0;  // 0: closed diametral disk
  std::uint64_t budget_ = 0, inserted_ = 0;
  bool cancelled_ = false, budgetHit_ = false;
  std::uint64_t floorHits_ = 0;
  struct EdgeRef {
    std::uint32_t a, b, hint;  // endpoints and a half-edge that was the edge when queued
  };
  std::vector<EdgeRef> encroached_;
  std::vector<std::vector<BadTriangle>> buckets_;
  int lowestBucket_ = kBuckets;
  std::uint64_t queuedByAngle_[kAngleClasses] = {};
  std::uint64_t queued_ = 0, compactAt_ = 1u << 20;  // entries in buckets_; when to drop stale ones
  std::vector<std::uint8_t> corner_;  // per vertex: acute input corner (concentric shells apply)
  std::vector<std::uint32_t> newTris_, parents_, flipped_, mendStack_;
  struct Inherited {
    double attribute, maxArea;
    std::uint8_t inDomain;
  };
  std::vector<Inherited> inherit_;

  // ---- set-up --------------------------------------------------------------------------------
  void markCorners() {
    // A corner is acute when two constrained edges at an input or intersection vertex are less than
    // 90 degrees apart, i.e. their directions have a positive dot product (any such pair makes two
    // neighbours in angular order that close too). The directions are gathered per vertex in one
    // flat array (counting sort by vertex), without trigonometry.
    const std::uint32_t n = t_.vertexCount();
    corner_.assign(n, 0);
    auto counted = [&](std::uint32_t v) {
      return m_.kind[v] == VertexKind::Input || m_.kind[v] == VertexKind::Intersection;
    };
    std::vector<std::uint32_t> start(n + 1, 0);
    auto forEachEnd = [&](auto&& visit) {
      for (std::uint32_t h = 0; h < t_.tv.size(); ++h) {
        if (!t_.alive(h / 3) || t_.con[h] == kFree) continue;
        if (t_.twin[h] != kNone && t_.twin[h] < h) continue;  // each edge once
        const std::uint32_t a = t_.origin(h), b = t_.dest(h);
        if (counted(a)) visit(a, b);
        if (counted(b)) visit(b, a);
      }
    };
    forEachEnd([&](std::uint32_t v, std::uint32_t) { ++start[v + 1]; });
    for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<double> dir(2 * std::size_t(start[n]));
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    forEachEnd([&](std::uint32_t v, std::uint32_t w) {
      const std::uint32_t k = fill[v]++;
      const double dx = t_.xy[2 * w] - t_.xy[2 * v], dy = t_.xy[2 * w + 1] - t_.xy[2 * v + 1];
      const double len = length(dx, dy);
      dir[2 * k] = dx / len, dir[2 * k + 1] = dy / len;
    });
    for (std::uint32_t v = 0; v < n; ++v)
      for (std::uint32_t i = start[v]; i < start[v + 1] && !corner_[v]; ++i)
        for (std::uint32_t j = i + 1; j < start[v + 1]; ++j)
          // cos(gap) > sin(1e-12): the gap is below 90 degrees by more than rounding.
          if (dir[2 * i] * dir[2 * j] + dir[2 * i + 1] * dir[2 * j + 1] > 1e-12) {
            corner_[v] = 1;
            break;
          }
  }

  void setBudget() {
    if (o_.maxSteiner != kAutoSteinerBudget) {
      budget_ = o_.maxSteiner;
      return;
    }
    // Generous for any reasonable input, yet small enough that a runaway at an unreachable angle
    // stops within seconds: ten thousand, plus 200 per input vertex (of the 61 shared PLCs, the
    // complete meshes at 33 and 35 degrees use at most 40 Steiner vertices per input vertex once
    // past the first ten thousand), plus 100 per crossing of two segments (stars of 80 to 300 chords
    // through a disk's centre, 3,160 to 44,850 crossings at small angles, use 30-63 Steiner vertices
    // per crossing at 30 and 33 degrees; 40 per crossing stopped several of them incomplete), plus
    // eight per unit of area bound (area A with triangles of area a needs about A / (2 a) vertices).
    const auto crossings = std::count(m_.kind.begin(), m_.kind.end(), VertexKind::Intersection);
    double estimate = 1e4 + 200.0 * m_.inputCount + 100.0 * static_cast<double>(crossings);
    for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
      if (!t_.alive(s) || m_.maxArea[s] <= 0) continue;
      estimate += 8 * qualityAt(s).area / m_.maxArea[s];
    }
    if (o_.sizeFunction) estimate += 1e8;
    budget_ = static_cast<std::uint64_t>(std::min(estimate, 4e9));
  }

  // ---- tests ---------------------------------------------------------------------------------
  // v encroaches (a, b) iff the angle avb is at least 90 degrees (closed diametral disk) or, with
  // lenses, at least 180 - 2 theta degrees when that is larger: cos(avb) <= lensCos_, i.e.
  // dot <= 0 and dot^2 >= lensCos_^2 |va|^2 |vb|^2.
  bool encroaches(const double* v, const double* a, const double* b) const {
    const double ax = a[0] - v[0], ay = a[1] - v[1], bx = b[0] - v[0], by = b[1] - v[1];
    const double dot = ax * bx + ay * by;
    if (dot > 0) return false;
    return lensCos2_ == 0 || dot * dot >= lensCos2_ * (ax * ax + ay * ay) * (bx * bx + by * by);
  }
  // O(1) test of Exercise 1: the subsegment h is encroached iff an apex on either side sees it at
  // 90 degrees or more.
  bool isEncroached(std::uint32_t h) const {
    const double* a = t_.pt(t_.origin(h));
    const double* b = t_.pt(t_.dest(h));
    if (encroaches(t_.pt(t_.apex(h)), a, b)) return true;
    const std::uint32_t g = t_.twin[h];
    return g != kNone && encroaches(t_.pt(t_.apex(g)), a, b);
  }
  void checkSubsegment(std::uint32_t h) {
    if (t_.con[h] == kFree) return;
    if (encroaches(t_.pt(t_.apex(h)), t_.pt(t_.origin(h)), t_.pt(t_.dest(h))))
      encroached_.push_back({t_.origin(h), t_.dest(h), h});
  }

  // The half-edge for a queued edge: the remembered one if it still is that edge, else a search.
  // (The search alone is not enough: at a vertex where the domain touches itself, rotating around
  // the vertex cannot reach every triangle.)
  std::uint32_t edgeOf(const EdgeRef& e) const {
    const std::uint32_t t = e.hint / 3;
    if (t_.alive(t))
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = 3 * t + i;
        const std::uint32_t o = t_.origin(h), d = t_.dest(h);
        if ((o == e.a && d == e.b) || (o == e.b && d == e.a)) return h;
      }
    return t_.findEdge(e.a, e.b);
  }

  TriangleQuality qualityAt(std::uint32_t s) const {
    return qualityOf(t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2]));
  }

  double maxAreaAt(std::uint32_t s) const {
    double bound = m_.maxArea[s];
    if (o_.sizeFunction) {
      const double* p0 = t_.pt(t_.tv[3 * s]);
      const double* p1 = t_.pt(t_.tv[3 * s + 1]);
      const double* p2 = t_.pt(t_.tv[3 * s + 2]);
      const double cx = m_.input.toUser((p0[0] + p1[0] + p2[0]) / 3);
      const double cy = m_.input.toUser((p0[1] + p1[1] + p2[1]) / 3);
      const double user = o_.sizeFunction(cx, cy);
      if (std::isfinite(user) && user > 0) {
        const double internal = m_.input.areaToInternal(user);
        bound = bound > 0 ? std::min(bound, internal) : internal;
      }
    }
    return bound;
  }

  // The one skinniness test everything uses: sin^2 of the smallest angle below sin^2 of the bound.
  bool isSkinny(const TriangleQuality& q) const { return theta_ > 0 && q.sin2MinAngle < sin2Theta_; }

  void checkTriangle(std::uint32_t s) {
    const double* p0 = t_.pt(t_.tv[3 * s]);
    const double* p1 = t_.pt(t_.tv[3 * s + 1]);
    const double* p2 = t_.pt(t_.tv[3 * s + 2]);
    const TriangleQuality q = qualityOf(p0, p1, p2);
    const double bound = maxAreaAt(s);
    const bool large = bound > 0 && q.area > bound;
    const bool skinny = isSkinny(q);
    if (!skinny && !large) return;
    // Order: skinny triangles with the shortest shortest-edge first, too-large but shapely ones last.
    // Fixing the smallest features first lets the mesh grade outwards from them; splitting the
    // skinniest first (measured on the 61 shared PLCs) spreads small triangles far from any feature:
    // 1.33x Triangle's count at 33 degrees against 0.99x with this order.
    int k = kBuckets - 1;
    if (skinny) {
      const double l2 = std::min({sq(p1, p2), sq(p2, p0), sq(p0, p1)});
      int e = 0;
      const double mantissa = std::frexp(l2, &e);  // l2 = mantissa * 2^e, mantissa in [0.5, 1)
      // Four classes per power of two (of the squared length): cuts at 2^-0.75, 2^-0.5, 2^-0.25.
      const int quarter = (mantissa >= 0.5946035575013605) + (mantissa >= 0.7071067811865476) +
                          (mantissa >= 0.8408964152537145);
      k = std::clamp(4 * (e - kLowestExponent) + quarter, 0, kBuckets - 2);
    }
    const auto angleClass = static_cast<std::uint8_t>(
        std::min<double>(kAngleClasses - 1, q.sin2MinAngle / 0.75 * (kAngleClasses - 1)));
    buckets_[k].push_back({s, t_.tv[3 * s], t_.tv[3 * s + 1], t_.tv[3 * s + 2], angleClass});
    ++queuedByAngle_[angleClass];
    lowestBucket_ = std::min(lowestBucket_, k);
    if (++queued_ > compactAt_) dropStaleEntries();
  }

  // Whether a queued entry still describes the triangle in its slot.
  bool current(const BadTriangle& e) const {
    return t_.alive(e.slot) && t_.tv[3 * e.slot] == e.a && t_.tv[3 * e.slot + 1] == e.b && t_.tv[3 * e.slot + 2] == e.c;
  }

  // Where refinement runs away, each step can rebuild a fan of thousands of needles, and the entries
  // of the ones it replaced stay queued: 70 million entries for 4 million triangles (300 chords
  // crossing in a star at 30 degrees, before off-centers aimed past the bound). Dropping the stale
  // ones (popNext would skip them anyway; the order of the rest is kept, so meshes do not change)
  // keeps memory proportional to the mesh.
  void dropStaleEntries() {
    queued_ = 0;
    for (auto& b : buckets_) {
      b.erase(std::remove_if(b.begin(), b.end(),
                             [&](const BadTriangle& e) {
                               if (current(e)) return false;
                               --queuedByAngle_[e.angleClass];
                               return true;
                             }),
              b.end());
      queued_ += b.size();
    }
    compactAt_ = 2 * std::max<std::uint64_t>(queued_, t_.slotCount()) + (1u << 16);
  }

  bool popNext(BadTriangle& out) {
    while (lowestBucket_ < kBuckets) {
      auto& b = buckets_[lowestBucket_];
      if (!b.empty()) {
        out = b.back();
        b.pop_back();
        --queued_;
        --queuedByAngle_[out.angleClass];
        return true;
      }
      ++lowestBucket_;
    }
    return false;
  }

  // The smallest angle among queued triangles (entries whose triangle has changed since included),
  // to within 60 / (kAngleClasses - 1) degrees; for progress reports only.
  double worstQueuedAngle() const {
    for (int c = 0; c < kAngleClasses; ++c)
      if (queuedByAngle_[c]) return std::asin(std::sqrt(0.75 * c / (kAngleClasses - 1))) * 180 / kPi;
    return o_.minAngle;
  }

  bool outOfBudget() {
    if (inserted_ >= budget_) {
      budgetHit_ = true;
      return true;
    }
    if (o_.onProgress && (inserted_ & 4095) == 0 && inserted_ > 0) {
      Progress p;
      p.insertedVertices = inserted_;
      p.triangles = t_.slotCount() - t_.freeSlots.size();
      p.worstAngle = worstQueuedAngle();
      if (!o_.onProgress(p)) {
        cancelled_ = true;
        return true;
      }
    }
    return false;
  }

  // ---- exemptions (§6.6) -------------------------------------------------------------------------
  // The triangle's smallest angle is an input angle: both edges at that corner are subsegments.
  bool nestledInInputAngle(std::uint32_t s, const TriangleShape& sh) const {
    const std::uint32_t i = static_cast<std::uint32_t>(sh.shortestEdge);  // the smallest angle's corner
    return t_.con[3 * s + (i + 1) % 3] != kFree && t_.con[3 * s + (i + 2) % 3] != kFree;
  }

  // Shortest edge u-w is seditious: u and w split two different segments that meet at a vertex z at
  // less than kSeditiousAngle, at the same distance from z (the same concentric shell). z is an
  // endpoint the segments share, or the point where they cross (an intersection vertex: shells are
  // measured from it too).
  bool seditious(std::uint32_t s, const TriangleShape& sh) const {
    const std::uint32_t h = 3 * s + static_cast<std::uint32_t>(sh.shortestEdge);
    const std::uint32_t u = t_.origin(h), w = t_.dest(h);
    if (m_.kind[u] != VertexKind::SegmentSplit || m_.kind[w] != VertexKind::SegmentSplit) return false;
    const std::int32_t su = m_.onSegment[u], sw = m_.onSegment[w];
    if (su < 0 || sw < 0 || su == sw) return false;
    const Plc& plc = *m_.plc;
    const auto& rep = m_.input.representative;
    const std::uint32_t a0 = rep[plc.segments[2 * su]], a1 = rep[plc.segments[2 * su + 1]];
    const std::uint32_t b0 = rep[plc.segments[2 * sw]], b1 = rep[plc.segments[2 * sw + 1]];
    double z[2];
    if (a0 == b0 || a0 == b1) {
      z[0] = t_.xy[2 * a0], z[1] = t_.xy[2 * a0 + 1];
    } else if (a1 == b0 || a1 == b1) {
      z[0] = t_.xy[2 * a1], z[1] = t_.xy[2 * a1 + 1];
    } else {
      const double* p = t_.pt(a0);
      const double* q = t_.pt(b0);
      const double ax = t_.xy[2 * a1] - p[0], ay = t_.xy[2 * a1 + 1] - p[1];
      const double bx = t_.xy[2 * b1] - q[0], by = t_.xy[2 * b1 + 1] - q[1];
      const double den = ax * by - ay * bx;
      if (den == 0) return false;
      const double ta = ((q[0] - p[0]) * by - (q[1] - p[1]) * bx) / den;
      const double tb = ((q[0] - p[0]) * ay - (q[1] - p[1]) * ax) / den;
      if (!(ta >= 0 && ta <= 1 && tb >= 0 && tb <= 1)) return false;  // the segments do not meet
      z[0] = p[0] + ta * ax, z[1] = p[1] + ta * ay;
    }
    const double ux = t_.xy[2 * u] - z[0], uy = t_.xy[2 * u + 1] - z[1];
    const double wx = t_.xy[2 * w] - z[0], wy = t_.xy[2 * w + 1] - z[1];
    if (std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) >= kSeditiousAngle) return false;
    const double du = length(ux, uy), dw = length(wx, wy);
    return std::fabs(du - dw) <= 1e-6 * std::max(du, dw);
  }

  // ---- insertion ---------------------------------------------------------------------------------
  // Insert vertex v at `loc`; new triangles inherit region data and are checked; their
  // subsegments are checked for encroachment. False (nothing changed) if the insertion would
  // create an inverted triangle (rounding at the precision limit). `cavity`, if given, is the
  // cavity of v's point at `loc` as Triangulation::cavity computed it, with nothing changed since.
  bool insertAt(std::uint32_t v, const Location& loc, const CavityRef& cavity = {}) {
    const bool onSubsegment = loc.kind == Location::OnEdge && t_.con[loc.edge] != kFree;
    flipped_.clear();
    // Bowyer-Watson first; where its cavity would wrap around a vertex at which the domain touches
    // itself, split and flip instead.
    const bool filled = cavity.tris ? t_.fillCavity(v, loc, *cavity.tris, *cavity.boundary, &newTris_, &parents_)
                                    : t_.insertVertex(v, loc, &newTris_, &parents_);
    if (!filled && !t_.insertVertexByFlips(v, loc, &newTris_, &parents_)) return false;
    ++inserted_;
    const bool box = !m_.inDomain.empty();
    if (m_.attribute.size() < t_.slotCount()) {
      m_.attribute.resize(t_.slotCount(), 0);
      m_.maxArea.resize(t_.slotCount(), 0);
      if (box) m_.inDomain.resize(t_.slotCount(), 0);
    }
    // Two passes: a new triangle may reuse the slot of another new triangle's parent.
    inherit_.resize(newTris_.size());
    for (std::size_t k = 0; k < newTris_.size(); ++k)
      inherit_[k] = {m_.attribute[parents_[k]], m_.maxArea[parents_[k]], box ? m_.inDomain[parents_[k]] : std::uint8_t(1)};
    for (std::size_t k = 0; k < newTris_.size(); ++k) {
      m_.attribute[newTris_[k]] = inherit_[k].attribute, m_.maxArea[newTris_[k]] = inherit_[k].maxArea;
      if (box) m_.inDomain[newTris_[k]] = inherit_[k].inDomain;
    }
    if (onSubsegment) mendDelaunay();
    for (std::uint32_t s : newTris_) {
      checkTriangle(s);
      for (std::uint32_t i = 0; i < 3; ++i) checkSubsegment(3 * s + i);
      // The outer edge's far side is an old triangle: its apex may now encroach nothing new, but a
      // split subsegment's halves need checking from both sides.
      const std::uint32_t g = t_.twin[3 * s];
      if (g != kNone) checkSubsegment(g);
    }
    for (std::uint32_t s : flipped_) {
      checkTriangle(s);
      for (std::uint32_t i = 0; i < 3; ++i) {
        checkSubsegment(3 * s + i);
        if (t_.twin[3 * s + i] != kNone) checkSubsegment(t_.twin[3 * s + i]);
      }
    }
    return true;
  }

  // A subsegment's split point is rounded, so it lies a hair off the subsegment's line. Bowyer-Watson
  // treats it as on the edge and joins it to the boundary of both sides' cavities; when it falls just
  // outside one side's triangle, a free edge there can end up not locally Delaunay (found by fuzzing:
  // two segments meeting at 5e-8 radians, split into pieces a million times longer than that
  // offset). Lawson flips around the new triangles mend it; flip() keeps both slots, and the two
  // triangles of a free edge share their region, so the slots' region data stays right. Slots that
  // changed and are not new are left in flipped_ for re-checking.
  void mendDelaunay() {
    mendStack_.clear();
    for (std::uint32_t s : newTris_)
      for (std::uint32_t i = 0; i < 3; ++i) mendStack_.push_back(3 * s + i);
    t_.legalize(mendStack_, &flipped_);
    std::sort(flipped_.begin(), flipped_.end());
    flipped_.erase(std::unique(flipped_.begin(), flipped_.end()), flipped_.end());
    flipped_.erase(std::remove_if(flipped_.begin(), flipped_.end(),
                                  [&](std::uint32_t s) {
                                    return std::find(newTris_.begin(), newTris_.end(), s) != newTris_.end();
                                  }),
                   flipped_.end());
  }

  // Split subsegment h (§6.2, §6.6). `by` = the encroaching vertex if known, for the trace.
  // Returns false if it cannot be split (precision floor).
  bool splitSubsegment(std::uint32_t h, const BadTriangle* bt, const double* rejected) {
    const std::uint32_t a = t_.origin(h), b = t_.dest(h);
    // Copies: adding a vertex below may reallocate the coordinate array.
    const double pa[2] = {t_.xy[2 * a], t_.xy[2 * a + 1]};
    const double pb[2] = {t_.xy[2 * b], t_.xy[2 * b + 1]};
    const double len = dist(pa, pb);
    if (len < 3 * kLengthFloor) {
      ++floorHits_;
      return false;
    }
    // Concentric shells: measured from an acute corner, the piece next to it gets a power-of-two
    // length in (len/3, 2len/3], so equal pieces on neighbouring segments do not encroach each other.
    double f = 0.5;
    const bool ca = corner_[a] != 0, cb = corner_[b] != 0;
    if (ca != cb) {
      const double d = std::exp2(std::floor(std::log2(2.0 * len / 3.0)));
      f = ca ? d / len : 1.0 - d / len;
    }
    double x = pa[0] + f * (pb[0] - pa[0]), y = pa[1] + f * (pb[1] - pa[1]);
    // On a subsegment with no triangle beyond it, a split point rounded to the outside can land in
    // another part of the domain across an exterior sliver thinner than the rounding (found by
    // fuzzing: two segments 1e-7 rad apart bounding a hole). Move it an ulp at a time onto the
    // domain's side, the left of a -> b.
    if (t_.twin[h] == kNone) {
      const double towardsX = pa[1] - pb[1], towardsY = pb[0] - pa[0];
      for (int step = 0;; ++step) {
        const double p[2] = {x, y};
        if (orient2d(pa, pb, p) >= 0) break;
        if (step == 4) {
          ++floorHits_;
          return false;
        }
        x = std::nextafter(x, towardsX > 0 ? HUGE_VAL : towardsX < 0 ? -HUGE_VAL : x);
        y = std::nextafter(y, towardsY > 0 ? HUGE_VAL : towardsY < 0 ? -HUGE_VAL : y);
      }
    }
    const double split[2] = {x, y};
    if (!representable(split)) {
      ++floorHits_;
      return false;
    }
    Location loc;
    loc.kind = Location::OnEdge;
    loc.tri = h / 3;
    loc.edge = h;
    // The new vertex's nearest neighbour is on its cavity's boundary: the vertices facing the
    // subsegment (an encroacher 1e-15 above the midpoint, say), or, when two segments meet at a tiny
    // angle, a shell split at the same distance from their common vertex on the other segment, closer
    // than doubles can keep apart (found by fuzzing). Refuse those, as the length floor does.
    t_.cavity(split, loc, splitTris_, splitBoundary_);
    if (tooCloseToCavity(split, splitBoundary_)) {
      ++floorHits_;
      return false;
    }
    const std::int32_t segment = t_.con[h] >= 0 ? t_.con[h] : -1;
    const std::uint32_t v = m_.addVertex(x, y, VertexKind::SegmentSplit, segment);
    corner_.push_back(0);
    if ((x == pa[0] && y == pa[1]) || (x == pb[0] && y == pb[1]) || !insertAt(v, loc, {&splitTris_, &splitBoundary_})) {
      // Not placeable: the new vertex stays unused (kind Unused) so output stays consistent.
      m_.kind[v] = VertexKind::Unused;
      ++floorHits_;
      return false;
    }
    if (o_.trace) {
      Event e;
      e.kind = rejected ? EventKind::Rejected : EventKind::SegmentSplit;
      e.vertex = v, e.x = x, e.y = y, e.a = a, e.b = b;
      if (rejected && bt) e.t0 = bt->a, e.t1 = bt->b, e.t2 = bt->c, e.cx = rejected[0], e.cy = rejected[1];
      out_.events.push_back(e);
    }
    return true;
  }

  // Straight walk from the centroid of triangle s towards p. Stops at the first subsegment in the
  // way (blocked = its half-edge), else returns p's location.
  Location walk(std::uint32_t s, const double* p, std::uint32_t& blocked) const {
    blocked = kNone;
    const double* q0 = t_.pt(t_.tv[3 * s]);
    const double* q1 = t_.pt(t_.tv[3 * s + 1]);
    const double* q2 = t_.pt(t_.tv[3 * s + 2]);
    const double o[2] = {(q0[0] + q1[0] + q2[0]) / 3, (q0[1] + q1[1] + q2[1]) / 3};
    std::uint32_t t = s;
    for (std::uint32_t step = 0; step < 100000; ++step) {
      std::uint32_t exit = kNone, fallback = kNone;
      double ori[3];
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = 3 * t + i;
        ori[i] = orient2d(t_.pt(t_.origin(h)), t_.pt(t_.dest(h)), p);
        if (ori[i] < 0) {
          if (fallback == kNone) fallback = h;
          const double su = orient2d(o, p, t_.pt(t_.origin(h))), sv = orient2d(o, p, t_.pt(t_.dest(h)));
          if (exit == kNone && ((su >= 0 && sv <= 0) || (su <= 0 && sv >= 0))) exit = h;
        }
      }
      if (exit == kNone) exit = fallback;
      if (exit == kNone) {
        return t_.locationInside(t, ori);
      }
      if (t_.con[exit] != kFree || t_.twin[exit] == kNone) {
        blocked = exit;
        return Location{};
      }
      t = t_.twin[exit] / 3;
    }
    return Location{};
  }

  void splitTriangle(const BadTriangle& bt) {
    const std::uint32_t s = bt.slot;
    const double* p[3] = {t_.pt(bt.a), t_.pt(bt.b), t_.pt(bt.c)};
    const TriangleShape sh = shapeOf(p[0], p[1], p[2]);
    const TriangleQuality q = qualityOf(p[0], p[1], p[2]);
    const bool skinny = isSkinny(q);
    if (skinny && (nestledInInputAngle(s, sh) || seditious(s, sh))) {
      const double bound = maxAreaAt(s);
      if (!(bound > 0 && q.area > bound)) return;  // left alone on purpose; counted in finish()
    }
    if (sh.shortest < 2 * kLengthFloor) {
      ++floorHits_;
      return;
    }
    // Circumcenter, relative to p[0] for accuracy.
    const double bx = p[1][0] - p[0][0], by = p[1][1] - p[0][1];
    const double cx = p[2][0] - p[0][0], cy = p[2][1] - p[0][1];
    const double d = 2 * (bx * cy - by * cx);
    if (!(d > 0)) {
      ++floorHits_;
      return;
    }
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    double cc[2] = {p[0][0] + (cy * b2 - by * c2) / d, p[0][1] + (bx * c2 - cx * b2) / d};
    double target[2] = {cc[0], cc[1]};
    VertexKind kind = VertexKind::Interior;
    if (skinny && o_.placement != Placement::Circumcenter) {
      // Off-center: on the bisector of the shortest edge, where the isosceles triangle on that edge
      // has apex angle exactly theta (so it just meets the bound).
      const int e = sh.shortestEdge;
      const double* u = p[(e + 1) % 3];
      const double* w = p[(e + 2) % 3];
      const double mx = (u[0] + w[0]) / 2, my = (u[1] + w[1]) / 2;
      const double toC = length(cc[0] - mx, cc[1] - my);
      // The new vertex is rounded to doubles, up to an ulp of its coordinates from where it is aimed;
      // seen from an edge of length l that turns the apex angle by up to ulp / l radians, so a
      // triangle built to meet the bound exactly can miss it, and its circumcenter then adds a vertex
      // no farther away than l: no gain in size, and at small scales a runaway (300 chords crossing at
      // 30 degrees: half of one's insertions split triangles 1e-9 to 1e-6 degrees short of 30). Aim
      // past the bound by several times that turn: 4e-12 rad for l = 1e-3, 1e-3 rad at the length floor.
      const double reach = std::max({std::fabs(u[0]), std::fabs(u[1]), std::fabs(w[0]), std::fabs(w[1])});
      const double margin = 16 * std::numeric_limits<double>::epsilon() * reach / sh.shortest;
      const double hOff = (sh.shortest / 2) / std::tan((theta_ + margin) / 2);
      if (hOff < toC && toC > 0) {
        target[0] = mx + (cc[0] - mx) * (hOff / toC);
        target[1] = my + (cc[1] - my) * (hOff / toC);
        kind = VertexKind::OffCenter;
      }
    }
    if (!representable(target)) {
      ++floorHits_;
      return;
    }
    std::uint32_t blocked;
    Location loc = walk(s, target, blocked);
    if (blocked != kNone) {
      // The new vertex would lie beyond a subsegment: that subsegment is encroached (Prop. 6.2).
      reject(bt, blocked, target);
      return;
    }
    if (loc.kind == Location::Lost || loc.kind == Location::OnVertex) {
      ++floorHits_;
      return;
    }
    if (loc.kind == Location::OnEdge && t_.con[loc.edge] != kFree) {
      reject(bt, loc.edge, target);
      return;
    }
    // Reject if the new vertex would encroach a subsegment on its cavity's boundary (§6.2, §6.3).
    t_.cavity(target, loc, cavityTris_, cavityBoundary_);
    if (tooCloseToCavity(target, cavityBoundary_)) {
      ++floorHits_;
      return;
    }
    bool rejectedAny = false;
    for (std::uint32_t h : cavityBoundary_) {
      if (t_.con[h] == kFree) continue;
      if (encroaches(target, t_.pt(t_.origin(h)), t_.pt(t_.dest(h)))) {
        rejectPairs_.push_back({t_.origin(h), t_.dest(h), h});
        rejectedAny = true;
      }
    }
    if (rejectedAny) {
      ++out_.rejected;
      bool splitSome = false;
      for (const EdgeRef& e : rejectPairs_) {
        const std::uint32_t h = edgeOf(e);
        if (h != kNone && t_.con[h] != kFree) splitSome = splitSubsegment(h, &bt, target) || splitSome;
      }
      rejectPairs_.clear();
      if (splitSome) requeue(bt);
      return;
    }
    // Only where no area bound applies: with one, the bound sets the size and the search buys little
    // (unit square, max area 1e-6: 794.6 k vertices with it, 794.7 k without, at 4x the time).
    // A petal point has a cavity of its own: insertAt computes it.
    CavityRef known{&cavityTris_, &cavityBoundary_};
    if (skinny && o_.placement == Placement::Petal && !(maxAreaAt(s) > 0) && petalMayHelp(target, sh.shortest) &&
        betterPlacement(s, sh, p, target, loc))
      kind = VertexKind::OffCenter, known = {};
    const std::uint32_t v = m_.addVertex(target[0], target[1], kind, -1);
    corner_.push_back(0);
    if (!insertAt(v, loc, known)) {
      m_.kind[v] = VertexKind::Unused;
      ++floorHits_;
      return;
    }
    if (o_.trace) {
      Event e;
      e.kind = kind == VertexKind::OffCenter ? EventKind::OffCenter : EventKind::Circumcenter;
      e.vertex = v, e.x = target[0], e.y = target[1], e.t0 = bt.a, e.t1 = bt.b, e.t2 = bt.c;
      out_.events.push_back(e);
    }
  }

  // Candidate points for betterPlacement, for a shortest edge from (-1/2, 0) to (1/2, 0) with the
  // triangle above it (scaled and rotated onto the real edge when used), sorted by `bound`, their
  // distance to the nearer endpoint (which no real placement's insertion radius can exceed).
  struct PetalPoint {
    double along, across, bound;
  };
  std::vector<PetalPoint> petal_;
  void preparePetal() {
    static constexpr double kFractions[] = {0, 0.125, -0.125, 0.25, -0.25, 0.375, -0.375, 0.5, -0.5, 0.75, -0.75, 1, -1};
    for (double extra = 0; extra < 0.35; extra += 0.1) {
      const double alpha = theta_ + extra;
      const double phiMax = kPi - alpha - 2 * theta_;
      if (phiMax < 0) break;
      const double radius = 1 / (2 * std::sin(alpha)), centre = 0.5 / std::tan(alpha);
      for (double f : kFractions) {
        const double along = radius * std::sin(f * phiMax), across = centre + radius * std::cos(f * phiMax);
        petal_.push_back({along, across, std::hypot(std::fabs(along) - 0.5, across)});
      }
    }
    std::sort(petal_.begin(), petal_.end(), [](const PetalPoint& a, const PetalPoint& b) { return a.bound > b.bound; });
  }

  // Whether a vertex of the cavity boundary lies within the length floor of x (the nearest existing
  // vertex to a new one is always on the boundary of its cavity).
  bool tooCloseToCavity(const double* x, const std::vector<std::uint32_t>& boundary) const {
    for (std::uint32_t h : boundary)
      if (sq(x, t_.pt(t_.origin(h))) < kLengthFloor * kLengthFloor) return true;
    return false;
  }

  // Smallest sin^2 angle among the triangles that inserting x creates, given x's cavity boundary.
  double newMinSin2(const double* x, const std::vector<std::uint32_t>& boundary) const {
    double worst = 1;
    for (std::uint32_t h : boundary)
      worst = std::min(worst, qualityOf(t_.pt(t_.origin(h)), t_.pt(t_.dest(h)), x).sin2MinAngle);
    return worst;
  }

  // Whether searching the petal can pay: the default point makes a skinny triangle (with cavityBoundary_
  // as its cavity), and every such triangle stands on a cavity edge less than kPetalReach times the
  // shortest edge. A longer edge makes a flat triangle with the default point; the petal's points all
  // lie within about one shortest edge of it, so they make the same flat triangle. Measured on the
  // shared PLCs at 33 degrees: of 89,541 searches 9,955 found a point; where such an edge was over 8
  // times the shortest, 2 of 31,000; over 4 times, 300 of 55,000. With 4, the geo-mean triangle ratio
  // to Triangle moves from 0.882 to 0.887 at 30 degrees and 0.859 to 0.861 at 33, and petal costs
  // about 2x the off-centers' time instead of 4-7x (cdt_sweden.poly at 33: 94 -> 32 ms, 15 ms).
  bool petalMayHelp(const double* target, double shortest) const {
    bool skinny = false;
    for (std::uint32_t h : cavityBoundary_) {
      const double* a = t_.pt(t_.origin(h));
      const double* b = t_.pt(t_.dest(h));
      if (qualityOf(a, b, target).sin2MinAngle >= sin2Theta_) continue;
      if (dist(a, b) > kPetalReach * shortest) return false;
      skinny = true;
    }
    return skinny;
  }

  // Locally better Steiner points, in the spirit of Erten and Üngör's: when the off-center (or the
  // circumcenter) would itself create a skinny triangle, look in the shortest edge's petal for a
  // point whose new triangles all meet the bound, and take the one farthest from its neighbours.
  // The petal of edge uw: points x with angle uxw >= theta and both base angles >= theta. Candidates
  // lie on the arcs where angle uxw = alpha for alpha = theta .. theta + 0.3 rad: on such an arc,
  // at central angle phi from its top, the base angles are (pi - alpha - phi) / 2 and
  // (pi - alpha + phi) / 2, so |phi| <= pi - alpha - 2 theta keeps both >= theta.
  // Measured on the 61 shared PLCs (geo-mean triangle count against Triangle's, off-centers -> petal):
  // 0.973 -> 0.887 at 30 degrees, 0.987 -> 0.861 at 33, at about twice the refinement time without an
  // area bound (most searches that petalMayHelp lets through still find no such point).
  // Returns true (and sets target, loc) if a candidate was found.
  bool betterPlacement(std::uint32_t s, const TriangleShape& sh, const double* const* p, double* target, Location& loc) {
    const int e = sh.shortestEdge;
    const double* u = p[(e + 1) % 3];
    const double* w = p[(e + 2) % 3];
    const double len = sh.shortest;
    const double dx = (w[0] - u[0]) / len, dy = (w[1] - u[1]) / len;
    const double nx = -dy, ny = dx;  // towards the triangle's side of u->w (counter-clockwise)
    const double mx = (u[0] + w[0]) / 2, my = (u[1] + w[1]) / 2;
    double bestRadius = 0, best[2] = {0, 0};
    Location bestLoc;
    for (const PetalPoint& c : petal_) {
      if (c.bound * len <= bestRadius) break;
      const double x[2] = {mx + len * (c.along * dx + c.across * nx), my + len * (c.along * dy + c.across * ny)};
      if (!representable(x)) continue;
      std::uint32_t blocked;
      const Location l = walk(s, x, blocked);
      if (blocked != kNone || l.kind != Location::InTriangle) continue;
      t_.cavity(x, l, candidateTris_, candidateBoundary_);
      // x must destroy the skinny triangle (lie in its circumcircle), and make nothing skinny.
      if (std::find(candidateTris_.begin(), candidateTris_.end(), s) == candidateTris_.end() ||
          newMinSin2(x, candidateBoundary_) < sin2Theta_)
        continue;
      bool encroaching = false;
      double nearest = HUGE_VAL;
      for (std::uint32_t h : candidateBoundary_) {
        nearest = std::min(nearest, dist(x, t_.pt(t_.origin(h))));
        if (t_.con[h] != kFree && encroaches(x, t_.pt(t_.origin(h)), t_.pt(t_.dest(h)))) encroaching = true;
      }
      if (encroaching || nearest <= bestRadius) continue;
      bestRadius = nearest, best[0] = x[0], best[1] = x[1], bestLoc = l;
    }
    if (bestRadius == 0) return false;
    target[0] = best[0], target[1] = best[1];
    loc = bestLoc;
    return true;
  }

  void reject(const BadTriangle& bt, std::uint32_t h, const double* target) {
    ++out_.rejected;
    if (splitSubsegment(h, &bt, target)) requeue(bt);
  }

  // The triangle survives a rejection unless the split destroyed it; keep it queued (§6.3).
  void requeue(const BadTriangle& bt) {
    if (t_.alive(bt.slot) && t_.tv[3 * bt.slot] == bt.a && t_.tv[3 * bt.slot + 1] == bt.b &&
        t_.tv[3 * bt.slot + 2] == bt.c)
      checkTriangle(bt.slot);
  }

  std::vector<std::uint32_t> cavityTris_, cavityBoundary_, candidateTris_, candidateBoundary_, splitTris_,
      splitBoundary_;
  std::vector<EdgeRef> rejectPairs_;

  // Whether a new vertex at p can be kept exactly. A coordinate can fall below the exact predicates'
  // range without any input doing so (found by fuzzing): splits of a hull edge from (0, 0) to
  // (1.5, 3e-39) have y coordinates under 2^-128. And on inputs near the subnormal range, the output's
  // user units cannot hold a new vertex's coordinates (fuzzing again: with coordinates near 1e-312 the
  // mesh returned had clockwise triangles though the internal one was valid). Such a vertex is
  // refused like one under the length floor.
  bool representable(const double* p) const {
    for (int k = 0; k < 2; ++k)
      if (!isSafeCoordinate(p[k]) || (p[k] != 0 && !(std::fabs(m_.input.toUser(p[k])) >= DBL_MIN))) return false;
    return true;
  }

  // ---- result ------------------------------------------------------------------------------------
  void finish() {
    std::uint64_t nestled = 0, sedition = 0, otherSkinny = 0, large = 0;
    for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
      if (!t_.alive(s)) continue;
      const TriangleQuality q = qualityAt(s);
      const double bound = maxAreaAt(s);
      if (bound > 0 && q.area > bound * (1 + 1e-9)) ++large;
      if (!isSkinny(q)) continue;
      const TriangleShape sh = shapeOf(t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2]));
      if (nestledInInputAngle(s, sh)) ++nestled;
      else if (seditious(s, sh)) ++sedition;
      else ++otherSkinny;
    }
    auto add = [&](ReasonKind k, std::uint64_t n, const std::string& msg) {
      out_.reasons.push_back(Reason{k, n, msg});
    };
    const std::uint64_t unmet = otherSkinny + large;
    if (cancelled_)
      add(ReasonKind::Cancelled, unmet, "refinement was cancelled; " + std::to_string(unmet) +
                                            " triangle(s) do not meet the bounds");
    else if (budgetHit_)
      add(ReasonKind::SteinerBudget, unmet, "the Steiner budget of " + std::to_string(budget_) +
                                                " vertices was reached; " + std::to_string(unmet) +
                                                " triangle(s) do not meet the bounds");
    else if (unmet > 0 || floorHits_ > 0)
      add(ReasonKind::PrecisionFloor, unmet,
          std::to_string(unmet) + " triangle(s) could not be improved: " + std::to_string(floorHits_) +
              " insertion(s) were refused because the new vertex would be closer than double precision can "
              "resolve, or its coordinates would leave what exact arithmetic or the output's numbers can hold, "
              "or its cavity would wrap around a vertex where the domain touches itself");
    if (nestled)
      add(ReasonKind::SmallInputAngle, nestled, std::to_string(nestled) +
          " triangle(s) sit in input angles smaller than the bound; no vertex can fix them (section 6.6)");
    if (sedition)
      add(ReasonKind::SeditiousEdge, sedition, std::to_string(sedition) +
          " triangle(s) have a seditious shortest edge between segments meeting at under 45 degrees; "
          "left alone so refinement terminates (section 6.6)");
  }
};

}  // namespace

RefineOutcome refine(MeshState& m) {
  Refiner r(m);
  return r.run();
}

}  // namespace ruppert::detail
