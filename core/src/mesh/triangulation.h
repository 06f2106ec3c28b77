// The mutable triangulation every stage works on: flat arrays (structure of arrays), half-edges as
// 3*triangle+i, constrained edges flagged per half-edge.
//
// Terminology used throughout the core:
//   triangle t   vertices tv[3t], tv[3t+1], tv[3t+2], counter-clockwise; tv[3t] == kNone: a free slot.
//   half-edge h  3t+i: the edge of t opposite its vertex tv[3t+i], from tv[3t+(i+1)%3] to tv[3t+(i+2)%3].
//   twin[h]      the same edge seen from the neighboring triangle, or kNone on the mesh boundary.
//   con[h]       which constraint the edge carries: kFree, an input segment index (>= 0), or kHullEdge.
//                Both half-edges of an edge always carry the same value.
//   vtri[v]      some live triangle that has v as a vertex (kNone for vertices not in the mesh).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/huge_pages.h"
namespace ruppert::detail {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;
inline constexpr std::int32_t kFree = -1;      // con[h]: not a subsegment
inline constexpr std::int32_t kHullEdge = -2;  // con[h]: convex-hull or bounding-box edge added by us
// The capacity that scratch lists made once per call (cavities, their boundaries, new triangles)
// start with: more than most cavities need.
inline constexpr std::size_t kScratchReserve = 32;

// Frees a vector's memory (assigning {} would keep its capacity).
template <class Vector>
void release(Vector& v) {
  Vector().swap(v);
}

// A hint that *p is read soon (none in WebAssembly, which has no such instruction: left out there,
// with the loads that would compute its address).
inline void prefetch(const void* p) {
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__wasm__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}
// The same for memory about to be written.
inline void prefetchForWrite(const void* p) {
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__wasm__)
  __builtin_prefetch(p, 1);
#else
  (void)p;
#endif
}

