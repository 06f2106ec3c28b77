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
//         to search the shortest edge's petal for a point that makes no new skinny triangle;
//         Placement::Optimal takes Erten and Üngör's locally optimal point, or moves a free vertex
//         (optimal_placement.h).
// Termination for any input: besides §6.6, a Steiner budget and a floor on subsegment length below
// which doubles cannot place new points; hitting either ends refinement with complete = false.
//
// Terminology: "subsegment" = constrained edge (con != kFree); "corner" = an input or intersection
// vertex where two constrained edges meet at less than 90 degrees; rho = circumradius / shortest edge.
#include "refine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "bad_triangle_queue.h"
#include "bound_push.h"
#include "old_mesh.h"
#include "optimal_placement.h"
#include "point_attributes.h"
#include "placement.h"
#include "predicates.h"
#include "refine_geometry.h"
#include "refine_setup.h"
#include "triangle_shape.h"

namespace ruppert::detail {

bool refinementRequested(const MeshState& m) {
  const Options& o = *m.options;
  bool regionArea = false;
  for (const Region& r : m.input.regions) regionArea = regionArea || r.maxArea > 0;
  const bool oldMeshArea = m.oldMesh != nullptr && m.oldMesh->hasBounds();
  return o.minAngle > 0 || o.maxArea > 0 || regionArea || oldMeshArea || static_cast<bool>(o.sizeFunction);
}

namespace {

// Segments meeting below this angle can make seditious edges. Prop. 6.14 proves termination with
// 60 degrees; §6.6 advises a smaller angle in practice (fewer triangles left skinny), which threatens
// termination only well below 20 degrees, and the Steiner budget bounds the work regardless. 45
// degrees lets earcut_earcut.poly reach 30 degrees where 60 left a 26.96-degree triangle.
constexpr double kSeditiousAngle = kPi / 4;
// corner_ holds 1 + 254 cos(the corner's smallest gap) (refine_setup.cpp): at or above this value the
// gap is under kSeditiousAngle.
constexpr std::uint8_t kSeditiousCorner = 1 + 180;  // 254 cos(45 degrees) = 179.6

// A cavity already computed by Triangulation::cavity, handed to the insertion so it is not searched
// twice (both null: none).
struct CavityRef {
  const std::vector<std::uint32_t>* tris = nullptr;
  const std::vector<std::uint32_t>* boundary = nullptr;
};

// A subsegment remembered by its endpoints, with a half-edge that was the edge when queued.
struct EdgeRef {
  std::uint32_t a, b, hint;
};

double radians(double degrees) { return degrees * kPi / 180.0; }
// sin^2 of a bound, lowered by a relative 1e-12 against rounding.
double sin2Bound(double theta) { return std::sin(theta) * std::sin(theta) * (1 - 1e-12); }

// Lens apex angle 180 - 2 theta, never below the disk's 90 degrees: cos(180 - 2 theta) = -cos(2 theta).
double lensCos2For(const Options& o, double theta) {
  if (o.encroachment == Encroachment::DiametralLens && theta < kPi / 4) return std::cos(2 * theta) * std::cos(2 * theta);
  return 0;
}

class Refiner {
  // Per-triangle region data carried from a cavity slot to the new triangle that replaces it.
  struct Inherited {
    double attribute, maxArea;
    std::uint8_t inDomain;
  };

  MeshState& m_;
  Triangulation& t_;
  const Options& o_;
  RefineOutcome out_;
  const RefinePlan plan_;
  double stageDegrees_;     // the current stage's angle bound (the requested one unless staged)
  double theta_;            // the same in radians
  double sin2Theta_;        // sin2Bound(theta_)
  const double sin2Requested_;
  MeshAccess mesh_;         // read-only queries for placements (and the walk)
  PetalPlacement petal_;
  OptimalPlacement optimal_;
  std::vector<std::uint8_t> relocations_;  // per vertex: how often it was moved (Placement::Optimal)
  PushTracker push_;              // staged runs only (plan_.track)
  std::uint64_t nextScoreAt_ = 0; // when the push next scores the mesh
  bool pushing_ = false;          // past the first stage
  bool unreachable_ = false;      // the result is the best mesh of a push that stopped short
  bool capHit_ = false;           // stopped at plan_.triangleCap
  const char* pushStop_ = "";     // why the push stopped, for the reason's message
  // The push's best mesh so far, with the trace length and rejection count it had.
  struct Snapshot {
    MeshState mesh;
    std::size_t events = 0;
    std::uint64_t rejected = 0;
  } best_;
  std::uint64_t budget_ = 0, inserted_ = 0;
  bool cancelled_ = false, budgetHit_ = false;
  std::uint64_t floorHits_ = 0;  // insertions refused at the precision limit
  std::uint64_t forbiddenHits_ = 0;  // splits refused by noBoundarySteiner / noSegmentSteiner
  bool refusedSplit_ = false;        // the current bad triangle's point asked for a refused split
  std::vector<EdgeRef> encroached_;
  BadTriangleQueue bad_;
  std::vector<std::uint8_t> corner_;  // per vertex: acute input corner (concentric shells apply)
  std::vector<std::uint32_t> newTris_, parents_, flipped_, mendStack_;
  std::vector<Inherited> inherit_;
  std::vector<std::uint32_t> cavityTris_, cavityBoundary_, splitTris_, splitBoundary_;
  std::vector<EdgeRef> rejectPairs_;
  mutable std::vector<double> oldBound_, oldBoundAt_;  // oldMeshBound's memo: per slot, and 6 coordinates

