// operator new and delete for the WebAssembly modules: blocks up to 64 KB come from free lists of
// power-of-two sizes, refilled from malloc, so that a call's many short-lived vectors (about 64
// allocations for a single triangle: the mesh's arrays, the refiner's scratch, the output) cost a
// list push and pop instead of a trip through emmalloc each. Larger blocks go to malloc.
//
// Why here and not in the core: natively glibc's per-thread caches do this already; emmalloc has no
// such cache, and its allocate and free are a visible share of a small call's time in Node
// (docs/measurements.md). Each list keeps at most keepLimit(c) blocks (64, and no more than 64 KB),
// so that after a large mesh the lists hold under 13 x 64 KB.
// Single-threaded, as the modules are.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

// Every block starts kHeader bytes after its malloc'd address, which holds its class (or kLarge), so
// that the pointer keeps malloc's 16-byte alignment.
constexpr std::size_t kHeader = 16;
constexpr std::size_t kSmallest = 16;
constexpr int kClasses = 13;  // 16 B .. 64 KB
constexpr std::size_t kLargest = kSmallest << (kClasses - 1);
constexpr std::int32_t kLarge = -1;
constexpr std::size_t kKeep = 64;
constexpr std::size_t kKeepBytes = 64 * 1024;

struct FreeBlock {
  FreeBlock* next;
};

FreeBlock* freeLists[kClasses];
std::size_t freeCounts[kClasses];

// How many freed blocks of class c its list keeps.
constexpr std::size_t keepLimit(int c) {
  return kKeepBytes / (kSmallest << c) < kKeep ? kKeepBytes / (kSmallest << c) : kKeep;
}

int classOf(std::size_t n) {
  if (n <= kSmallest) return 0;
  // ceil(log2(n)) - log2(kSmallest)
  return static_cast<int>(sizeof(unsigned long) * 8) - __builtin_clzl(static_cast<unsigned long>(n - 1)) - 4;
}

void* fromMalloc(std::size_t bytes, std::int32_t tag) {
  if (bytes > SIZE_MAX - kHeader) return nullptr;  // the header would wrap the size round
  char* p = static_cast<char*>(std::malloc(kHeader + bytes));
  if (p == nullptr) return nullptr;
  *reinterpret_cast<std::int32_t*>(p) = tag;
  return p + kHeader;
}

void* allocate(std::size_t n) {
  if (n > kLargest) return fromMalloc(n, kLarge);
  const int c = classOf(n);
  if (FreeBlock* b = freeLists[c]) {
    freeLists[c] = b->next;
    --freeCounts[c];
    return b;
  }
  return fromMalloc(kSmallest << c, c);
}

void release(void* p) {
  if (p == nullptr) return;
  char* start = static_cast<char*>(p) - kHeader;
  const std::int32_t c = *reinterpret_cast<std::int32_t*>(start);
  if (c != kLarge && freeCounts[c] < keepLimit(c)) {
    FreeBlock* b = static_cast<FreeBlock*>(p);
    b->next = freeLists[c];
    freeLists[c] = b;
    ++freeCounts[c];
    return;
  }
  std::free(start);
}

}  // namespace

void* operator new(std::size_t n) {
  if (void* p = allocate(n)) return p;
  throw std::bad_alloc();  // the binding turns it into a TOO_LARGE error
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocate(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
