// The chapter's refinement loop (§6.2-6.8), class Refiner, one class in six files by concern:
//   refiner.cpp        the loop itself (run: encroached subsegments first, then bad triangles);
//   refine_checks.cpp  what is bad: encroached subsegments, skinny and large triangles (area bounds),
//                      the Steiner budget, forbidden splits, the exemptions of §6.6;
//   refine_split.cpp   what to do about it: split points of subsegments, the point for a bad
//                      triangle (placement), rejection of points that encroach;
//   refine_insert.cpp  inserting a vertex: cavity, region data, attributes, flips that mend;
//   refine_curve.cpp, refine_wide.cpp  curve pieces, and triangles over Options::maxAngle;
//   refine_result.cpp  why a mesh is incomplete (RefineOutcome::reasons).
// refine() (refine.cpp) runs the loop once, or above kSearchAboveDegrees through the bound search
// (bound_search/), a strategy that drives it through a LoopControl (loop_control.h).
// Terminology: see refiner.cpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesh/triangle_shape.h"
#include "mesh_state.h"
#include "refine/bad_triangle_queue.h"
#include "refine/exemptions.h"
#include "refine/loop_control.h"
#include "refine/placement/optimal_placement.h"
#include "refine/placement/placement.h"
#include "refine/placement/refine_geometry.h"
#include "refine/refine.h"
#include "refine/refine_plan.h"
#include "refine/refine_terms.h"

namespace ruppert::detail {

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
  double stageDegrees_;     // the loop's angle bound (plan_.first, unless a control raised it)
  double theta_;            // the same in radians
  double sin2Theta_;        // sin2Bound(theta_)
  const double cosMaxAngle_;  // cos(Options::maxAngle) less 1e-12 against rounding; -2: no bound
  MeshAccess mesh_;         // read-only queries for placements (and the walk)
  PetalPlacement petal_;
  OptimalPlacement optimal_;
  std::vector<std::uint8_t> relocations_;  // per vertex: how often it was moved (Placement::Optimal)
  LoopControl* control_;    // the strategy around the loop, or none
  bool unreachable_ = false;  // the control marked the result short of the requested bound
  std::uint64_t budget_ = 0, inserted_ = 0;
  // The automatic budget's checkpoints (nextGuardCheckpoint): whether this run has them, their base
  // allowance, and the size measure the last one estimated.
  bool guarded_ = false, guardStopped_ = false;
  double guardBase_ = 0, guardIntegral_ = 0;  // guardBase_: before the corners' term (measureCorners)
  std::uint64_t steps_ = 0;  // steps (insertions, moves) in the mesh run() returns
  bool cancelled_ = false, budgetHit_ = false, scratchReserved_ = false;
  std::uint64_t floorHits_ = 0, forbiddenHits_ = 0;  // refused at the precision limit; by splitForbidden()
  bool refusedSplit_ = false;        // the current bad triangle's point asked for a refused split
  std::vector<EdgeRef> encroached_;
  BadTriangleQueue bad_;
  // Per vertex: acute input corner (concentric shells apply), and the guard's allowance for them.
  // Measured when first needed, at the first split of a subsegment or guard checkpoint (a mesh that
  // needs neither, small or already fine, skips the arctangents); until then no split has moved a
  // constrained edge, so the measure is the one the loop started with.
  mutable std::vector<std::uint8_t> corner_;
  mutable double inverseGaps_ = 0;
  mutable bool cornersMeasured_ = false;
  void measureCorners() const;
  std::uint8_t cornerOf(std::uint32_t v) const {
    measureCorners();
    return corner_[v];
  }
  void cornerForNewVertex() {
    if (cornersMeasured_) corner_.push_back(0);
  }
  std::vector<std::uint32_t> newTris_, parents_, flipped_, mendStack_;
  std::vector<Inherited> inherit_;
  std::vector<std::uint32_t> cavityTris_, cavityBoundary_, splitTris_, splitBoundary_;
  std::vector<EdgeRef> rejectPairs_;
  std::vector<std::uint32_t> slideStar_;  // slideOnSegment's fan
  mutable std::vector<double> oldBound_, oldBoundAt_;  // oldMeshBound's memo: per slot, and 6 coordinates

 public:
  // `control`: the strategy around the loop; without one the loop keeps plan.first.
  Refiner(MeshState& m, const RefinePlan& plan, LoopControl* control = nullptr);

  // After run(): the steps that make the mesh returned, an earlier run's (plan_.used) included.
  std::uint64_t steps() const { return plan_.used + steps_; }
  RefineOutcome run();