 public:
  Refiner(MeshState& m, const RefinePlan& plan)
      : m_(m),
        t_(m.tri),
        o_(*m.options),
        plan_(plan),
        stageDegrees_(plan.first),
        theta_(radians(plan.first)),
        sin2Theta_(sin2Bound(theta_)),
        sin2Requested_(sin2Bound(radians(plan.requested))),
        mesh_(m.tri, m.input, sin2Theta_, lensCos2For(o_, theta_)),
        petal_(o_.placement == Placement::Petal ? theta_ : 0),
        optimal_(theta_) {}

  // After run(): whether it stopped at plan_.triangleCap.
  bool capHit() const { return capHit_; }

  RefineOutcome run() {
    corner_ = acuteCorners(m_);
    const std::uint64_t budget = steinerBudget(m_);
    budget_ = budget > plan_.used ? budget - plan_.used : 0;
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
      if (!bad_.pop(bt)) {
        if (nextStage()) continue;
        break;
      }
      if (!isCurrent(t_, bt)) continue;  // stale entry: the triangle is gone
      splitTriangle(bt);
      stop = outOfBudget() || overCap() || pushStopped();
    }
    if (pushing_ && stop && !cancelled_) endPush();
    finish();
    return std::move(out_);
  }

 private:
  // ---- stages (bound_push.h) -------------------------------------------------------------------
  void setBound(double degrees) {
    stageDegrees_ = degrees;
    theta_ = radians(degrees);
    sin2Theta_ = sin2Bound(theta_);
    mesh_.sin2Theta = sin2Theta_;
    mesh_.lensCos2 = lensCos2For(o_, theta_);
    if (o_.placement == Placement::Petal) petal_ = PetalPlacement(theta_);
    if (o_.placement == Placement::Optimal) optimal_ = OptimalPlacement(theta_);
  }

  // The queue is empty: if a stage below the requested bound just completed, raise the bound by a
  // step and queue what the new bound makes bad. False when there is no next stage.
  bool nextStage() {
    if (!(stageDegrees_ < plan_.requested)) return false;
    if (plan_.track) {
      if (!pushing_) push_.setBase(liveTriangles());
      observe();
    }
    pushing_ = true;
    setBound(std::min(plan_.requested, stageDegrees_ + kStageStepDegrees));
    push_.newStage(inserted_);
    for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
      if (!t_.alive(s)) continue;
      checkTriangle(s);
      for (std::uint32_t i = 0; i < 3; ++i) checkSubsegment(3 * s + i);
    }
    return true;
  }

  std::uint64_t liveTriangles() const { return t_.slotCount() - t_.freeSlots.size(); }

  bool overCap() {
    if (!plan_.triangleCap || liveTriangles() <= plan_.triangleCap) return false;
    capHit_ = true;
    pushStop_ = "the mesh reached four times the 33-degree mesh's triangles";
    return true;
  }

  // Scores the mesh and, if it is the best so far, keeps a copy.
  void observe() {
    if (!push_.observe(score(), inserted_)) return;
    best_.mesh = m_;
    best_.events = out_.events.size(), best_.rejected = out_.rejected;
  }

  // During a push: scores the mesh every so often (every quarter of its size in insertions, so
  // scores and copies cost a fraction of the refinement) and stops when a stage stops reducing its
  // bad triangles.
  bool pushStopped() {
    if (!plan_.track || !pushing_ || inserted_ < nextScoreAt_) return false;
    nextScoreAt_ = inserted_ + std::max<std::uint64_t>(2048, liveTriangles() / 4);
    observe();
    if (!push_.stalled(inserted_)) return false;
    pushStop_ = "a stage stopped reducing its skinny triangles";
    return true;
  }

  // The push stopped short of the requested bound: the result is its best mesh.
  void endPush() {
    if (!plan_.track) return;
    if (budgetHit_) pushStop_ = "the Steiner budget was reached";
    if (!capHit_) observe();  // a mesh over the cap is never the result
    unreachable_ = true;
    if (push_.bestStep() == inserted_) return;
    m_ = std::move(best_.mesh);
    out_.events.resize(best_.events);
    out_.rejected = best_.rejected;
  }

