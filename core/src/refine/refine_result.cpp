// Refiner (refiner.h): the result. What stays unmet when refinement ends, and why, as
// RefineOutcome::reasons.
#include "refine/refiner.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "cold_code.h"
#include "decimal_text.h"
#include "refine/refine_setup.h"

// Runs once per refinement: compiled for size (cold_code.h).
RUPPERT_COLD_BEGIN

namespace ruppert::detail {

Refiner::Unmet Refiner::countUnmet(AngleStats& angles) const {
  Unmet u;
  for (std::uint32_t s = 0; s < t_.slotCount(); ++s) {
    t_.prefetchCorners(s + Triangulation::kScanAhead);
    if (!t_.alive(s)) continue;
    const TriangleQuality q = qualityAt(s);
    const double bound = maxAreaAt(s);
    if (bound > 0 && q.area > bound * (1 + 1e-9)) ++u.large;
    const double* p[3] = {t_.pt(t_.tv[3 * s]), t_.pt(t_.tv[3 * s + 1]), t_.pt(t_.tv[3 * s + 2])};
    angles.add(p[0], p[1], p[2]);
    const bool skinny = isSkinny(q);
    if (!skinny) u.minSin2 = std::min(u.minSin2, q.sin2MinAngle);
    if (!skinny && !isWide(p[0], p[1], p[2])) continue;
    const TriangleShape sh = shapeOf(p[0], p[1], p[2]);
    if (nestledInInputAngle(s, sh)) ++u.nestled;
    else if (seditious(s, sh)) ++u.sedition;
    else if (skinny) ++u.otherSkinny, u.minSin2 = std::min(u.minSin2, q.sin2MinAngle);
    else ++u.wide;
  }
  return u;
}

std::string Refiner::guardMessage(std::uint64_t unmet) const {
  const std::string measure = formatSignificant(guardIntegral_, 4);
  return "refinement stopped after " + std::to_string(plan_.used + inserted_) +
         " steps, more than the automatic budget, " + std::to_string(int(kGuardStepsPerInverseRadian)) +
         " per inverse radian of the input's acute corners and " + std::to_string(int(kGuardStepsPerLfsUnit)) +
         " per unit of the size measure (the integral of 1/lfs^2 over the domain, " + measure +
         ", section 6.5): it is not converging; " + std::to_string(unmet) +
         " triangle(s) do not meet the bounds (maxSteiner sets a budget instead)";
}

void Refiner::finish() {
  if (stageDegrees_ != plan_.requested) setBound(plan_.requested);  // judge by the bound asked for
  AngleStats angles;
  const Unmet u = countUnmet(angles);
  out_.angles = std::move(angles);
  out_.reachedAngle = std::asin(std::sqrt(u.minSin2)) * 180 / kPi;
  auto add = [&](ReasonKind k, std::uint64_t n, const std::string& msg) {
    out_.reasons.push_back(Reason{k, n, msg});
  };
  const std::uint64_t unmet = u.otherSkinny + u.large + u.wide;
  if (cancelled_)
    add(ReasonKind::Cancelled, unmet, "refinement was cancelled; " + std::to_string(unmet) +
                                          " triangle(s) do not meet the bounds");
  else if (unreachable_) {
    // A push whose best mesh meets the requested bound after all (its triangles below it all
    // exempt, §6.6) stopped on what came after that mesh, say an encroached subsegment whose splits
    // ran into the precision floor: the mesh returned is complete (a single triangle in a
    // 0.86-degree input angle, 1e6 from the origin, with an area bound, was marked unreachable).
    if (unmet > 0) add(ReasonKind::AngleUnreachable, unmet, control_->unreachableMessage(unmet, out_.reachedAngle));
  } else if (budgetHit_ && guardStopped_)
    add(ReasonKind::SteinerBudget, unmet, guardMessage(unmet));
  else if (budgetHit_)
    add(ReasonKind::SteinerBudget, unmet, "the Steiner budget of " + std::to_string(budget_ + plan_.used) +
                                              " vertices was reached; " + std::to_string(unmet) +
                                              " triangle(s) do not meet the bounds");
  else if (unmet > 0 && forbiddenHits_ > 0)
    add(ReasonKind::SegmentSplitForbidden, unmet,
        std::to_string(unmet) + " triangle(s) do not meet the bounds: " + std::to_string(forbiddenHits_) +
            " split(s) of subsegments were refused because " + forbiddenRule() +
            " (no-segment-steiner / no-boundary-steiner), and the vertices that would have caused them were not inserted");
  // Refused insertions that leave every bound met (a split of an encroached subsegment that no
  // bad triangle waits on) leave nothing unmet: the mesh is complete.
  else if (unmet > 0)
    add(ReasonKind::PrecisionFloor, unmet,
        std::to_string(unmet) + " triangle(s) could not be improved: " + std::to_string(floorHits_) +
            " insertion(s) were refused because the new vertex would be closer than double precision can "
            "resolve, or its coordinates would leave what exact arithmetic or the output's numbers can hold, "
            "or its cavity would wrap around a vertex where the domain touches itself");
  if (u.nestled)
    add(ReasonKind::SmallInputAngle, u.nestled, std::to_string(u.nestled) +
        " triangle(s) sit in input angles smaller than the bound (or are wider than maxAngle there); no vertex "
        "can fix them (section 6.6)");
  if (u.sedition)
    add(ReasonKind::SeditiousEdge, u.sedition, std::to_string(u.sedition) +
        " triangle(s) have a seditious shortest edge between segments meeting at under 45 degrees; "
        "left alone so refinement terminates (section 6.6)");
}

}  // namespace ruppert::detail

RUPPERT_COLD_END
