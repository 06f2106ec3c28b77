// The bad-triangle queue's two orders (bad_triangle_queue.h): smallest shortest edge first, as
// refinement always does up to 34 degrees, and largest first, for the direct attempts above it
// (bound_push.h). Too-large triangles come last either way, the largest area first; within a class,
// last in first out.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "refine/bad_triangle_queue.h"
#include "mesh/triangulation.h"

using ruppert::detail::BadTriangle;
using ruppert::detail::BadTriangleQueue;
using ruppert::detail::Triangulation;

namespace {

// Slots 0..n-1, each with vertices (3s, 3s+1, 3s+2): enough for the queue, which only reads tv.
Triangulation slots(std::uint32_t n) {
  Triangulation t;
  t.vtri.assign(3 * std::size_t(n), ruppert::detail::kNone);
  for (std::uint32_t i = 0; i < n; ++i) t.newTriangle(3 * i, 3 * i + 1, 3 * i + 2);
  return t;
}

std::vector<std::uint32_t> drain(BadTriangleQueue& q) {
  std::vector<std::uint32_t> order;
  BadTriangle b;
  while (q.pop(b)) order.push_back(b.slot);
  return order;
}

// Slot s: shortest edge lengths spread over several powers of two (squared: 1e-6 .. 4); slot 5 is
// only too large; slots 6 and 7 share slot 2's class.
void fill(BadTriangleQueue& q, const Triangulation& t) {
  const double shortest2[] = {1e-2, 4, 1e-6, 0.25, 1e-4};
  for (std::uint32_t s = 0; s < 5; ++s) q.push(t, s, true, shortest2[s], 0.1);
  q.push(t, 5, false, 0, 0.5);
  q.push(t, 6, true, 1e-6, 0.1);
  q.push(t, 7, true, 1.1e-6, 0.1);
}

}  // namespace

TEST_CASE("the bad-triangle queue pops the smallest shortest edge first by default", "[queue]") {
  const Triangulation t = slots(8);
  BadTriangleQueue q;
  fill(q, t);
  CHECK(drain(q) == std::vector<std::uint32_t>{7, 6, 2, 4, 0, 3, 1, 5});
}

TEST_CASE("the bad-triangle queue pops the largest shortest edge first when asked, too-large ones last", "[queue]") {
  const Triangulation t = slots(9);
  BadTriangleQueue q;
  q.setLargestFirst(true);
  fill(q, t);
  // A push between pops goes where it belongs, above or below what is left.
  BadTriangle b;
  REQUIRE(q.pop(b));
  CHECK(b.slot == 1);
  q.push(t, 8, true, 16, 0.1);
  CHECK(drain(q) == std::vector<std::uint32_t>{8, 3, 0, 4, 7, 6, 2, 5});
}

TEST_CASE("the bad-triangle queue pops too-large triangles by area, largest first, after every skinny one", "[queue]") {
  const Triangulation t = slots(6);
  BadTriangleQueue q;
  // Areas over many powers of two, two of them in one class (1.0 and 1.01: the later one first).
  q.push(t, 0, false, 1.0, 0.5);
  q.push(t, 1, false, 1e-9, 0.5);
  q.push(t, 2, false, 64, 0.5);
  q.push(t, 3, true, 1e-4, 0.1);
  q.push(t, 4, false, 1.01, 0.5);
  q.push(t, 5, false, 0.3, 0.5);
  CHECK(drain(q) == std::vector<std::uint32_t>{3, 2, 4, 0, 5, 1});
}