  // The whole mesh against the requested bound and the current stage's.
  MeshScore score() const {
    MeshScore sc;
    for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
      if (!t_.alive(s)) continue;
      ++sc.triangles;
      const TriangleQuality q = qualityAt(s);
      const double bound = maxAreaAt(s);
      if (bound > 0 && q.area > bound * (1 + 1e-9)) ++sc.large;
      if (q.sin2MinAngle < sin2Requested_) {
        const TriangleShape sh = shapeOf(t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2]));
        if (nestledInInputAngle(s, sh) || seditious(s, sh)) continue;
        ++sc.belowRequested;
        if (q.sin2MinAngle < sin2Theta_) ++sc.belowStage;
      }
      sc.minSin2 = std::min(sc.minSin2, q.sin2MinAngle);
    }
    return sc;
  }

  // ---- tests ---------------------------------------------------------------------------------
  // O(1) test of Exercise 1: the subsegment h is encroached iff an apex on either side sees it at
  // 90 degrees or more.
  bool isEncroached(std::uint32_t h) const {
    if (mesh_.encroachesEdge(t_.pt(t_.apex(h)), h)) return true;
    const std::uint32_t g = t_.twin[h];
    return g != kNone && mesh_.encroachesEdge(t_.pt(t_.apex(g)), h);
  }
  void checkSubsegment(std::uint32_t h) {
    if (t_.con[h] == kFree) return;
    if (mesh_.encroachesEdge(t_.pt(t_.apex(h)), h)) encroached_.push_back({t_.origin(h), t_.dest(h), h});
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
    if (m_.oldMesh != nullptr) {
      const double old = oldMeshBound(s);
      if (old > 0) bound = bound > 0 ? std::min(bound, old) : old;
    }
    return bound;
  }

  // Refining a mesh: the old mesh's bound for slot s (old_mesh.h), remembered with the corner
  // coordinates it was computed for (vertex ids would not do: Placement::Optimal moves vertices).
  double oldMeshBound(std::uint32_t s) const {
    if (oldBound_.size() < t_.slotCount()) oldBound_.resize(t_.slotCount(), 0), oldBoundAt_.resize(6 * std::size_t(t_.slotCount()), NAN);
    const double* p[3] = {t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2])};
    double* at = &oldBoundAt_[6 * std::size_t(s)];
    bool same = true;
    for (int i = 0; i < 6; ++i) same = same && at[i] == p[i / 2][i % 2];
    if (!same) {
      oldBound_[s] = m_.oldMesh->boundFor(p[0], p[1], p[2]);
      for (int i = 0; i < 6; ++i) at[i] = p[i / 2][i % 2];
    }
    return oldBound_[s];
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
    const double shortest2 = skinny ? std::min({sq(p1, p2), sq(p2, p0), sq(p0, p1)}) : 0;
    bad_.push(t_, s, skinny, shortest2, q.sin2MinAngle);
  }

  // Checked before every insertion, so that a budget of k inserts at most k vertices (0: none).
  // The loop also stops once k are in (outOfBudget), so any k > 0 gives the first k insertions of
  // the unbounded run.
  bool mayInsert() {
    if (inserted_ < budget_) return true;
    budgetHit_ = true;
    return false;
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
      p.worstAngle = bad_.worstQueuedAngle(o_.minAngle);
      if (!o_.onProgress(p)) {
        cancelled_ = true;
        return true;
      }
    }
    return false;
  }

  // ---- forbidden splits (Options::noBoundarySteiner, noSegmentSteiner) ---------------------------
  // Such a subsegment is never split. A point that encroaches it, lies beyond it or on it is not
  // inserted; instead a triangle over its area bound gets a point pulled back towards its centroid
  // (halfway or a quarter of the way, if that encroaches no subsegment, else the centroid itself)
  // (placeAwayFromForbidden); a triangle that is only skinny stays as it is.
  // Only centroids of triangles over their area bound may lie in a forbidden subsegment's lens; what
  // stays bad is reported as SegmentSplitForbidden. The Steiner budget and the length floor bound
  // the work regardless.
  bool onDomainBoundary(std::uint32_t h) const {
    const std::uint32_t g = t_.twin[h];
    if (m_.inDomain.empty()) return g == kNone;
    // Bounding-box variant: the box's sides are not the domain's boundary.
    return g != kNone && m_.inDomain[h / 3] != m_.inDomain[g / 3];
  }
  bool splitForbidden(std::uint32_t h) const {
    if (o_.noSegmentSteiner && (t_.con[h] >= 0 || onDomainBoundary(h))) return true;
    return o_.noBoundarySteiner && onDomainBoundary(h);
  }

  // The fallback of a triangle whose point was refused (see above): between the point and the
  // triangle's centroid, the first of three points that lies in the domain on this side and
  // encroaches no subsegment. False if none does.
  bool placeAwayFromForbidden(const BadTriangle& bt, const double* const* p, const double* refused) {
    const double g[2] = {(p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3};
    for (double lambda : {0.5, 0.25, 0.0}) {
      const double q[2] = {g[0] + lambda * (refused[0] - g[0]), g[1] + lambda * (refused[1] - g[1])};
      std::uint32_t blocked;
      const Location loc = mesh_.walk(bt.slot, q, blocked);
      if (blocked != kNone || loc.kind == Location::Lost || loc.kind == Location::OnVertex) continue;
      if (loc.kind == Location::OnEdge && t_.con[loc.edge] != kFree) continue;
      t_.cavity(q, loc, cavityTris_, cavityBoundary_);
      if (mesh_.tooCloseToCavity(q, cavityBoundary_) || !mesh_.representable(q)) continue;
      // The centroid, the last resort, may encroach a forbidden subsegment: a triangle over its area
      // bound always holds it, so the bound is met in the end (its distance to the triangle's
      // corners, at least 2/3 of its smallest altitude, 4 A / (3 longest edge), keeps the splits finite).
      bool encroaches = false;
      for (std::uint32_t h : cavityBoundary_)
        encroaches = encroaches || (t_.con[h] != kFree && (lambda > 0 || !splitForbidden(h)) && mesh_.encroachesEdge(q, h));
      if (encroaches) continue;
      insertSteiner(bt, q, loc, VertexKind::Interior, {&cavityTris_, &cavityBoundary_});
      return true;
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
    const std::uint32_t a0 = m_.segmentEnd(su, 0), a1 = m_.segmentEnd(su, 1);
    const std::uint32_t b0 = m_.segmentEnd(sw, 0), b1 = m_.segmentEnd(sw, 1);
    double z[2];
    if (a0 == b0 || a0 == b1) {
      z[0] = t_.xy[2 * a0], z[1] = t_.xy[2 * a0 + 1];
    } else if (a1 == b0 || a1 == b1) {
      z[0] = t_.xy[2 * a1], z[1] = t_.xy[2 * a1 + 1];
    } else if (!segmentsMeet(t_.pt(a0), t_.pt(a1), t_.pt(b0), t_.pt(b1), z)) {
      return false;
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
    if (m_.attributeCount) interpolateAttributes(v, loc);
    // Bowyer-Watson first; where its cavity would wrap around a vertex at which the domain touches
    // itself, split and flip instead.
    const bool filled = cavity.tris ? t_.fillCavity(v, loc, *cavity.tris, *cavity.boundary, &newTris_, &parents_)
                                    : t_.insertVertex(v, loc, &newTris_, &parents_);
    if (!filled && !t_.insertVertexByFlips(v, loc, &newTris_, &parents_)) return false;
    ++inserted_;
    inheritRegionData();
    if (onSubsegment) mendDelaunay();
    for (std::uint32_t s : newTris_) {
      checkTriangle(s);
      for (std::uint32_t i = 0; i < 3; ++i) checkSubsegment(3 * s + i);
      // The outer edge's far side is an old triangle: its apex may now encroach nothing new, but a
      // split subsegment's halves need checking from both sides.
      const std::uint32_t g = t_.twin[3 * s];
      if (g != kNone) checkSubsegment(g);
    }
    recheckFlipped();
    return true;
  }

  // v's attributes from the edge or triangle it is about to be inserted in (point_attributes.h).
  void interpolateAttributes(std::uint32_t v, const Location& loc) {
    if (loc.kind == Location::OnEdge) return interpolateOnSegment(m_, v, t_.origin(loc.edge), t_.dest(loc.edge));
    const std::uint32_t* c = &t_.tv[3 * loc.tri];
    interpolateInTriangle(m_, v, c[0], c[1], c[2]);
  }

  // A vertex about to move to x: its attributes at x, from the triangle of its star that holds x.
  void reinterpolateMoved(std::uint32_t v, const double* x) {
    const std::vector<std::uint32_t>& star = optimal_.star();
    if (star.empty()) return;
    std::uint32_t pick = star.front();
    for (std::uint32_t h : star) {
      const double* o = t_.pt(t_.origin(h));
      const double* d = t_.pt(t_.dest(h));
      if (orient2d(o, d, x) >= 0 && orient2d(t_.pt(v), o, x) >= 0 && orient2d(d, t_.pt(v), x) >= 0) {
        pick = h;
        break;
      }
    }
    interpolateInTriangle(m_, v, v, t_.origin(pick), t_.dest(pick), x);
  }

  // Triangles changed by flips (in flipped_): queue them if bad, and their edges and the edges
  // across them if encroached.
  void recheckFlipped() {
    for (std::uint32_t s : flipped_) {
      checkTriangle(s);
      for (std::uint32_t i = 0; i < 3; ++i) {
        checkSubsegment(3 * s + i);
        if (t_.twin[3 * s + i] != kNone) checkSubsegment(t_.twin[3 * s + i]);
      }
    }
  }

  // The new triangles take their parents' region data. Two passes: a new triangle may reuse the
  // slot of another new triangle's parent.
  void inheritRegionData() {
    const bool box = !m_.inDomain.empty();
    if (m_.attribute.size() < t_.slotCount()) {
      m_.attribute.resize(t_.slotCount(), 0);
      m_.maxArea.resize(t_.slotCount(), 0);
      if (box) m_.inDomain.resize(t_.slotCount(), 0);
    }
    inherit_.resize(newTris_.size());
    for (std::size_t k = 0; k < newTris_.size(); ++k)
      inherit_[k] = {m_.attribute[parents_[k]], m_.maxArea[parents_[k]], box ? m_.inDomain[parents_[k]] : std::uint8_t(1)};
    for (std::size_t k = 0; k < newTris_.size(); ++k) {
      m_.attribute[newTris_[k]] = inherit_[k].attribute, m_.maxArea[newTris_[k]] = inherit_[k].maxArea;
      if (box) m_.inDomain[newTris_[k]] = inherit_[k].inDomain;
    }
  }

  // A subsegment's split point is rounded, so it lies a hair off the subsegment's line. Bowyer-Watson
  // treats it as on the edge and joins it to the boundary of both sides' cavities; when it falls just
  // outside one side's triangle, a free edge there can end up not locally Delaunay (found by fuzzing,
  // tests/hostile/split-point-off-its-segment-broke-delaunay.poly: two segments meeting at 5e-8
  // radians, split into pieces a million times longer than that offset). Lawson flips around the new triangles mend it; flip() keeps both slots, and the two
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

  // Where subsegment h from pa to pb is split (§6.2, §6.6), into xy; false if no point can be kept.
  bool subsegmentSplitPoint(std::uint32_t h, const double* pa, const double* pb, std::uint32_t a, std::uint32_t b,
                            double xy[2]) const {
    const double len = dist(pa, pb);
    // Concentric shells: measured from an acute corner, the piece next to it gets a power-of-two
    // length in (len/3, 2len/3], so equal pieces on neighbouring segments do not encroach each other.
    // Between two corners, one under kSeditiousAngle and sharper than the other, the shells are
    // measured from the sharper, at the power of two nearest half the length: every later split
    // near that corner then lies on one of its shells on both of its segments, where seditious
    // edges stop the refinement (§6.6); a midpoint there starts the two sides off different shells
    // and a cascade of splits towards the corner (the spikes of stars: 15% fewer triangles, 0.86x;
    // shape families 0.99x, corpus triangles 0.99x in sum).
    double f = 0.5;
    const bool ca = corner_[a] != 0, cb = corner_[b] != 0;
    if (ca && cb && corner_[a] != corner_[b] && std::max(corner_[a], corner_[b]) >= kSeditiousCorner) {
      const double d = std::exp2(std::round(std::log2(len / 2)));
      f = corner_[a] > corner_[b] ? d / len : 1.0 - d / len;
    } else if (ca != cb) {
      const double d = std::exp2(std::floor(std::log2(2.0 * len / 3.0)));
      f = ca ? d / len : 1.0 - d / len;
    }
    double x = pa[0] + f * (pb[0] - pa[0]), y = pa[1] + f * (pb[1] - pa[1]);
    // On a subsegment with no triangle beyond it, a split point rounded to the outside can land in
    // another part of the domain across an exterior sliver thinner than the rounding (found by
    // fuzzing, tests/hostile/boundary-split-rounded-across-an-exterior-sliver.poly: two segments
    // 1e-7 rad apart bounding a hole). Move it an ulp at a time onto the
    // domain's side, the left of a -> b.
    if (t_.twin[h] == kNone) {
      const double towardsX = pa[1] - pb[1], towardsY = pb[0] - pa[0];
      for (int step = 0;; ++step) {
        const double p[2] = {x, y};
        if (orient2d(pa, pb, p) >= 0) break;
        if (step == 4) return false;
        x = std::nextafter(x, towardsX > 0 ? HUGE_VAL : towardsX < 0 ? -HUGE_VAL : x);
        y = std::nextafter(y, towardsY > 0 ? HUGE_VAL : towardsY < 0 ? -HUGE_VAL : y);
      }
    }
    xy[0] = x, xy[1] = y;
    return mesh_.representable(xy);
  }

  // Split subsegment h (§6.2, §6.6). `bt` and `rejected`: the triangle whose point was rejected
  // and that point, if that is why, for the trace. False if it cannot be split (precision floor).
  bool splitSubsegment(std::uint32_t h, const BadTriangle* bt, const double* rejected) {
    if (splitForbidden(h)) {
      ++forbiddenHits_;
      refusedSplit_ = true;
      return false;
    }
    const std::uint32_t a = t_.origin(h), b = t_.dest(h);
    // Copies: adding a vertex below may reallocate the coordinate array.
    const double pa[2] = {t_.xy[2 * a], t_.xy[2 * a + 1]};
    const double pb[2] = {t_.xy[2 * b], t_.xy[2 * b + 1]};
    double split[2];
    if (dist(pa, pb) < 3 * kLengthFloor || !subsegmentSplitPoint(h, pa, pb, a, b, split)) {
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
    // than doubles can keep apart (found by fuzzing, tests/hostile/shell-splits-closer-than-doubles-resolve.poly).
    // Refuse those, as the length floor does.
    t_.cavity(split, loc, splitTris_, splitBoundary_);
    if (mesh_.tooCloseToCavity(split, splitBoundary_)) {
      ++floorHits_;
      return false;
    }
    if (!mayInsert()) return false;
    const std::int32_t segment = t_.con[h] >= 0 ? t_.con[h] : -1;
    const double x = split[0], y = split[1];
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

  // The first choice of point for a bad triangle: its circumcenter, or for a skinny one (unless
  // Placement::Circumcenter) the off-center when that is nearer. False: no point to trust.
  bool firstChoice(const double* const* p, const TriangleShape& sh, bool skinny, double target[2],
                   VertexKind& kind) const {
    double cc[2];
    if (!circumcenter(p, cc)) return false;
    target[0] = cc[0], target[1] = cc[1];
    kind = VertexKind::Interior;
    if (skinny && o_.placement != Placement::Circumcenter) {
      const int e = sh.shortestEdge;
      if (offCenter(p[(e + 1) % 3], p[(e + 2) % 3], sh.shortest, cc, theta_, target)) kind = VertexKind::OffCenter;
    }
    return mesh_.representable(target);
  }

  // A better point than the first choice from the configured placement, if it has one (placement.h).
  bool improvePlacement(const SkinnyTriangle& st, double target[2], Location& loc) {
    switch (o_.placement) {
      case Placement::Petal:
        // Only where no area bound applies: with one, the bound sets the size and the search buys
        // little (unit square, max area 1e-6: 794.6 k vertices with it, 794.7 k without, at 4x the time).
        return !(maxAreaAt(st.slot) > 0) && petal_.propose(mesh_, st, target, loc);
      default:
        return false;
    }
  }

  void splitTriangle(const BadTriangle& bt) {
    const std::uint32_t s = bt.slot;
    const double* p[3] = {t_.pt(bt.a), t_.pt(bt.b), t_.pt(bt.c)};
    const TriangleShape sh = shapeOf(p[0], p[1], p[2]);
    const TriangleQuality q = qualityOf(p[0], p[1], p[2]);
    const bool skinny = isSkinny(q);
    // A moved vertex (relocate) leaves its old triangles' entries current (same vertices) though
    // their shape has changed: such a triangle may now meet the bounds.
    if (!relocations_.empty() && !skinny && !(maxAreaAt(s) > 0 && q.area > maxAreaAt(s))) return;
    if (skinny && (nestledInInputAngle(s, sh) || seditious(s, sh))) {
      const double bound = maxAreaAt(s);
      if (!(bound > 0 && q.area > bound)) return;  // left alone on purpose; counted in finish()
    }
    double target[2];
    VertexKind kind;
    if (sh.shortest < 2 * kLengthFloor || !firstChoice(p, sh, skinny, target, kind)) {
      ++floorHits_;
      return;
    }
    // As for Petal, only where no area bound applies.
    if (skinny && o_.placement == Placement::Optimal && !(maxAreaAt(s) > 0) && optimalOrRelocate(bt, p, sh, target))
      return;
    Location loc;
    refusedSplit_ = false;
    const std::uint64_t before = inserted_;
    if (!locateOrReject(bt, target, loc)) {
      // (Only when nothing was inserted meanwhile: p points into the coordinates, which may move.)
      // Only for triangles over their area bound: for skinny ones, centroids cascade into ever
      // smaller skinny triangles along the forbidden subsegment (measured: A.poly at 30 degrees ran
      // to the Steiner budget, 15 829 vertices, where it needs 78 without the option).
      if (refusedSplit_ && inserted_ == before && isCurrent(t_, bt) && maxAreaAt(s) > 0 && q.area > maxAreaAt(s))
        placeAwayFromForbidden(bt, p, target);
      return;
    }
    CavityRef known{&cavityTris_, &cavityBoundary_};
    const SkinnyTriangle st{s, p, sh, target, &cavityBoundary_};
    double better[2];
    Location betterLoc;
    if (skinny && improvePlacement(st, better, betterLoc)) {
      // A proposed point has a cavity of its own: insertAt computes it.
      target[0] = better[0], target[1] = better[1], loc = betterLoc;
      kind = VertexKind::OffCenter, known = {};
      insertSteiner(bt, target, loc, kind, known, EventKind::PetalPoint);
      return;
    }
    insertSteiner(bt, target, loc, kind, known);
  }

  // Placement::Optimal (optimal_placement.h): insert the locally optimal point if one meets the bound,
  // else move a free endpoint of the shortest edge. False: neither; the first choice goes ahead.
  bool optimalOrRelocate(const BadTriangle& bt, const double* const* p, const TriangleShape& sh, const double* first) {
    double cc[2], x[2];
    if (!circumcenter(p, cc)) return false;
    const SkinnyTriangle st{bt.slot, p, sh, first, nullptr};
    Location loc;
    switch (optimal_.propose(mesh_, st, cc, x, loc)) {
      case OptimalPlacement::Result::Found:
        insertSteiner(bt, x, loc, VertexKind::OffCenter, {}, EventKind::OptimalPoint);
        return true;
      case OptimalPlacement::Result::FirstFine:
        return false;
      case OptimalPlacement::Result::None:
        break;
    }
    const std::uint32_t ends[2] = {t_.tv[3 * bt.slot + (sh.shortestEdge + 1) % 3], t_.tv[3 * bt.slot + (sh.shortestEdge + 2) % 3]};
    for (std::uint32_t v : ends)
      if (relocate(v)) return true;
    return false;
  }

  // Erten and Üngör's relocation: move v, a vertex refinement placed off every segment, to where
  // every triangle of its star meets the bound (OptimalPlacement::relocation), then restore the
  // Delaunay property by flips and re-check what changed. Each vertex moves at most
  // kMaxRelocations times and every move counts against the Steiner budget, so refinement still
  // ends. Not with a trace: the replay knows only insertions.
  static constexpr std::uint8_t kMaxRelocations = 4;
  bool relocate(std::uint32_t v) {
    if (o_.trace || v < m_.inputCount || (m_.kind[v] != VertexKind::Interior && m_.kind[v] != VertexKind::OffCenter))
      return false;
    if (relocations_.size() <= v) relocations_.resize(t_.vertexCount(), 0);
    double x[2];
    if (relocations_[v] >= kMaxRelocations || !mayInsert() || !optimal_.relocation(mesh_, v, x)) return false;
    if (m_.attributeCount) reinterpolateMoved(v, x);
    t_.xy[2 * v] = x[0], t_.xy[2 * v + 1] = x[1];
    ++relocations_[v], ++inserted_;
    // The star's edges, and those of the triangles beyond it, may no longer be locally Delaunay.
    mendStack_.clear();
    flipped_.clear();
    for (std::uint32_t h : optimal_.star())
      for (std::uint32_t k = 0; k < 3; ++k) mendStack_.push_back(3 * (h / 3) + k);
    t_.legalize(mendStack_, &flipped_);
    for (std::uint32_t h : optimal_.star()) flipped_.push_back(h / 3);
    std::sort(flipped_.begin(), flipped_.end());
    flipped_.erase(std::unique(flipped_.begin(), flipped_.end()), flipped_.end());
    recheckFlipped();
    return true;
  }

  // Locate target for bad triangle bt. Where it lies beyond or on a subsegment, or encroaches one on
  // its cavity's boundary (§6.2, §6.3), it is rejected and those subsegments are split instead;
  // false then, and false at the precision limit. True: loc and cavityTris_ / cavityBoundary_ hold
  // its location and cavity.
  bool locateOrReject(const BadTriangle& bt, const double* target, Location& loc) {
    std::uint32_t blocked;
    loc = mesh_.walk(bt.slot, target, blocked);
    if (blocked != kNone) {
      // The new vertex would lie beyond a subsegment: that subsegment is encroached (Prop. 6.2).
      reject(bt, blocked, target);
      return false;
    }
    if (loc.kind == Location::Lost || loc.kind == Location::OnVertex) {
      ++floorHits_;
      return false;
    }
    if (loc.kind == Location::OnEdge && t_.con[loc.edge] != kFree) {
      reject(bt, loc.edge, target);
      return false;
    }
    t_.cavity(target, loc, cavityTris_, cavityBoundary_);
    if (mesh_.tooCloseToCavity(target, cavityBoundary_)) {
      ++floorHits_;
      return false;
    }
    for (std::uint32_t h : cavityBoundary_)
      if (t_.con[h] != kFree && mesh_.encroachesEdge(target, h)) rejectPairs_.push_back({t_.origin(h), t_.dest(h), h});
    if (rejectPairs_.empty()) return true;
    ++out_.rejected;
    bool splitSome = false;
    for (const EdgeRef& e : rejectPairs_) {
      const std::uint32_t h = edgeOf(e);
      if (h != kNone && t_.con[h] != kFree) splitSome = splitSubsegment(h, &bt, target) || splitSome;
    }
    rejectPairs_.clear();
    if (splitSome) requeue(bt);
    return false;
  }

  // `placed`: the event's kind when a placement other than the first choice chose the point.
  void insertSteiner(const BadTriangle& bt, const double* target, const Location& loc, VertexKind kind,
                     const CavityRef& known, std::optional<EventKind> placed = std::nullopt) {
    if (!mayInsert()) return;
    const std::uint32_t v = m_.addVertex(target[0], target[1], kind, -1);
    corner_.push_back(0);
    if (!insertAt(v, loc, known)) {
      m_.kind[v] = VertexKind::Unused;
      ++floorHits_;
      return;
    }
    if (o_.trace) {
      Event e;
      e.kind = placed ? *placed : kind == VertexKind::OffCenter ? EventKind::OffCenter : EventKind::Circumcenter;
      e.vertex = v, e.x = target[0], e.y = target[1], e.t0 = bt.a, e.t1 = bt.b, e.t2 = bt.c;
      out_.events.push_back(e);
    }
  }

  void reject(const BadTriangle& bt, std::uint32_t h, const double* target) {
    ++out_.rejected;
    if (splitSubsegment(h, &bt, target)) requeue(bt);
  }

  // The triangle survives a rejection unless the split destroyed it; keep it queued (§6.3).
  void requeue(const BadTriangle& bt) {
    if (isCurrent(t_, bt)) checkTriangle(bt.slot);
  }

  // ---- result ------------------------------------------------------------------------------------
  struct Unmet {
    std::uint64_t nestled = 0, sedition = 0, otherSkinny = 0, large = 0;
    double minSin2 = 1;  // over the triangles the bound applies to
  };
  Unmet countUnmet() const {
    Unmet u;
    for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
      if (!t_.alive(s)) continue;
      const TriangleQuality q = qualityAt(s);
      const double bound = maxAreaAt(s);
      if (bound > 0 && q.area > bound * (1 + 1e-9)) ++u.large;
      if (!isSkinny(q)) {
        u.minSin2 = std::min(u.minSin2, q.sin2MinAngle);
        continue;
      }
      const TriangleShape sh = shapeOf(t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2]));
      if (nestledInInputAngle(s, sh)) ++u.nestled;
      else if (seditious(s, sh)) ++u.sedition;
      else ++u.otherSkinny, u.minSin2 = std::min(u.minSin2, q.sin2MinAngle);
    }
    return u;
  }

  std::string unreachableMessage(std::uint64_t unmet, double reached) const {
    char angles[96];
    std::snprintf(angles, sizeof angles, "%.6g degrees is out of reach; the smallest angle reached is %.2f", plan_.requested, reached);
    return std::string("a minimum angle of ") + angles + " degrees (section 6.6's exemptions aside): refining to it directly did not complete within eight times the "
           "triangles of the " + std::to_string(static_cast<int>(kReachableDegrees)) + "-degree mesh, and from that mesh "
           "refinement raised the bound a degree at a time until " + pushStop_ + "; this is the best mesh it reached; " + std::to_string(unmet) +
           " triangle(s) are below the bound";
  }

  void finish() {
    if (stageDegrees_ != plan_.requested) setBound(plan_.requested);  // judge by the bound asked for
    const Unmet u = countUnmet();
    out_.reachedAngle = std::asin(std::sqrt(u.minSin2)) * 180 / kPi;
    auto add = [&](ReasonKind k, std::uint64_t n, const std::string& msg) {
      out_.reasons.push_back(Reason{k, n, msg});
    };
    const std::uint64_t unmet = u.otherSkinny + u.large;
    if (cancelled_)
      add(ReasonKind::Cancelled, unmet, "refinement was cancelled; " + std::to_string(unmet) +
                                            " triangle(s) do not meet the bounds");
    else if (unreachable_)
      add(ReasonKind::AngleUnreachable, unmet, unreachableMessage(unmet, out_.reachedAngle));
    else if (budgetHit_)
      add(ReasonKind::SteinerBudget, unmet, "the Steiner budget of " + std::to_string(budget_) +
                                                " vertices was reached; " + std::to_string(unmet) +
                                                " triangle(s) do not meet the bounds");
    else if (unmet > 0 && forbiddenHits_ > 0)
      add(ReasonKind::SegmentSplitForbidden, unmet,
          std::to_string(unmet) + " triangle(s) do not meet the bounds: " + std::to_string(forbiddenHits_) +
              " split(s) of subsegments were refused because " +
              (o_.noSegmentSteiner ? "no new vertex may lie on a segment" : "no new vertex may lie on the domain's boundary") +
              " (no-segment-steiner / no-boundary-steiner), and the vertices that would have caused them were not inserted");
    else if (unmet > 0 || floorHits_ > 0)
      add(ReasonKind::PrecisionFloor, unmet,
          std::to_string(unmet) + " triangle(s) could not be improved: " + std::to_string(floorHits_) +
              " insertion(s) were refused because the new vertex would be closer than double precision can "
              "resolve, or its coordinates would leave what exact arithmetic or the output's numbers can hold, "
              "or its cavity would wrap around a vertex where the domain touches itself");
    if (u.nestled)
      add(ReasonKind::SmallInputAngle, u.nestled, std::to_string(u.nestled) +
          " triangle(s) sit in input angles smaller than the bound; no vertex can fix them (section 6.6)");
    if (u.sedition)
      add(ReasonKind::SeditiousEdge, u.sedition, std::to_string(u.sedition) +
          " triangle(s) have a seditious shortest edge between segments meeting at under 45 degrees; "
          "left alone so refinement terminates (section 6.6)");
  }
};

}  // namespace

