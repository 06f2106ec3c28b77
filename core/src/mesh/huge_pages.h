// Transparent huge pages for the large arrays. A first touch of a 4 KB page costs a fault; on a
// virtual machine the 67,000 faults of a CDT of 10^6 points take about half its CPU time.
// Asked for (MADV_HUGEPAGE), Linux backs each aligned 2 MB of an array with one page instead of 512:
// the same memory in a few thousand faults, and fewer TLB misses while the mesh is walked. Where
// the system never uses huge pages, or outside Linux (WebAssembly included), the advice is a no-op.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sys/mman.h>
#endif

namespace ruppert::detail {

inline void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && !defined(__EMSCRIPTEN__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  if (bytes < 2 * kHuge) return;  // (smaller arrays gain little and would round up to 2 MB)
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)data, (void)bytes;
#endif
}

// Hands the whole pages within [data, data + bytes) back to the system (they read as zeros if
// touched again): memory a vector keeps as capacity but will not use.
inline void releasePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && !defined(__EMSCRIPTEN__) && defined(MADV_DONTNEED)
  constexpr std::uintptr_t kPage = 4096;
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
#else
  (void)data, (void)bytes;
#endif
}

// v.reserve(n), the new storage advised before anything touches it.
template <class Vector>
void reserveHuge(Vector& v, std::size_t n) {
  v.reserve(n);
  adviseHugePages(v.data(), v.capacity() * sizeof(*v.data()));
}

}  // namespace ruppert::detail