inline std::uint32_t next3(std::uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
inline std::uint32_t prev3(std::uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; }

// Where a point lies relative to the triangulation (result of locate()).
struct Location {
  enum Kind { InTriangle, OnEdge, OnVertex, Outside, Lost } kind = Lost;
  std::uint32_t tri = kNone;   // containing triangle (InTriangle), or a triangle of the edge/vertex
  std::uint32_t edge = kNone;  // half-edge (OnEdge; Outside: the boundary half-edge crossed last)
  std::uint32_t vertex = kNone;  // OnVertex
};

// Everything a triangle slot holds, in one record: a cavity search or a fill reads a slot's stamp,
// corners, neighbors and constraints together, and as separate arrays each of them was its own
// cache miss on a mesh larger than the cache. The stamp comes first: it is what a search reads first.
// The records live in an array of 32-bit words (kSlotWords per slot), so that output can compact the
// corners to the array's front in place and hand the array over as its triangle list.
struct TriangleSlot {
  mutable std::uint32_t mark;  // per-slot stamp for cavity search
  std::uint32_t tv[3];
  std::uint32_t twin[3];
  std::int32_t con[3];
};
inline constexpr std::size_t kSlotWords = 10;
static_assert(sizeof(TriangleSlot) == kSlotWords * sizeof(std::uint32_t) && alignof(TriangleSlot) == alignof(std::uint32_t),
              "a slot record is ten 32-bit words");

// One per-half-edge field of the slot records, indexed by half-edge h = 3t+i like a flat array
// (field[h] is slot t's field[i]). It points into the records (pointer semantics: a const view still
// gives a writable element) and is re-aimed by SlotRecords whenever they move.
template <class T, T (TriangleSlot::*Field)[3]>
class HalfEdgeField {
 public:
  T& operator[](std::uint32_t h) const { return (slots_[h / 3].*Field)[h % 3]; }
  void aim(TriangleSlot* slots) { slots_ = slots; }

 private:
  TriangleSlot* slots_ = nullptr;
};

// The slot records and the three flat views of them (tv, twin, con: see the file's comment), kept
// aimed at the records through copies and moves.
class SlotRecords {
 public:
  HalfEdgeField<std::uint32_t, &TriangleSlot::tv> tv;
  HalfEdgeField<std::uint32_t, &TriangleSlot::twin> twin;
  HalfEdgeField<std::int32_t, &TriangleSlot::con> con;

  SlotRecords() = default;
  SlotRecords(const SlotRecords& o) : words_(o.words_) { aim(); }
  SlotRecords(SlotRecords&& o) noexcept : words_(std::move(o.words_)) { aim(), o.aim(); }
  SlotRecords& operator=(const SlotRecords& o) {
    words_ = o.words_;
    aim();
    return *this;
  }
  SlotRecords& operator=(SlotRecords&& o) noexcept {
    words_ = std::move(o.words_);
    aim(), o.aim();
    return *this;
  }
  std::uint32_t slotCount() const { return static_cast<std::uint32_t>(words_.size() / kSlotWords); }

 protected:
  std::vector<std::uint32_t> words_;  // the records' storage
  TriangleSlot* slots_ = nullptr;     // the records, aimed at words_
  void aim() {
    slots_ = reinterpret_cast<TriangleSlot*>(words_.data());
    tv.aim(slots_), twin.aim(slots_), con.aim(slots_);
  }
};

class Triangulation : public SlotRecords {
 public:
  std::vector<double> xy;          // vertex coordinates x0,y0,x1,y1,...
  std::vector<std::uint32_t> vtri; // 1 per vertex
  std::vector<std::uint32_t> freeSlots;

  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>(xy.size() / 2); }
  bool alive(std::uint32_t t) const { return slots_[t].tv[0] != kNone; }
  const double* pt(std::uint32_t v) const { return &xy[2 * v]; }
  // Slot t's record: hot loops read a triangle's fields from it directly, where tv[3 * t + i]
  // would divide the half-edge by three again for each field.
  const TriangleSlot& slot(std::uint32_t t) const { return slots_[t]; }
  std::uint32_t origin(std::uint32_t h) const {  // start of half-edge h
    const std::uint32_t t = h / 3, i = h - 3 * t;
    return slots_[t].tv[i == 2 ? 0 : i + 1];
  }
  std::uint32_t dest(std::uint32_t h) const {  // end of half-edge h
    const std::uint32_t t = h / 3, i = h - 3 * t;
    return slots_[t].tv[i == 0 ? 2 : i - 1];
  }
  std::uint32_t apex(std::uint32_t h) const { return tv[h]; }  // vertex opposite h
  // For passes over every slot in order: the records stream in, but the corners' coordinates and
  // the neighbors' records are scattered, one miss after another unless asked for ahead (at slot
  // s + kScanAhead while at s).
  static constexpr std::uint32_t kScanAhead = 8;
  void prefetchCorners(std::uint32_t s) const {
    if (s >= slotCount() || slots_[s].tv[0] == kNone) return;
    for (std::uint32_t i = 0; i < 3; ++i) prefetch(pt(slots_[s].tv[i]));
  }
  void prefetchNeighbors(std::uint32_t s) const {
    if (s >= slotCount()) return;
    for (std::uint32_t i = 0; i < 3; ++i)
      if (slots_[s].twin[i] != kNone) prefetch(&slots_[slots_[s].twin[i] / 3]);
  }

  std::uint32_t addVertex(double x, double y);
  // Takes `coordinates` (x0,y0,x1,y1,...) as the first vertices, none in the mesh yet, without
  // copying them, and reserves room for `vertices` in all.
  void adoptVertices(std::vector<double>&& coordinates, std::size_t vertices);
  // A triangle with no neighbors and no constraints yet, in a free slot if there is one.
  std::uint32_t newTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (!freeSlots.empty()) {
      const std::uint32_t t = freeSlots.back();
      freeSlots.pop_back();
      return refillTriangle(t, a, b, c);
    }
    const std::uint32_t t = slotCount();
    const std::uint32_t f = static_cast<std::uint32_t>(kFree);
    words_.insert(words_.end(), {0, a, b, c, kNone, kNone, kNone, f, f, f});
    aim();
    // Slots are appended a few per insertion, too slowly for the hardware to see a stream: the
    // record after next is asked for now, so that writing it later does not wait for memory.
    if (words_.capacity() - words_.size() > 2 * kSlotWords)
      prefetchForWrite(words_.data() + words_.size() + kSlotWords);
    vtri[a] = vtri[b] = vtri[c] = t;
    return t;
  }
  // Slot t (free, or about to be: a cavity's) becomes the triangle a, b, c with no neighbors and
  // no constraints yet.
  std::uint32_t refillTriangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    TriangleSlot& r = slots_[t];
    r.tv[0] = a, r.tv[1] = b, r.tv[2] = c;
    for (int i = 0; i < 3; ++i) r.twin[i] = kNone, r.con[i] = kFree;
    vtri[a] = vtri[b] = vtri[c] = t;
    return t;
  }
  // Room for this many vertices and triangle slots without regrowing (a small mesh otherwise spends
  // a sixth of its time growing these arrays from empty one doubling at a time).
  void reserve(std::size_t vertices, std::size_t slots) {
    reserveHuge(xy, 2 * vertices), reserveHuge(vtri, vertices);
    reserveHuge(words_, kSlotWords * slots);
    aim();
  }
  // Frees what only insertion and search use (the free-slot list).
  void releaseScratch() { release(freeSlots); }
  // Output's per-slot label (a slot's triangle index in the output), kept in the word of the
  // slot's search stamp, free once searches are over: no per-slot array at the output's peak.
  std::uint32_t label(std::uint32_t t) const { return slots_[t].mark; }
  void setLabel(std::uint32_t t, std::uint32_t value) { slots_[t].mark = value; }
  // Room for output's per-vertex map (capacity for every vertex, empty).
  std::vector<std::uint32_t> takeVertexScratch() const {
    std::vector<std::uint32_t> map;
    map.reserve(vertexCount());
    return map;
  }
  // Output's corners in the records' own memory, for a scan over the slots that compacts as it
  // reads: it copies slot s's record out before storing output triangle o's corners (o <= s) at
  // words 3o..3o+2, which lie in records already read; releaseReadRecords(end, count) hands back the
  // pages of records [0, end) beyond the corners' room (3 words for each of count triangles);
  // takeCompactCorners(count) hands the corners over, and every slot is gone afterwards.
  void writeCompactCorners(std::uint32_t o, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t* w = words_.data() + 3 * std::size_t(o);
    w[0] = a, w[1] = b, w[2] = c;
  }
  void releaseReadRecords(std::uint32_t end, std::uint32_t count) {
    const std::size_t from = 3 * std::size_t(count), to = kSlotWords * std::size_t(end);
    if (to > from) releasePages(words_.data() + from, (to - from) * sizeof(std::uint32_t));
  }
  std::vector<std::uint32_t> takeCompactCorners(std::uint32_t count);
  void killTriangle(std::uint32_t t) {
    TriangleSlot& r = slots_[t];
    r.tv[0] = r.tv[1] = r.tv[2] = kNone;
    freeSlots.push_back(t);
  }
  void link(std::uint32_t h, std::uint32_t g) {  // make h and g twins (either may be kNone)
    if (h != kNone) twin[h] = g;
    if (g != kNone) twin[g] = h;
  }

  // Walk from triangle `start` towards p. Stochastic visibility walk; bounded number of steps.
  Location locate(const double* p, std::uint32_t start) const;

  // Location of p in triangle t given ori[i] = orient2d(edge i, p), none of them negative.
  Location locationInside(std::uint32_t t, const double ori[3]) const;

  // A half-edge of the edge {a, b}: a->b when that side exists, else b->a; kNone if no such edge.
  // Searches the triangles around a, then around b. At a vertex where the domain touches itself
  // the triangles around it form several fans and only vtri's fan is searched.
  std::uint32_t findEdge(std::uint32_t a, std::uint32_t b) const;

  // Flip the edge h (must be free and have a twin; the quad must be strictly convex).
  // Afterwards h's triangle is (apex(h), origin(h), d) and the new diagonal runs apex(h)-d.
  void flip(std::uint32_t h);

  // Bowyer-Watson insertion of vertex v located at `loc` (InTriangle or OnEdge). The cavity is the
  // set of triangles, connected to the start without crossing constrained edges, whose open
  // circumdisk contains v. On a constrained edge (OnEdge with con != kFree) the edge is split and
  // both halves keep the constraint. Returns false, changing nothing, if a new triangle would not be
  // strictly counter-clockwise (v on the cavity boundary: possible only for rounded points).
  // newTris receives the triangles created and parents, for each, the (now freed) cavity slot it
  // replaces on the same side of the cavity boundary: per-triangle data is inherited from there
  // (cavities never cross constrained edges, so a cavity lies in one region). Either may be null.
  // checkOrientation = false skips the orientation test of every new triangle: only for a point
  // located exactly with no constraints around (its cavity is then star-shaped by construction).
  bool insertVertex(std::uint32_t v, const Location& loc, std::vector<std::uint32_t>* newTris = nullptr,
                    std::vector<std::uint32_t>* parents = nullptr, bool checkOrientation = true);

  // The second half of insertVertex: replace the cavity that cavity() computed for v's point and
  // `loc`, in a triangulation not changed since, by the fan around v.
  bool fillCavity(std::uint32_t v, const Location& loc, const std::vector<std::uint32_t>& tris,
                  const std::vector<std::uint32_t>& boundary, std::vector<std::uint32_t>* newTris = nullptr,
                  std::vector<std::uint32_t>* parents = nullptr, bool checkOrientation = true);

  // The same insertion by splitting the containing triangle (or the two sharing the edge) and Lawson
  // flips. Slower, but it needs no fan around any other vertex: it works where insertVertex refuses a
  // cavity that wraps around a vertex at which the domain touches itself. False, changing nothing,
  // if a new triangle would not be strictly counter-clockwise.
  bool insertVertexByFlips(std::uint32_t v, const Location& loc, std::vector<std::uint32_t>* newTris = nullptr,
                           std::vector<std::uint32_t>* parents = nullptr);

  // Cavity computation without modifying anything (the first half of insertVertex). Returns the
  // boundary half-edges (outer side twins are looked up from the cavity triangles' half-edges).
  void cavity(const double* p, const Location& loc, std::vector<std::uint32_t>& tris,
              std::vector<std::uint32_t>& boundary) const;

  // Lawson flips from the half-edges on `stack` (consumed) until every free edge they lead to is
  // locally Delaunay. flip() keeps both slots and the four outer edges are pushed again, so an entry
  // whose slot has since changed edge costs one test and nothing is missed. `changed`, if given,
  // receives both slots of every flip, with repeats.
  void legalize(std::vector<std::uint32_t>& stack, std::vector<std::uint32_t>* changed = nullptr);
  // Lawson flips over every free edge until all are locally Delaunay (converges to the CDT).
  void legalizeAll();

 private:
  mutable std::uint32_t stamp_ = 0;
  mutable std::uint64_t rng_ = 0x9E3779B97F4A7C15ull;
  std::uint32_t nextStamp() const;
  std::uint32_t findEdgeFrom(std::uint32_t a, std::uint32_t b) const;
  // The steps of insertVertexByFlips.
  void splitTriangleAt(std::uint32_t v, std::uint32_t t, std::vector<std::uint32_t>& stack);
  bool splitEdgeAt(std::uint32_t v, std::uint32_t e, std::vector<std::uint32_t>& stack, std::uint32_t& sideU);
  std::vector<std::uint32_t> trianglesAround(std::uint32_t v) const;

  // The one walk around a vertex: visit(t) for each triangle around v in order round the fan (one
  // way from vtri[v], then the other way when the fan is open: v on the boundary) until it returns
  // something other than kNone, which is returned (kNone when no call does).
  template <class Visit>
  std::uint32_t aroundVertex(std::uint32_t v, Visit&& visit) const {
    const std::uint32_t start = vtri[v];
    if (start == kNone) return kNone;
    auto corner = [&](std::uint32_t t) { return tv[3 * t] == v ? 0u : tv[3 * t + 1] == v ? 1u : 2u; };
    std::uint32_t t = start;
    for (;;) {
      if (const std::uint32_t r = visit(t); r != kNone) return r;
      const std::uint32_t g = twin[3 * t + (corner(t) + 2) % 3];
      if (g == kNone) break;
      t = g / 3;
      if (t == start) return kNone;  // a closed fan, all seen
    }
    for (t = start;;) {
      const std::uint32_t g = twin[3 * t + (corner(t) + 1) % 3];
      if (g == kNone) return kNone;
      t = g / 3;
      if (t == start) return kNone;
      if (const std::uint32_t r = visit(t); r != kNone) return r;
    }
  }
};

}  // namespace ruppert::detail