namespace {

bool completeOutcome(const RefineOutcome& r) {
  for (const Reason& reason : r.reasons)
    if (reason.kind != ReasonKind::SmallInputAngle && reason.kind != ReasonKind::SeditiousEdge) return false;
  return true;
}

std::uint64_t liveTriangles(const MeshState& m) { return m.tri.slotCount() - m.tri.freeSlots.size(); }

// A request above kStagedAboveDegrees (bound_push.h): the 33-degree mesh first, for its size; then
// the requested bound directly, up to eight times that size; else the push from the 33-degree mesh.
RefineOutcome refineStaged(MeshState& m) {
  const double requested = m.options->minAngle;
  MeshState start = m;
  const std::size_t unrefined = m.kind.size();
  RefineOutcome reach = Refiner(m, RefinePlan::direct(kReachableDegrees)).run();
  if (!completeOutcome(reach)) {  // not even 33 degrees: refine as asked, as without stages
    m = std::move(start);
    return Refiner(m, RefinePlan::direct(requested)).run();
  }
  const std::uint64_t base = liveTriangles(m);
  RefinePlan direct = RefinePlan::direct(requested);
  direct.triangleCap = kDirectTriangleFactor * base;
  Refiner attempt(start, direct);
  RefineOutcome out = attempt.run();
  if (!attempt.capHit() && completeOutcome(out)) {
    m = std::move(start);
    return out;
  }
  start = MeshState{};  // free it before the push
  const std::uint64_t used = m.kind.size() - unrefined;
  RefinePlan push{requested, kReachableDegrees, true, kPushTriangleFactor * base, used};
  out = Refiner(m, push).run();
  // The push continues the 33-degree run: its trace and rejections come first.
  reach.events.insert(reach.events.end(), out.events.begin(), out.events.end());
  out.events = std::move(reach.events);
  out.rejected += reach.rejected;
  return out;
}

}  // namespace

RefineOutcome refine(MeshState& m) {
  if (!(m.options->minAngle > kStagedAboveDegrees)) return Refiner(m, RefinePlan::direct(m.options->minAngle)).run();
  return refineStaged(m);
}

}  // namespace ruppert::detail
