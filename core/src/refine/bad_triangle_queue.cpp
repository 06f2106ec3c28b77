#include "refine/bad_triangle_queue.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <utility>

namespace ruppert::detail {

namespace {

// The buckets of the last queue this thread destroyed, emptied but with their capacity, for the
// next one: a small mesh otherwise spends a tenth of its allocations growing the few buckets it
// uses from empty, one doubling at a time, on every call. Kept only while they are small.
// Outside [keptLow, keptHigh] every kept bucket has no capacity, so a queue clears and measures
// only the classes that were ever used, not all 337 (which was a tenth of a one-triangle call).
constexpr std::size_t kKeptEntries = std::size_t(1) << 16;
thread_local std::vector<std::vector<BadTriangle>> keptBuckets;
thread_local int keptLow = 0, keptHigh = -1;

}  // namespace

BadTriangleQueue::BadTriangleQueue() {
  if (keptBuckets.size() == std::size_t(kBuckets)) {
    buckets_.swap(keptBuckets);
    usedLow_ = keptLow, usedHigh_ = keptHigh;
  } else {
    buckets_.resize(kBuckets);
  }
}

BadTriangleQueue::~BadTriangleQueue() {
  if (buckets_.size() != std::size_t(kBuckets) || !keptBuckets.empty()) return;
  std::size_t entries = 0;
  for (int k = usedLow_; k <= usedHigh_; ++k) buckets_[k].clear(), entries += buckets_[k].capacity();
  if (entries > kKeptEntries) return;
  keptBuckets.swap(buckets_);
  keptLow = usedLow_, keptHigh = usedHigh_;
}

int BadTriangleQueue::classOf(double shortest2) {
  // shortest2 = mantissa * 2^e, mantissa in [0.5, 1): read off the bits of a positive normal number
  // (what frexp returns, without a library call per new triangle), else from frexp.
  int e = 0;
  double mantissa;
  if (shortest2 >= DBL_MIN && shortest2 <= DBL_MAX) {
    std::uint64_t bits;
    std::memcpy(&bits, &shortest2, sizeof bits);
    e = static_cast<int>(bits >> 52) - 1022;
    bits = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1022) << 52);
    std::memcpy(&mantissa, &bits, sizeof bits);
  } else {
    mantissa = std::frexp(shortest2, &e);
  }
  // Four classes per power of two (of the squared length): cuts at 2^-0.75, 2^-0.5, 2^-0.25.
  const int quarter = (mantissa >= 0.5946035575013605) + (mantissa >= 0.7071067811865476) +
                      (mantissa >= 0.8408964152537145);
  return std::clamp(4 * (e - kLowestExponent) + quarter, 0, kBuckets - 1);
}

int BadTriangleQueue::sizeClassOf(double area) {
  const double k = std::floor((std::log2(area) - kLowestAreaExponent) * kSizeClassesPerOctave);
  return static_cast<int>(std::clamp(k, 0.0, double(kSizeBuckets - 1)));
}

void BadTriangleQueue::push(const Triangulation& t, std::uint32_t s, bool skinny, double key, double sin2MinAngle) {
  const auto angleClass =
      static_cast<std::uint8_t>(std::min<double>(kAngleClasses - 1, sin2MinAngle / 0.75 * (kAngleClasses - 1)));
  mesh_ = &t;
  const TriangleSlot& r = t.slot(s);
  const BadTriangle e{s, r.tv[0], r.tv[1], r.tv[2], skinny ? 0 : planeKey(t, r.tv[0]), angleClass};
  ++queuedByAngle_[angleClass];
  if (skinny) {
    const int k = classOf(key);
    buckets_[k].push_back(e);
    usedLow_ = std::min(usedLow_, k), usedHigh_ = std::max(usedHigh_, k);
    lowestBucket_ = std::min(lowestBucket_, k);
    highestSkinny_ = std::max(highestSkinny_, k);
  } else {
    if (sizeBuckets_.empty()) sizeBuckets_.resize(kSizeBuckets);
    const int k = sizeClassOf(key);
    sizeBuckets_[k].push_back(e);
    highestSize_ = std::max(highestSize_, k);
  }
  if (++queued_ > compactAt_) dropStaleEntries(t);
}