  // ---- for the control (loop_control.h) -----------------------------------------------------------
  double bound() const { return stageDegrees_; }  // degrees
  // Sets the loop's bound and queues every triangle and subsegment it makes bad.
  void raiseBound(double degrees);
  std::uint64_t inserted() const { return inserted_; }
  std::uint64_t liveTriangles() const { return t_.slotCount() - t_.freeSlots.size(); }
  // The whole mesh against a requested bound (sin^2) and the loop's current one.
  MeshScore survey(double sin2Requested) const;
  const MeshState& mesh() const { return m_; }
  std::size_t eventCount() const { return out_.events.size(); }
  std::uint64_t rejectedCount() const { return out_.rejected; }
  bool budgetHit() const { return budgetHit_; }
  bool cancelled() const { return cancelled_; }
  // The result falls short of the requested bound (LoopControl::unreachableMessage says why).
  void markUnreachable() { unreachable_ = true; }
  // The result is an earlier state of this run: its mesh, steps, trace length and rejections.
  void returnEarlier(MeshState&& mesh, std::uint64_t steps, std::size_t events, std::uint64_t rejected);

 private:
  // Room for a typical cavity in every scratch list before the first step (none if none is made).
  void reserveScratch();
  void setBound(double degrees);
  void queueEverything();

  // ---- what is bad (refine_checks.cpp, which says why) ----------------------------------------
  bool isEncroached(std::uint32_t h) const;  // O(1), Exercise 1
  void checkSubsegment(std::uint32_t h);
  std::uint32_t edgeOf(const EdgeRef& e) const;  // the half-edge of a queued edge
  TriangleQuality qualityAt(std::uint32_t s) const;
  // Slot s's area bound (<= 0: none): its region's or the global one, a size function's at its
  // centroid and, refining a mesh, the old mesh's (oldMeshBound), whichever is smallest. Inline
  // for the common case of neither of the last two: it is asked for every new triangle.
  double maxAreaAt(std::uint32_t s) const {
    if (!o_.sizeFunction && m_.oldMesh == nullptr) return m_.maxAreaOf(s);
    return maxAreaFromEverySource(s);
  }
  double maxAreaFromEverySource(std::uint32_t s) const;
  double oldMeshBound(std::uint32_t s) const;
  // The one skinniness test everything uses: sin^2 of the smallest angle below sin^2 of the bound.
  bool isSkinny(const TriangleQuality& q) const { return theta_ > 0 && q.sin2MinAngle < sin2Theta_; }
  // Options::maxAngle: whether the triangle's largest angle exceeds it (law of cosines, no arctangent).
  bool isWide(const double* p0, const double* p1, const double* p2) const;
  void checkTriangle(std::uint32_t s);
  // The Steiner budget: mayInsert before every insertion, outOfBudget after every step; with the
  // automatic budget extendBudget decides at its checkpoints whether refinement may go on.
  bool mayInsert();
  bool outOfBudget();
  bool extendBudget();
  std::string guardMessage(std::uint64_t unmet) const;
  // Forbidden splits (Triangle's -Y and -YY), and what is done instead.
  bool onDomainBoundary(std::uint32_t h) const;
  bool splitForbidden(std::uint32_t h) const;
  const char* forbiddenRule() const;  // what splitForbidden() keeps, in words
  bool placeAwayFromForbidden(const BadTriangle& bt, const double* const* p, const double* refused);
  // The exemptions of §6.6: the rules are exemptions.h's, shared with the output.
  bool nestledInInputAngle(std::uint32_t s, const TriangleShape& sh) const {
    return detail::nestledInInputAngle(m_, s, sh);
  }
  bool seditious(std::uint32_t s, const TriangleShape& sh) const { return seditiousShortestEdge(m_, s, sh); }

  // ---- insertion (refine_insert.cpp) ----------------------------------------------------------
  // Insert vertex v at `loc` (with its cavity, if already computed); new triangles inherit region
  // data and are checked, and so are their subsegments. False (nothing changed): an inverted triangle.
  bool insertAt(std::uint32_t v, const Location& loc, const CavityRef& cavity = {});
  // v's attributes from the edge or triangle it is about to be inserted in (point_attributes.h).
  void interpolateAttributes(std::uint32_t v, const Location& loc);
  // A vertex about to move to x: its attributes at x, from the triangle of its star that holds x.
  void reinterpolateMoved(std::uint32_t v, const double* x);
  // Triangles changed by flips (in flipped_): queue them if bad, and their edges and the edges
  // across them if encroached.
  void recheckFlipped();
  // The new triangles take their parents' region data (two passes: a new triangle may reuse the
  // slot of another new triangle's parent).
  void inheritRegionData();
  bool regionDataCoversSlots();  // false: uniform region data; else the per-slot arrays cover every slot
  // Lawson flips around new triangles where a rounded split point left an edge not locally Delaunay.
  void mendDelaunay();

