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
  return true;
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

// Position along a Hilbert curve through a 2^16 x 2^16 grid.
std::uint32_t hilbertIndex(std::uint32_t x, std::uint32_t y) {
  constexpr std::uint32_t n = 1u << 16;
  std::uint32_t d = 0;
  for (std::uint32_t s = n / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) x = n - 1 - x, y = n - 1 - y;
      std::swap(x, y);
    }
  }
  return d;
}

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
  return hilbertIndex(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
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