// Where refinement runs away, each step can rebuild a fan of thousands of needles, and the entries
// of the ones it replaced stay queued: 70 million entries for 4 million triangles (300 chords
// crossing in a star at 30 degrees, before off-centers aimed past the bound). Dropping the stale
// ones (pop would hand them out to be skipped anyway; the order of the rest is kept, so meshes do
// not change) keeps memory proportional to the mesh.
void BadTriangleQueue::dropStaleEntries(const Triangulation& t) {
  queued_ = 0;
  for (auto* classes : {&buckets_, &sizeBuckets_}) {
    for (auto& b : *classes) {
      b.erase(std::remove_if(b.begin(), b.end(),
                             [&](const BadTriangle& e) {
                               if (isCurrent(t, e)) return false;
                               --queuedByAngle_[e.angleClass];
                               return true;
                             }),
              b.end());
      queued_ += b.size();
    }
  }
  compactAt_ = 2 * std::max<std::uint64_t>(queued_, t.slotCount()) + (1u << 16);
}

bool BadTriangleQueue::take(std::vector<BadTriangle>& bucket, BadTriangle& out) {
  if (bucket.empty()) return false;
  out = bucket.back();
  bucket.pop_back();
  --queued_;
  --queuedByAngle_[out.angleClass];
  if (mesh_) prefetchAhead(bucket);
  return true;
}

// The next entries are split after this one's insertion, each after the one before; their cavities
// are their triangles and the neighbors around them. Three steps, an insertion apart, each reading
// what the step before asked for: the third entry's record, then the second's corners and
// neighbors' records, then the next one's neighbors' apices. Their cache misses then overlap the
// insertions instead of stalling the cavity search.
void BadTriangleQueue::prefetchAhead(const std::vector<BadTriangle>& bucket) const {
  const Triangulation& t = *mesh_;
  const std::size_t n = bucket.size();
  if (n >= 3) prefetch(&t.slot(bucket[n - 3].slot));
  if (n >= 2) {
    const TriangleSlot& r = t.slot(bucket[n - 2].slot);
    for (std::uint32_t i = 0; i < 3 && r.tv[0] != kNone; ++i) {
      prefetch(t.pt(r.tv[i]));
      if (r.twin[i] != kNone) prefetch(&t.slot(r.twin[i] / 3));
    }
  }
  if (n >= 1) {
    const TriangleSlot& r = t.slot(bucket[n - 1].slot);
    for (std::uint32_t i = 0; i < 3 && r.tv[0] != kNone; ++i) {
      if (r.twin[i] == kNone) continue;
      const TriangleSlot& beyond = t.slot(r.twin[i] / 3);
      if (beyond.tv[0] != kNone) prefetch(t.pt(beyond.tv[r.twin[i] % 3]));
    }
  }
}

bool BadTriangleQueue::pop(BadTriangle& out) {
  if (largestFirst_) {
    for (; highestSkinny_ >= 0; --highestSkinny_)
      if (take(buckets_[highestSkinny_], out)) return true;
    lowestBucket_ = kBuckets;  // no skinny class holds an entry
  }
  for (; lowestBucket_ < kBuckets; ++lowestBucket_)
    if (take(buckets_[lowestBucket_], out)) return true;
  for (; highestSize_ >= 0; --highestSize_) {
    if (highestSize_ < sortedSizeClass_ && !sizeBuckets_[highestSize_].empty()) {
      sortInPlaneOrder(sizeBuckets_[highestSize_]);
      sortedSizeClass_ = highestSize_;
    }
    if (take(sizeBuckets_[highestSize_], out)) return true;
  }
  return false;
}