  // ---- splitting (refine_split.cpp) -----------------------------------------------------------
  // Where along subsegment a-b of length len it is split, as a fraction from a (§6.2, §6.6).
  double splitFraction(std::uint32_t a, std::uint32_t b, double len) const;
  bool subsegmentSplitPoint(std::uint32_t h, const double* pa, const double* pb, std::uint32_t a, std::uint32_t b,
                            double xy[2]) const;
  std::int32_t hullEdgeOf(std::uint32_t a, std::uint32_t b);
  // Split subsegment h; `bt` and `rejected`: the triangle and point that were rejected, if that is why.
  bool splitSubsegment(std::uint32_t h, const BadTriangle* bt, const double* rejected);
  std::uint32_t insertOnSubsegment(std::uint32_t h, const double* split, std::int32_t segment, const BadTriangle* bt,
                                   const double* rejected);
  void traceSplit(std::uint32_t v, std::uint32_t a, std::uint32_t b, const BadTriangle* bt, const double* rejected);
  // A bad triangle's point: the first choice (circumcenter or off-center), a better one from the
  // configured placement, located or rejected (§6.2, §6.3), inserted.
  bool firstChoice(const double* const* p, const TriangleShape& sh, bool skinny, double overBound,
                   double target[2], VertexKind& kind) const;
  bool improvePlacement(const SkinnyTriangle& st, double target[2], Location& loc);
  void splitTriangle(const BadTriangle& bt);
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

  // ---- Placement::Optimal's moves (refine_split.cpp; optimal_placement.h) ----------------------
  bool optimalOrRelocate(const BadTriangle& bt, const double* const* p, const TriangleShape& sh,
                         const double* first);
  // Insert x, the point OptimalPlacement just chose, with the cavity its check computed.
  void insertChosenPoint(const BadTriangle& bt, const double* x, const Location& loc);
  // Erten and Üngör's relocation: move v, a vertex refinement placed off every segment, to where
  // every triangle of its star meets the bound (OptimalPlacement::relocation), then restore the
  // Delaunay property by flips and re-check what changed. Each vertex moves at most
  // kMaxRelocations times and every move counts against the Steiner budget, so refinement still
  // ends. Traced as EventKind::Relocated (a trace changes nothing: the replay's step k is the run's).
  static constexpr std::uint8_t kMaxRelocations = 4;
  bool relocate(std::uint32_t v, const BadTriangle& bt);
  bool mayMove(std::uint32_t v);  // once more (kMaxRelocations) within the Steiner budget
  // With RefinePlan::slide: move v, a vertex refinement placed on a segment, along it to where every
  // triangle of its fan meets the bound (segment_slide.h); count and budget shared with relocate.
  bool slideOnSegment(std::uint32_t v, const BadTriangle& bt);
  // After v moved from `from`: the trace, the count, the Delaunay property restored around the star
  // (half-edges opposite v) by flips, and what changed re-checked.
  void afterMove(std::uint32_t v, const double* from, const BadTriangle& bt, const std::vector<std::uint32_t>& star);

  // ---- curves (refine_curve.cpp; cdt/curves.h) ------------------------------------------------
  // Whether curve piece h must be split though nothing encroaches it: farther from its curve than
  // the tolerance, or not within its chord's diametral disk.
  [[gnu::noinline]] bool curvePieceTooCoarse(std::uint32_t h) const;
  double curveParam(std::uint32_t v, std::int32_t segment) const;  // v's parameter on the piece's curve
  // Split curve piece h at its curve's point (§6.2's midpoint, or a shell, in the parameter).
  [[gnu::noinline]] bool splitCurvePiece(std::uint32_t h, const BadTriangle* bt, const double* rejected);
  // Insert v, off the chord u-w on its left, with the triangle (u, w, v) between chord and curve,
  // and hand that triangle to the chord's other side (or remove it) so that u-v-w is the boundary.
  bool insertBesideChord(std::uint32_t v, std::uint32_t u, std::uint32_t w, std::uint32_t hs, std::uint32_t ho);
  void moveBoundaryToCurve(std::uint32_t x, std::int32_t segment, std::uint32_t ho);
  void copyRegionData(std::uint32_t from, std::uint32_t to);  // slot `from`'s to slot `to`

  // ---- maxAngle (refine_wide.cpp) -------------------------------------------------------------
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
  static int wideCorner(const double* const* p);  // the corner with the largest angle
  // The smallest sin^2 and the smallest cosine of the largest angle among the triangles inserting x
  // would make, if x fits (in the domain, destroying bt, encroaching nothing); false if it does not.
  bool wideCandidate(const BadTriangle& bt, const double* x, double& minSin2, double& maxCos);

  // ---- result (refine_result.cpp) -------------------------------------------------------------
  struct Unmet {
    std::uint64_t nestled = 0, sedition = 0, otherSkinny = 0, large = 0, wide = 0;
    double minSin2 = 1;  // over the triangles the bound applies to
  };
  // Every triangle once: what stays unmet, and the angle statistics.
  Unmet countUnmet(AngleStats& angles) const;
  void finish();
};

}  // namespace ruppert::detail
