// What a strategy around the refinement loop (the search above kSearchAboveDegrees, bound_search/)
// sees of it: the loop asks its control when the queues run dry and after every bad triangle's step,
// and tells it when it ends. The loop itself knows nothing of stages, caps or best meshes.
#pragma once

#include <cstdint>
#include <string>

namespace ruppert::detail {

class Refiner;

// One look at the whole mesh (Refiner::survey).
struct MeshScore {
  double minSin2 = 1;               // smallest sin^2 angle over triangles not exempt (§6.6)
  std::uint64_t belowRequested = 0; // non-exempt triangles below the requested bound
  std::uint64_t belowStage = 0;     // ... below the loop's current bound
  std::uint64_t large = 0;          // triangles over their area bound
  std::uint64_t triangles = 0;
  std::uint64_t domainTriangles = 0;  // those inside the domain (all but the box variant's outside)
};

class LoopControl {
 public:
  enum class Next { Done, GoOn, Stop };
  virtual ~LoopControl() = default;
  // The queues are empty: Done ends the loop; GoOn and Stop follow a raised bound
  // (Refiner::raiseBound), Stop when the control already knows the loop must end there.
  virtual Next queuesEmpty(Refiner& loop) = 0;
  // After a bad triangle's step: true to stop the loop.
  virtual bool stopAfterStep(Refiner& loop) = 0;
  // The loop ended, `stopped` short of an empty queue: the control may put an earlier mesh of the
  // run in place of the last (Refiner::returnEarlier).
  virtual void ended(Refiner& loop, bool stopped) = 0;
  // The reason's message where the control marked the result short of the requested bound.
  virtual std::string unreachableMessage(std::uint64_t unmet, double reached) const = 0;
};

}  // namespace ruppert::detail
