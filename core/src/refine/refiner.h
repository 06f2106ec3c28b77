// The refinement loop's state and steps (class Refiner), one class in five files by concern:
//   refine.cpp         the main loop and its stages (above34/bound_push.h; refine() itself, which
//                      runs it directly or in stages, is in above34/staged.cpp);
//   refine_checks.cpp  what is bad: encroached subsegments, skinny and large triangles (area bounds),
//                      the Steiner budget, forbidden splits, the exemptions of §6.6;
//   refine_split.cpp   what to do about it: split points of subsegments, the point for a bad
//                      triangle (placement), rejection of points that encroach;
//   refine_insert.cpp  inserting a vertex: cavity, region data, attributes, flips that mend;
//   refine_result.cpp  why a mesh is incomplete (RefineOutcome::reasons).
// Terminology: see refine.cpp.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "refine/bad_triangle_queue.h"
#include "refine/exemptions.h"
#include "refine/above34/bound_push.h"
#include "mesh_state.h"
#include "refine/placement/optimal_placement.h"
#include "refine/placement/placement.h"
#include "refine/refine.h"
#include "refine/placement/refine_geometry.h"
#include "mesh/triangle_shape.h"

namespace ruppert::detail {

// Segments meeting below this angle can make seditious edges. Prop. 6.14 proves termination with
// 60 degrees; §6.6 advises a smaller angle in practice (fewer triangles left skinny), which threatens
// termination only well below 20 degrees, and the Steiner budget bounds the work regardless. 45
// degrees lets earcut_earcut.poly reach 30 degrees where 60 left a 26.96-degree triangle.
inline constexpr double kSeditiousAngle = kPi / 4;
// corner_ holds 1 + 254 cos(the corner's smallest gap) (refine_setup.cpp): at or above this value the
// gap is under kSeditiousAngle.
inline constexpr std::uint8_t kSeditiousCorner = 1 + 180;  // 254 cos(45 degrees) = 179.6

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

inline double radians(double degrees) { return degrees * kPi / 180.0; }
// sin^2 of a bound, lowered by a relative 1e-12 against rounding.
inline double sin2Bound(double theta) { return std::sin(theta) * std::sin(theta) * (1 - 1e-12); }

// Lens apex angle 180 - 2 theta, never below the disk's 90 degrees: cos(180 - 2 theta) = -cos(2 theta).
inline double lensCos2For(const Options& o, double theta) {
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
  // cos(Options::maxAngle), lowered by 1e-12 against rounding; -2 without that option (no
  // triangle is then wide).
  const double cosMaxAngle_;
  MeshAccess mesh_;         // read-only queries for placements (and the walk)
  PetalPlacement petal_;
  OptimalPlacement optimal_;
  std::vector<std::uint8_t> relocations_;  // per vertex: how often it was moved (Placement::Optimal)
  PushTracker push_;              // staged runs only (plan_.track)
  std::uint64_t nextScoreAt_ = 0; // when the push next scores the mesh
  bool pushing_ = false;          // past the first stage
  bool unreachable_ = false;      // the result is the best mesh of a push that stopped short
  bool capHit_ = false;           // stopped at plan_.triangleCap or plan_.domainCap
  bool overDomainCap_ = false;    // a score found more domain triangles than plan_.domainCap
  const char* pushStop_ = "";     // why the push stopped, for the reason's message
  // The push's best mesh so far, with the trace length and rejection count it had.
  struct Snapshot {
    MeshState mesh;
    std::size_t events = 0;
    std::uint64_t rejected = 0;
  } best_;
  std::uint64_t budget_ = 0, inserted_ = 0;
  // The automatic budget's checkpoints (nextGuardCheckpoint): whether this run has them, their base
  // allowance, and the size measure the last one estimated.
  bool guarded_ = false, guardStopped_ = false;
  double guardBase_ = 0;
  double guardIntegral_ = 0;
  std::uint64_t steps_ = 0;  // steps (insertions, moves) in the mesh run() returns
  bool cancelled_ = false, budgetHit_ = false;
  std::uint64_t floorHits_ = 0;  // insertions refused at the precision limit
  std::uint64_t forbiddenHits_ = 0;  // splits refused by splitForbidden()
  bool refusedSplit_ = false;        // the current bad triangle's point asked for a refused split
  std::vector<EdgeRef> encroached_;
  BadTriangleQueue bad_;
  std::vector<std::uint8_t> corner_;  // per vertex: acute input corner (concentric shells apply)
  std::vector<std::uint32_t> newTris_, parents_, flipped_, mendStack_;
  std::vector<Inherited> inherit_;
  std::vector<std::uint32_t> cavityTris_, cavityBoundary_, splitTris_, splitBoundary_;
  std::vector<EdgeRef> rejectPairs_;
  std::vector<std::uint32_t> slideStar_;  // slideOnSegment's fan
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
        cosMaxAngle_(m.options->maxAngle > 0 ? std::cos(radians(m.options->maxAngle)) - 1e-12 : -2),
        mesh_(m.tri, m.input, sin2Theta_, lensCos2For(o_, theta_)),
        petal_(o_.placement == Placement::Petal ? theta_ : 0),
        optimal_(theta_, plan.belowBoundGain) {
    mesh_.curveFirst = m.curves->first;
    bad_.setLargestFirst(plan.largestFirst);
    reserveScratch();
  }

  // After run(): whether it stopped at plan_.triangleCap.
  bool capHit() const { return capHit_; }
  // After run(): the steps that make the mesh returned, an earlier run's (plan_.used) included.
  std::uint64_t steps() const { return plan_.used + steps_; }

  RefineOutcome run();

 private:
  // Room for a typical cavity in every scratch list from the start: a call otherwise grows each
  // from empty one doubling at a time, an allocation, a copy and a free apiece.
  void reserveScratch();

  // ---- stages (bound_push.h) -------------------------------------------------------------------
  void setBound(double degrees);

  // The queue is empty: if a stage below the requested bound just completed, raise the bound by a
  // step and queue what the new bound makes bad. False when there is no next stage.
  bool nextStage();

  std::uint64_t liveTriangles() const { return t_.slotCount() - t_.freeSlots.size(); }

  bool overCap();

  // Scores the mesh and, if it is the best so far, keeps a copy.
  void observe();

  // During a push: scores the mesh every so often (every quarter of its size in insertions, so
  // scores and copies cost a fraction of the refinement) and stops when a stage stops reducing its
  // bad triangles.
  bool pushStopped();

  // The push stopped short of the requested bound: the result is its best mesh.
  void endPush();

  // The whole mesh against the requested bound and the current stage's.
  MeshScore score() const;

  // ---- tests ---------------------------------------------------------------------------------
  // O(1) test of Exercise 1: the subsegment h is encroached iff an apex on either side sees it at
  // 90 degrees or more.
  bool isEncroached(std::uint32_t h) const;
  void checkSubsegment(std::uint32_t h);

  // The half-edge for a queued edge: the remembered one if it still is that edge, else a search.
  // (The search alone is not enough: at a vertex where the domain touches itself, rotating around
  // the vertex cannot reach every triangle.)
  std::uint32_t edgeOf(const EdgeRef& e) const;

  TriangleQuality qualityAt(std::uint32_t s) const;

  // Slot s's area bound (<= 0: none): its region's or the global one, a size function's at its
  // centroid and, refining a mesh, the old mesh's, whichever is smallest. Inline for the common case
  // of neither of the last two: it is asked for every new triangle.
  double maxAreaAt(std::uint32_t s) const {
    if (!o_.sizeFunction && m_.oldMesh == nullptr) return m_.maxAreaOf(s);
    return maxAreaFromEverySource(s);
  }
  double maxAreaFromEverySource(std::uint32_t s) const;

  // Refining a mesh: the old mesh's bound for slot s (old_mesh.h), remembered with the corner
  // coordinates it was computed for (vertex ids would not do: Placement::Optimal moves vertices).
  double oldMeshBound(std::uint32_t s) const;

  // The one skinniness test everything uses: sin^2 of the smallest angle below sin^2 of the bound.
  bool isSkinny(const TriangleQuality& q) const { return theta_ > 0 && q.sin2MinAngle < sin2Theta_; }

  // Options::maxAngle: whether the triangle's largest angle exceeds it (the law of cosines at the
  // corner opposite the longest edge; no arctangent).
  bool isWide(const double* p0, const double* p1, const double* p2) const;

  void checkTriangle(std::uint32_t s);

  // Checked before every insertion, so that a budget of k inserts at most k vertices (0: none).
  // The loop also stops once k are in (outOfBudget), so any k > 0 gives the first k insertions of
  // the unbounded run.
  bool mayInsert();

  bool outOfBudget();
  // At the budget: with the automatic one, whether the refinement may go on (budget_ raised to the
  // next checkpoint); false to stop.
  bool extendBudget();
  std::string guardMessage(std::uint64_t unmet) const;

  // ---- forbidden splits (Triangle's -Y and -YY; what is done instead: refine_checks.cpp) ---------
  bool onDomainBoundary(std::uint32_t h) const;
  bool splitForbidden(std::uint32_t h) const;
  // What splitForbidden() keeps, in words, for the SegmentSplitForbidden reason.
  const char* forbiddenRule() const;

  // The fallback of a triangle whose point was refused (see above): between the point and the
  // triangle's centroid, the first of three points that lies in the domain on this side and
  // encroaches no subsegment. False if none does.
  bool placeAwayFromForbidden(const BadTriangle& bt, const double* const* p, const double* refused);

  // ---- exemptions (§6.6): the rules are exemptions.h's, shared with the output ------------------
  bool nestledInInputAngle(std::uint32_t s, const TriangleShape& sh) const {
    return detail::nestledInInputAngle(m_, s, sh);
  }
  bool seditious(std::uint32_t s, const TriangleShape& sh) const { return seditiousShortestEdge(m_, s, sh); }

  // ---- insertion ---------------------------------------------------------------------------------
  // Insert vertex v at `loc`; new triangles inherit region data and are checked; their
  // subsegments are checked for encroachment. False (nothing changed) if the insertion would
  // create an inverted triangle (rounding at the precision limit). `cavity`, if given, is the
  // cavity of v's point at `loc` as Triangulation::cavity computed it, with nothing changed since.
  bool insertAt(std::uint32_t v, const Location& loc, const CavityRef& cavity = {});

  // v's attributes from the edge or triangle it is about to be inserted in (point_attributes.h).
  void interpolateAttributes(std::uint32_t v, const Location& loc);

  // A vertex about to move to x: its attributes at x, from the triangle of its star that holds x.
  void reinterpolateMoved(std::uint32_t v, const double* x);

  // Triangles changed by flips (in flipped_): queue them if bad, and their edges and the edges
  // across them if encroached.
  void recheckFlipped();

  // The new triangles take their parents' region data. Two passes: a new triangle may reuse the
  // slot of another new triangle's parent.
  void inheritRegionData();
  bool regionDataCoversSlots();  // false: uniform region data; else the per-slot arrays cover every slot

  // A subsegment's split point is rounded, so it lies a hair off the subsegment's line. Bowyer-Watson
  // treats it as on the edge and joins it to the boundary of both sides' cavities; when it falls just
  // outside one side's triangle, a free edge there can end up not locally Delaunay (found by fuzzing,
  // tests/hostile/split-point-off-its-segment-broke-delaunay.poly: two segments meeting at 5e-8
  // radians, split into pieces a million times longer than that offset). Lawson flips around the
  // new triangles mend it; flip() keeps both slots, and the two triangles of a free edge share their
  // region, so the slots' region data stays right. Slots that changed and are not new are left in
  // flipped_ for re-checking.
  void mendDelaunay();

  // Where along subsegment a-b of length len it is split, as a fraction from a (§6.2, §6.6).
  double splitFraction(std::uint32_t a, std::uint32_t b, double len) const;
  // Where subsegment h from pa to pb is split (§6.2, §6.6), into xy; false if no point can be kept.
  bool subsegmentSplitPoint(std::uint32_t h, const double* pa, const double* pb, std::uint32_t a, std::uint32_t b,
                            double xy[2]) const;

  // Split subsegment h (§6.2, §6.6). `bt` and `rejected`: the triangle whose point was rejected
  // and that point, if that is why, for the trace. False if it cannot be split (precision floor).
  std::int32_t hullEdgeOf(std::uint32_t a, std::uint32_t b);
  bool splitSubsegment(std::uint32_t h, const BadTriangle* bt, const double* rejected);
  // Insert a vertex at `split`, on subsegment h or within rounding of it, with onSegment code
  // `segment`. Its id, or kNone if it cannot be placed (then counted as a precision-floor hit).
  std::uint32_t insertOnSubsegment(std::uint32_t h, const double* split, std::int32_t segment, const BadTriangle* bt,
                                   const double* rejected);
  void traceSplit(std::uint32_t v, std::uint32_t a, std::uint32_t b, const BadTriangle* bt, const double* rejected);

  // ---- curves (refine_curve.cpp; cdt/curves.h) ------------------------------------------------
  // Whether curve piece h must be split though nothing encroaches it: farther from its curve than
  // the tolerance, or not within its chord's diametral disk.
  [[gnu::noinline]] bool curvePieceTooCoarse(std::uint32_t h) const;
  // Vertex v's parameter on the curve of piece `segment` (one of its ends, or a split of it).
  double curveParam(std::uint32_t v, std::int32_t segment) const;
  // Split curve piece h at its curve's point (§6.2's midpoint, or a shell, in the parameter).
  [[gnu::noinline]] bool splitCurvePiece(std::uint32_t h, const BadTriangle* bt, const double* rejected);
  // The split point p lies off the chord u-w, on its left: insert it with the triangle (u, w, p)
  // between chord and curve, then hand that triangle to the chord's other side (or remove it where
  // there is none) so that u-p-w is the boundary. v: p's vertex, already added.
  bool insertBesideChord(std::uint32_t v, std::uint32_t u, std::uint32_t w, std::uint32_t hs, std::uint32_t ho);
  void moveBoundaryToCurve(std::uint32_t x, std::int32_t segment, std::uint32_t ho);
  // Copies slot `from`'s region data to slot `to`.
  void copyRegionData(std::uint32_t from, std::uint32_t to);

  // The first choice of point for a bad triangle: its circumcenter, or an off-center (for a skinny
  // one, or one only over its area bound overBound > 0). False: no point to trust.
  bool firstChoice(const double* const* p, const TriangleShape& sh, bool skinny, double overBound,
                   double target[2], VertexKind& kind) const;

  // A better point than the first choice from the configured placement, if it has one (placement.h).
  bool improvePlacement(const SkinnyTriangle& st, double target[2], Location& loc);

  void splitTriangle(const BadTriangle& bt);

  // ---- maxAngle (refine_wide.cpp) -----------------------------------------------------------------
  // A better point than the circumcenter for triangle bt, over maxAngle but not skinny: into target,
  // false if no candidate makes only triangles that meet both bounds.
  bool widePoint(const BadTriangle& bt, const double* const* p, int k, double target[2]);
  // Move the wide corner k, a free vertex, away from the midpoint of the edge it faces, by the
  // first of a few steps after which every triangle of its star meets both bounds. False: none does.
  bool pushWideCorner(const BadTriangle& bt, const double* const* p, int k);
  // Slide v, a vertex refinement placed on a segment, along it to where every triangle of its fan
  // meets both bounds (the largest smallest angle among those places). False: no such place.
  bool slideWideCorner(std::uint32_t v, const BadTriangle& bt);
  // sin^2 of the smallest angle a fix of a wide triangle may make (refine_wide.cpp).
  static constexpr double kSin2WideFloor = 0.11697777844051097;  // sin^2(20 degrees)
  double sin2WideFloor() const;
  // The corner with the largest angle (it faces the longest edge).
  static int wideCorner(const double* const* p);
  // The smallest sin^2 and the smallest cosine of the largest angle among the triangles inserting x
  // would make, if x fits (in the domain, destroying bt, encroaching nothing); false if it does not.
  bool wideCandidate(const BadTriangle& bt, const double* x, double& minSin2, double& maxCos);

  // Placement::Optimal (optimal_placement.h): insert the locally optimal point if one meets the bound,
  // else move a free endpoint of the shortest edge. False: neither; the first choice goes ahead.
  bool optimalOrRelocate(const BadTriangle& bt, const double* const* p, const TriangleShape& sh,
                         const double* first);
  // Insert x, the point OptimalPlacement just chose (propose's Found, or bestBelowBound), with the
  // cavity its check computed (OptimalPlacement::takeCandidate).
  void insertChosenPoint(const BadTriangle& bt, const double* x, const Location& loc);

  // Erten and Üngör's relocation: move v, a vertex refinement placed off every segment, to where
  // every triangle of its star meets the bound (OptimalPlacement::relocation), then restore the
  // Delaunay property by flips and re-check what changed. Each vertex moves at most
  // kMaxRelocations times and every move counts against the Steiner budget, so refinement still
  // ends. Traced as EventKind::Relocated (for bad triangle bt): a trace changes nothing, so that
  // the replay's step k is the run's.
  static constexpr std::uint8_t kMaxRelocations = 4;
  bool relocate(std::uint32_t v, const BadTriangle& bt);
  // Whether v may move once more (kMaxRelocations) within the Steiner budget.
  bool mayMove(std::uint32_t v);
  // With RefinePlan::slide: move v, a vertex refinement placed on a segment, along it to where every
  // triangle of its fan meets the bound (segment_slide.h); otherwise as relocate, whose count and
  // budget it shares.
  bool slideOnSegment(std::uint32_t v, const BadTriangle& bt);
  // After v moved from `from` to its new place: the trace, the count, and the Delaunay property
  // restored around the star (half-edges opposite v) by flips, with what changed re-checked.
  void afterMove(std::uint32_t v, const double* from, const BadTriangle& bt, const std::vector<std::uint32_t>& star);

  // Locate target for bad triangle bt. Where it lies beyond or on a subsegment, or encroaches one on
  // its cavity's boundary (§6.2, §6.3), it is rejected and those subsegments are split instead;
  // false then, and false at the precision limit. True: loc and cavityTris_ / cavityBoundary_ hold
  // its location and cavity.
  bool locateOrReject(const BadTriangle& bt, const double* target, Location& loc);

  // `placed`: the event's kind when a placement other than the first choice chose the point.
  void insertSteiner(const BadTriangle& bt, const double* target, const Location& loc, VertexKind kind,
                     const CavityRef& known, std::optional<EventKind> placed = std::nullopt);

  void reject(const BadTriangle& bt, std::uint32_t h, const double* target);
  bool collectEncroached(const double* target, bool splittableOnly);
  bool splitRejected(const BadTriangle& bt, const double* target);

  // The triangle survives a rejection unless the split destroyed it; keep it queued (§6.3).
  void requeue(const BadTriangle& bt) {
    if (isCurrent(t_, bt)) checkTriangle(bt.slot);
  }

  // ---- result ------------------------------------------------------------------------------------
  struct Unmet {
    std::uint64_t nestled = 0, sedition = 0, otherSkinny = 0, large = 0, wide = 0;
    double minSin2 = 1;  // over the triangles the bound applies to
  };
  Unmet countUnmet() const;

  std::string unreachableMessage(std::uint64_t unmet, double reached) const;

  void finish();
};

}  // namespace ruppert::detail