namespace {

// Position along a Hilbert curve through a 2^16 x 2^16 grid. Digit by digit from the top, each
// quadrant's digit depends on the orientation the levels above left (swapped axes, mirrored axes:
// four states); a table steps four levels at once (a nibble of x and of y), four steps per key.
class HilbertCurve {
 public:
  HilbertCurve() {
    for (std::uint32_t state = 0; state < 4; ++state)
      for (std::uint32_t nibbles = 0; nibbles < 256; ++nibbles) {
        std::uint32_t s = state, digits = 0;
        for (int level = 3; level >= 0; --level) {
          std::uint32_t rx = (nibbles >> (4 + level)) & 1, ry = (nibbles >> level) & 1;
          if (s & 1) std::swap(rx, ry);
          if (s & 2) rx ^= 1, ry ^= 1;
          digits = digits << 2 | ((3 * rx) ^ ry);
          if (ry == 0) s ^= 1 | (rx << 1);  // a quarter turn, mirrored in the far quadrant
        }
        step_[state << 8 | nibbles] = static_cast<std::uint16_t>(digits << 2 | s);
      }
  }
  std::uint32_t index(std::uint32_t x, std::uint32_t y) const {
    std::uint32_t d = 0, state = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
      const std::uint32_t e = step_[state << 8 | ((x >> shift) & 15) << 4 | ((y >> shift) & 15)];
      d = d << 8 | e >> 2, state = e & 3;
    }
    return d;
  }

 private:
  std::uint16_t step_[4 * 256];
};

// A mesh of fewer slots than this fits in the cache: it gains nothing from plane order and pays
// for the keys and sorts, so it keeps the order of pushes (and so its exact mesh).
constexpr std::uint32_t kCachedSlots = 1u << 17;  // 5 MB of slot records

}  // namespace

// Computed at the push, while the triangle's corners are in the cache (a sort reading them back
// would miss on nearly every one).
std::uint32_t BadTriangleQueue::planeKey(const Triangulation& t, std::uint32_t a) {
  if (t.slotCount() < kCachedSlots / 2) return 0;
  if (frameScale_ == 0) {
    double hi[2] = {-HUGE_VAL, -HUGE_VAL};
    frameLow_[0] = frameLow_[1] = HUGE_VAL;
    for (std::size_t k = 0; k < t.xy.size(); ++k)
      frameLow_[k % 2] = std::min(frameLow_[k % 2], t.xy[k]), hi[k % 2] = std::max(hi[k % 2], t.xy[k]);
    frameScale_ = 65535 / std::max({hi[0] - frameLow_[0], hi[1] - frameLow_[1], 1e-300});
  }
  const double* p = t.pt(a);
  const double x = std::clamp((p[0] - frameLow_[0]) * frameScale_, 0.0, 65535.0);
  const double y = std::clamp((p[1] - frameLow_[1]) * frameScale_, 0.0, 65535.0);
  static const HilbertCurve curve;
  return curve.index(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
}

// A size class is taken in the order of a Hilbert curve through the triangles' first corners, so
// that consecutive splits touch neighboring triangles and vertices, which a mesh larger than the
// cache then finds there, instead of hopping across the plane. The class still decides the order.
// A radix sort on the keys, least significant byte first (each pass stable).
void BadTriangleQueue::sortInPlaneOrder(std::vector<BadTriangle>& bucket) {
  if (frameScale_ == 0 || bucket.size() < 64) return;
  sortBuffer_.resize(bucket.size());
  for (int shift = 0; shift < 32; shift += 8) {
    std::size_t start[257] = {};
    for (const BadTriangle& e : bucket) ++start[((e.planeKey >> shift) & 0xFF) + 1];
    if (start[1] == bucket.size()) continue;  // one value of this byte throughout
    for (int b = 0; b < 256; ++b) start[b + 1] += start[b];
    for (const BadTriangle& e : bucket) sortBuffer_[start[(e.planeKey >> shift) & 0xFF]++] = e;
    bucket.swap(sortBuffer_);
  }
}

double BadTriangleQueue::worstQueuedAngle(double fallback) const {
  for (int c = 0; c < kAngleClasses; ++c)
    if (queuedByAngle_[c]) return std::asin(std::sqrt(0.75 * c / (kAngleClasses - 1))) * 180 / 3.14159265358979323846;
  return fallback;
}

}  // namespace ruppert::detail
