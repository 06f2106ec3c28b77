// The queue of bad triangles (§6.3): triangles too skinny or too large, waiting to be split.
// Lazily invalidated: an entry remembers the triangle's vertices, and one whose slot has since
// changed is stale and skipped.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/triangulation.h"

namespace ruppert::detail {

struct BadTriangle {
  std::uint32_t slot, a, b, c;
  std::uint32_t planeKey;   // position of corner a along a Hilbert curve (0 in a small mesh)
  std::uint8_t angleClass;  // sin^2 of the smallest angle in BadTriangleQueue::kAngleClasses steps
};

// Whether a queued entry still describes the triangle in its slot.
inline bool isCurrent(const Triangulation& t, const BadTriangle& e) {
  const TriangleSlot& r = t.slot(e.slot);  // (a free slot's corners are kNone)
  return r.tv[0] == e.a && r.tv[1] == e.b && r.tv[2] == e.c;
}

// Order: skinny triangles with the shortest shortest-edge first, too-large but shapely ones last
// and the largest of those first, last in, first out within a class. Fixing the smallest features first lets the mesh grade
// outwards from them; splitting the skinniest first (measured on the 61 shared PLCs) spreads small
// triangles far from any feature: 1.33x Triangle's count at 33 degrees against 0.99x with this order.
// Priority classes, not a binary heap (§6.3): four per power of two of the squared shortest edge.
// The reverse order (setLargestFirst) is for bounds above 34 degrees, where grading outwards from
// the small features leaves them inside cavities of much larger triangles that no point can please
// (bound_push.h).
// Largest first among the too-large: a triangle split at its circumcenter leaves pieces of about a
// third of its area, so splitting the largest first lets every piece end between a third of the
// bound and the bound, where last in, first out splits small neighbors of a fresh large piece
// again. Measured with max area = bounding box / 3000 on the 300 generated PLCs against Triangle
// (tests/bench/results/area-bound.md): 0.981x -> 0.952x its triangles at 30 degrees, 0.926x ->
// 0.906x at 33; a unit square at max area 1e-6 becomes the 2^20 right triangles of a grid.
class BadTriangleQueue {
 public:
  static constexpr int kAngleClasses = 64;  // queued triangles counted by smallest angle, for progress

  BadTriangleQueue();
  ~BadTriangleQueue();
  BadTriangleQueue(const BadTriangleQueue&) = default;
  BadTriangleQueue& operator=(const BadTriangleQueue&) = default;
  BadTriangleQueue(BadTriangleQueue&&) = default;
  BadTriangleQueue& operator=(BadTriangleQueue&&) = default;

  // Queue the triangle in slot s of t. skinny: queued by its squared shortest edge, `key`;
  // otherwise (too large only) by its area, `key`, after every skinny one.
  void push(const Triangulation& t, std::uint32_t s, bool skinny, double key, double sin2MinAngle);
  // The next entry, stale or not; false when the queue is empty.
  bool pop(BadTriangle& out);
  // Pop the skinny triangles with the longest shortest edge first instead (too-large ones still last).
  void setLargestFirst(bool on) { largestFirst_ = on; }
  // The smallest angle among queued triangles (entries whose triangle has changed since included),
  // to within 60 / (kAngleClasses - 1) degrees, in degrees; `fallback` when none is queued.
  double worstQueuedAngle(double fallback) const;

 private:
  // The skinny classes: from 2^-80 (below refinement's length floor) to 2^4 (above the scaled
  // input's extent), four per power of two of the squared shortest edge.
  static constexpr int kLowestExponent = -80;
  static constexpr int kBuckets = 4 * (4 - kLowestExponent);
  // The size classes, sixteen per power of two of the area, from 2^-170 to 2^10; made on the first
  // too-large triangle (a call without an area bound never pays for them).
  static constexpr int kLowestAreaExponent = -170;
  static constexpr int kSizeClassesPerOctave = 16;
  static constexpr int kSizeBuckets = kSizeClassesPerOctave * (10 - kLowestAreaExponent);

  std::vector<std::vector<BadTriangle>> buckets_;
  std::vector<std::vector<BadTriangle>> sizeBuckets_;
  int highestSize_ = -1;  // no size class above this one holds an entry
  int lowestBucket_ = kBuckets;  // no class below this one holds an entry
  int highestSkinny_ = -1;       // no skinny class above this one holds an entry
  int usedLow_ = kBuckets, usedHigh_ = -1;  // no bucket outside these has capacity
  bool largestFirst_ = false;
  const Triangulation* mesh_ = nullptr;  // the mesh of the last push, for prefetching the next entry
  std::uint64_t queuedByAngle_[kAngleClasses] = {};
  std::uint64_t queued_ = 0, compactAt_ = 1u << 20;  // entries in buckets_; when to drop stale ones

  // Plane order (sortInPlaneOrder): size classes at or above sortedSizeClass_ were sorted; the
  // Hilbert curve's frame, around the vertices when the mesh first grew large enough for plane
  // order (the domain's extent: later vertices lie within it), unset while frameScale_ is 0.
  int sortedSizeClass_ = kSizeBuckets;
  double frameLow_[2] = {0, 0}, frameScale_ = 0;
  std::vector<BadTriangle> sortBuffer_;
  static int classOf(double shortest2);
  std::uint32_t planeKey(const Triangulation& t, std::uint32_t a);
  void sortInPlaneOrder(std::vector<BadTriangle>& bucket);
  static int sizeClassOf(double area);
  bool take(std::vector<BadTriangle>& bucket, BadTriangle& out);
  void prefetchAhead(const std::vector<BadTriangle>& bucket) const;
  void dropStaleEntries(const Triangulation& t);
};

}  // namespace ruppert::detail
