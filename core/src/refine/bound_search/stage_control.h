// The bound search's control of one run of the refinement loop (loop_control.h): a cap on the
// mesh's triangles and, for the push, the stages (the bound raised a degree at a time from the
// 33-degree mesh), the scores, and the best mesh seen, which is the result where the push stops.
#pragma once

#include <cstdint>
#include <string>

#include "mesh_state.h"
#include "refine/bound_search/bound_push.h"
#include "refine/loop_control.h"

namespace ruppert::detail {

struct StageRules {
  bool track = false;  // push: raise the bound stage by stage, keep the best mesh, stop on a stall
  std::uint64_t triangleCap = 0;  // stop once the mesh has more triangles (0: no cap)
  // The push's promise (ruppert.h: never over four times the 33-degree mesh's triangles), counted
  // in the domain only: the bounding-box variant's triangles outside it, which triangleCap counts
  // too, leave the mesh. A scored mesh over it is never the result, and the push stops (0: none).
  std::uint64_t domainCap = 0;
  // Replaying the first steps of a longer run (bound_search.cpp): at the Steiner budget the mesh as
  // it stands, not the push's best mesh so far.
  bool prefix = false;
};

class StageControl final : public LoopControl {
 public:
  // `requested`: the bound asked for (degrees); the loop starts at its plan's first bound.
  StageControl(const Options& o, double requested, const StageRules& rules);

  Next queuesEmpty(Refiner& loop) override;
  bool stopAfterStep(Refiner& loop) override;
  void ended(Refiner& loop, bool stopped) override;
  std::string unreachableMessage(std::uint64_t unmet, double reached) const override;

  // After the run: whether it stopped at a cap.
  bool capHit() const { return capHit_; }

 private:
  bool overCap(const Refiner& loop);
  void observe(const Refiner& loop);
  bool pushStopped(const Refiner& loop);

  const Options& o_;
  const double requested_;
  const double sin2Requested_;
  const StageRules rules_;
  PushTracker push_;
  std::uint64_t nextScoreAt_ = 0;  // when the push next scores the mesh
  bool pushing_ = false;           // past the first stage
  bool capHit_ = false;            // stopped at rules_.triangleCap or rules_.domainCap
  bool overDomainCap_ = false;     // a score found more domain triangles than rules_.domainCap
  const char* pushStop_ = "";      // why the push stopped, for the reason's message
  // The push's best mesh so far, with the trace length and rejection count it had.
  struct Snapshot {
    MeshState mesh;
    std::size_t events = 0;
    std::uint64_t rejected = 0;
  } best_;
};

}  // namespace ruppert::detail
