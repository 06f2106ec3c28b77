#include "mesh/triangulation.h"

#include <algorithm>
#include <utility>

#include "mesh/predicates.h"

namespace ruppert::detail {

std::uint32_t Triangulation::addVertex(double x, double y) {
  xy.push_back(x);
  xy.push_back(y);
  vtri.push_back(kNone);
  return vertexCount() - 1;
}

void Triangulation::adoptVertices(std::vector<double>&& coordinates, std::size_t vertices) {
  xy = std::move(coordinates);
  reserveHuge(xy, 2 * vertices), reserveHuge(vtri, vertices);
  vtri.assign(xy.size() / 2, kNone);
}

std::vector<std::uint32_t> Triangulation::takeCompactCorners(std::uint32_t count) {
  words_.resize(3 * std::size_t(count));
  // The rest of the records' pages would stay the corners' capacity, unused: they go back now.
  releasePages(words_.data() + words_.size(), (words_.capacity() - words_.size()) * sizeof(std::uint32_t));
  std::vector<std::uint32_t> corners = std::move(words_);
  words_ = {};
  aim();
  return corners;
}

std::uint32_t Triangulation::nextStamp() const {
  stamp_ += 2;  // two values per search: stamp_ = inside the cavity, stamp_ + 1 = tested, outside
  if (stamp_ >= 0xFFFFFFF0u) {
    for (std::uint32_t t = 0; t < slotCount(); ++t) slots_[t].mark = 0;
    stamp_ = 2;
  }
  return stamp_;
}

Location Triangulation::locationInside(std::uint32_t t, const double ori[3]) const {
  // No orientation is negative: p is inside t, on one edge (one zero) or at a vertex (two zeros,
  // at the corner neither of those edges is opposite).
  Location loc;
  loc.tri = t;
  int zeros = 0;
  std::uint32_t zi = 0, zj = 0;
  for (std::uint32_t i = 0; i < 3; ++i)
    if (ori[i] == 0) (zeros++ == 0 ? zi : zj) = i;
  if (zeros == 0) {
    loc.kind = Location::InTriangle;
  } else if (zeros == 1) {
    loc.kind = Location::OnEdge;
    loc.edge = 3 * t + zi;
  } else {
    loc.kind = Location::OnVertex;
    loc.vertex = tv[3 * t + (3 - zi - zj)];
  }
  return loc;
}

Location Triangulation::locate(const double* p, std::uint32_t start) const {
  Location loc;
  std::uint32_t t = start;
  // A visibility walk can cycle in a constrained triangulation; starting each step at a random edge
  // makes cycles vanish with probability one. The bound only guards against bugs.
  const std::uint64_t maxSteps = 64 + 4ull * slotCount();
  std::uint32_t entered = kNone;  // the half-edge we came in through: p is on its inner side
  double enteredOrient = 0;
  for (std::uint64_t step = 0; step < maxSteps; ++step) {
    rng_ ^= rng_ << 13;
    rng_ ^= rng_ >> 7;
    rng_ ^= rng_ << 17;
    const std::uint32_t r = static_cast<std::uint32_t>(rng_ % 3);
    double o[3];
    bool moved = false;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t i = (r + k) % 3;
      const std::uint32_t h = 3 * t + i;
      if (h == entered) {
        o[i] = enteredOrient;
        continue;
      }
      o[i] = orient2d(pt(origin(h)), pt(dest(h)), p);
      if (o[i] < 0) {
        if (twin[h] == kNone) {
          loc.kind = Location::Outside;
          loc.tri = t;
          loc.edge = h;
          return loc;
        }
        entered = twin[h];
        enteredOrient = -o[i];
        t = entered / 3;
        moved = true;
        break;
      }
    }
    if (moved) continue;
    return locationInside(t, o);
  }
  loc.kind = Location::Lost;
  return loc;
}

std::uint32_t Triangulation::findEdge(std::uint32_t a, std::uint32_t b) const {
  const std::uint32_t h = findEdgeFrom(a, b);
  return h != kNone ? h : findEdgeFrom(b, a);
}

std::uint32_t Triangulation::findEdgeFrom(std::uint32_t a, std::uint32_t b) const {
  // In triangle t with a at corner i: half-edge 3t+(i+2)%3 runs a -> tv[i+1] ("out"),
  // half-edge 3t+(i+1)%3 runs tv[i+2] -> a ("in").
  return aroundVertex(a, [&](std::uint32_t t) -> std::uint32_t {
    const std::uint32_t i = tv[3 * t] == a ? 0u : tv[3 * t + 1] == a ? 1u : 2u;
    if (tv[3 * t + (i + 1) % 3] == b) return 3 * t + (i + 2) % 3;
    if (tv[3 * t + (i + 2) % 3] == b) {
      const std::uint32_t in = 3 * t + (i + 1) % 3;
      return twin[in] != kNone ? twin[in] : in;
    }
    return kNone;
  });
}

//            c                        c
//           / \                      /|\                                     .
//      CA  /   \  DC            CA  / | \  DC
//         /  T  \                  /  |  \                                   .
//        a ----- d   (edge b-c)   a U | T d   becomes edge a-d: T = (a,b,d), U = (a,d,c)
//         \  U  /                  \  |  /                                   .
//      AB  \   /  BD            AB  \ | /  BD
//           \ /                      \|/
//            b                        b
// (left: before, T = (a,b,c) owns half-edge h = b->c, U = (d,c,b) its twin; drawn schematically)
void Triangulation::flip(std::uint32_t h) {
  const std::uint32_t g = twin[h];
  const std::uint32_t T = h / 3, U = g / 3;
  const std::uint32_t a = tv[h], b = tv[next3(h)], c = tv[prev3(h)], d = tv[g];
  const std::uint32_t ca = twin[next3(h)], ab = twin[prev3(h)], bd = twin[next3(g)], dc = twin[prev3(g)];
  const std::int32_t cca = con[next3(h)], cab = con[prev3(h)], cbd = con[next3(g)], cdc = con[prev3(g)];
  tv[3 * T] = a, tv[3 * T + 1] = b, tv[3 * T + 2] = d;
  tv[3 * U] = a, tv[3 * U + 1] = d, tv[3 * U + 2] = c;
  link(3 * T + 0, bd), con[3 * T + 0] = cbd;
  link(3 * T + 1, 3 * U + 2), con[3 * T + 1] = kFree, con[3 * U + 2] = kFree;
  link(3 * T + 2, ab), con[3 * T + 2] = cab;
  link(3 * U + 0, dc), con[3 * U + 0] = cdc;
  link(3 * U + 1, ca), con[3 * U + 1] = cca;
  vtri[a] = vtri[b] = vtri[d] = T;
  vtri[c] = U;
}

void Triangulation::cavity(const double* p, const Location& loc, std::vector<std::uint32_t>& tris,
                           std::vector<std::uint32_t>& boundary) const {
  tris.clear();
  boundary.clear();
  const std::uint32_t in = nextStamp(), out = in + 1;
  std::uint32_t split = kNone, splitTwin = kNone;
  tris.push_back(loc.tri);
  slots_[loc.tri].mark = in;
  if (loc.kind == Location::OnEdge) {
    split = loc.edge;
    splitTwin = twin[split];
    if (splitTwin != kNone) {
      tris.push_back(splitTwin / 3);
      slots_[splitTwin / 3].mark = in;
    }
  }
  // The list grows while we scan it: a breadth-first search over the cavity.
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const std::uint32_t t = tris[k];
    const TriangleSlot& r = slots_[t];
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * t + i;
      if (h == split || h == splitTwin) continue;
      const std::uint32_t g = r.twin[i];
      if (g == kNone || r.con[i] != kFree) {
        boundary.push_back(h);
        continue;
      }
      const TriangleSlot& n = slots_[g / 3];
      if (n.mark == in) continue;
      if (n.mark != out && incircle(pt(n.tv[0]), pt(n.tv[1]), pt(n.tv[2]), p) > 0) {
        n.mark = in;
        tris.push_back(g / 3);
        // Its neighbors are tested after the triangles queued before it: asking for their records
        // now overlaps those misses with that work.
        for (std::uint32_t j = 0; j < 3; ++j)
          if (n.twin[j] != kNone) prefetch(&slots_[n.twin[j] / 3]);
      } else {
        n.mark = out;
        boundary.push_back(h);
      }
    }
  }
}

bool Triangulation::insertVertex(std::uint32_t v, const Location& loc, std::vector<std::uint32_t>* newTris,
                                 std::vector<std::uint32_t>* parents, bool checkOrientation) {
  static thread_local std::vector<std::uint32_t> tris, boundary;
  cavity(pt(v), loc, tris, boundary);
  return fillCavity(v, loc, tris, boundary, newTris, parents, checkOrientation);
}

namespace {

// One side of a cavity's boundary, u -> w seen from inside, becoming the new triangle (v, u, w).
struct FanSide {
  std::uint32_t u, w, outer, from;
  std::int32_t c;
};

// The sides of a fan found by their first vertex u, in a small open-addressing table (twice as
// many places as sides) rather than a per-vertex table, whose entries for a cavity's vertices,
// scattered through the vertex arrays, would each be a cache miss on a mesh larger than the cache.
class FanIndex {
 public:
  // False if some vertex starts two sides (the domain touching itself there: no fan).
  bool build(const std::vector<FanSide>& sides) {
    std::uint32_t bits = 4;
    while ((std::size_t(1) << bits) < 2 * sides.size()) ++bits;
    shift_ = 32 - bits;
    places_.assign(std::size_t(1) << bits, kEmpty);
    for (std::size_t k = 0; k < sides.size(); ++k) {
      const std::uint32_t u = sides[k].u;
      std::size_t p = placeOf(u);
      for (; places_[p] != kEmpty; p = (p + 1) & (places_.size() - 1))
        if (places_[p] >> 32 == u) return false;
      places_[p] = std::uint64_t(u) << 32 | k;
    }
    return true;
  }
  // The index of the side starting at x, or kNone.
  std::uint32_t find(std::uint32_t x) const {
    for (std::size_t p = placeOf(x); places_[p] != kEmpty; p = (p + 1) & (places_.size() - 1))
      if (places_[p] >> 32 == x) return static_cast<std::uint32_t>(places_[p]);
    return kNone;
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);
  std::uint32_t shift_ = 28;
  std::vector<std::uint64_t> places_;  // u << 32 | side index, or kEmpty
  std::size_t placeOf(std::uint32_t x) const { return (x * 0x9E3779B1u) >> shift_; }
};

}  // namespace

bool Triangulation::fillCavity(std::uint32_t v, const Location& loc, const std::vector<std::uint32_t>& tris,
                               const std::vector<std::uint32_t>& boundary, std::vector<std::uint32_t>* newTris,
                               std::vector<std::uint32_t>* parents, bool checkOrientation) {
  static thread_local std::vector<FanSide> sides;
  static thread_local FanIndex index;
  const double* p = pt(v);
  sides.clear();
  for (std::uint32_t h : boundary) {
    const std::uint32_t t = h / 3, i = h - 3 * t;
    const TriangleSlot& r = slots_[t];
    const std::uint32_t u = r.tv[i == 2 ? 0 : i + 1], w = r.tv[i == 0 ? 2 : i - 1];
    if (checkOrientation && !(orient2d(pt(u), pt(w), p) > 0)) return false;
    sides.push_back({u, w, r.twin[i], t, r.con[i]});
  }
  // A vertex twice on the boundary (the domain touching itself there) would break the fan.
  if (!index.build(sides)) return false;
  // Every vertex of the cavity must be on its boundary, or the fan would drop it. Exactly Delaunay
  // cavities always pass; a rounded split point a hair from a vertex can take in every triangle
  // around it (found by fuzzing, tests/hostile/shell-split-a-hair-from-a-vertex-dropped-it.poly: a
  // shell split 2.6e-8 from an input vertex lost it). Counted, not searched: the cavity is
  // connected and no vertex starts two of its boundary edges, so it is a planar surface whose
  // boundary is simple cycles, and Euler's formula makes it a disk with no vertex inside exactly
  // when it has k - 2 triangles for k boundary edges (k - 1 when splitting an edge with no triangle
  // beyond: the boundary is then a path, closed by the split edge, whose origin must then start no
  // other boundary edge).
  // A point located exactly with no constraints around (checkOrientation false) has a Delaunay
  // cavity, which passes: the test is left out with the orientations.
  const bool open = loc.kind == Location::OnEdge && twin[loc.edge] == kNone;
  const bool disk = tris.size() + (open ? 1 : 2) == sides.size() && !(open && index.find(origin(loc.edge)) != kNone);
  if (checkOrientation && !disk) return false;
  std::uint32_t sa = kNone, sb = kNone;
  std::int32_t splitCon = kFree;
  if (loc.kind == Location::OnEdge) {
    sa = origin(loc.edge);
    sb = dest(loc.edge);
    splitCon = con[loc.edge];
  }
  if (newTris) newTris->clear();
  if (parents) parents->clear();
  // Fan of new triangles {v, u, w}: edge 0 (u->w) faces the old outside, edge 1 (w->v) and
  // edge 2 (v->u) face the neighboring new triangles.
  static thread_local std::vector<std::uint32_t> made;
  made.resize(sides.size());
  // The cavity's slots are refilled last first, the slots killing them and taking free slots back
  // would give (so the numbering is the same), without passing them through freeSlots.
  std::size_t reuse = tris.size();
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const FanSide& s = sides[k];
    const std::uint32_t t = reuse > 0 ? refillTriangle(tris[--reuse], v, s.u, s.w) : newTriangle(v, s.u, s.w);
    made[k] = t;
    slots_[t].twin[0] = s.outer;
    if (s.outer != kNone) twin[s.outer] = 3 * t;
    slots_[t].con[0] = s.c;
    if (newTris) newTris->push_back(t);
    if (parents) parents->push_back(s.from);
  }
  for (std::size_t k = 0; k < reuse; ++k) killTriangle(tris[k]);  // (a fan has more triangles: none)
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const std::uint32_t j = index.find(sides[k].w);
    if (j == kNone) continue;
    const std::uint32_t t = made[k], nb = made[j];
    slots_[t].twin[1] = 3 * nb + 2, slots_[nb].twin[2] = 3 * t + 1;
  }
  if (splitCon != kFree) {
    for (std::uint32_t t : made) {
      TriangleSlot& r = slots_[t];
      if (r.tv[1] == sa || r.tv[1] == sb) r.con[2] = splitCon;
      if (r.tv[2] == sa || r.tv[2] == sb) r.con[1] = splitCon;
    }
  }
  return true;
}

// Triangle t = (a, b, c) becomes (v, b, c) in place, plus (v, c, a) and (v, a, b): three triangles
// around v, each keeping one outer edge. `stack` receives the three edges opposite v.
//        c
//       /|\   (v inside a-b-c)
//      / v \  .
//     a-----b
void Triangulation::splitTriangleAt(std::uint32_t v, std::uint32_t t, std::vector<std::uint32_t>& stack) {
  const std::uint32_t ta = tv[3 * t], tb = tv[3 * t + 1], tc = tv[3 * t + 2];
  const std::uint32_t o0 = twin[3 * t], o1 = twin[3 * t + 1], o2 = twin[3 * t + 2];
  const std::int32_t c0 = con[3 * t], c1 = con[3 * t + 1], c2 = con[3 * t + 2];
  tv[3 * t] = v;
  const std::uint32_t t1 = newTriangle(v, tc, ta), t2 = newTriangle(v, ta, tb);
  vtri[v] = vtri[tb] = vtri[tc] = t;
  link(3 * t, o0), con[3 * t] = c0;
  link(3 * t1, o1), con[3 * t1] = c1;
  link(3 * t2, o2), con[3 * t2] = c2;
  link(3 * t + 1, 3 * t1 + 2), con[3 * t + 1] = con[3 * t1 + 2] = kFree;
  link(3 * t1 + 1, 3 * t2 + 2), con[3 * t1 + 1] = con[3 * t2 + 2] = kFree;
  link(3 * t2 + 1, 3 * t + 2), con[3 * t2 + 1] = con[3 * t + 2] = kFree;
  stack = {3 * t, 3 * t1, 3 * t2};
}

// The edge a-b of half-edge e (in T = (x, a, b), and U = (y, b, a) across it if any) is split at v:
// T -> (x, a, v) + (x, v, b), U -> (y, b, v) + (y, v, a). Both halves keep the edge's constraint.
// `stack` receives the edges opposite v; sideU is U's slot, or kNone. False, changing nothing, if
// a new triangle would not be strictly counter-clockwise.
//        x
//       / \   (v on a-b)
//      a-v-b
//       \ /
//        y
bool Triangulation::splitEdgeAt(std::uint32_t v, std::uint32_t e, std::vector<std::uint32_t>& stack,
                                std::uint32_t& sideU) {
  const double* p = pt(v);
  const std::uint32_t g = twin[e];
  const std::uint32_t T = e / 3, x = tv[e];
  const std::uint32_t a = origin(e), b = dest(e);
  const std::int32_t split = con[e];
  if (!(orient2d(pt(x), pt(a), p) > 0 && orient2d(pt(x), p, pt(b)) > 0)) return false;
  std::uint32_t y = kNone;
  if (g != kNone) {
    y = tv[g];
    if (!(orient2d(pt(y), pt(b), p) > 0 && orient2d(pt(y), p, pt(a)) > 0)) return false;
  }
  const std::uint32_t tXB = twin[next3(e)], tAX = twin[prev3(e)];
  const std::int32_t cXB = con[next3(e)], cAX = con[prev3(e)];
  tv[3 * T] = x, tv[3 * T + 1] = a, tv[3 * T + 2] = v;  // T1 = (x, a, v) in place
  const std::uint32_t T2 = newTriangle(x, v, b);
  vtri[x] = vtri[a] = vtri[v] = T;
  link(3 * T + 2, tAX), con[3 * T + 2] = cAX;
  link(3 * T2 + 1, tXB), con[3 * T2 + 1] = cXB;
  link(3 * T + 1, 3 * T2 + 2), con[3 * T + 1] = con[3 * T2 + 2] = kFree;
  con[3 * T] = con[3 * T2] = split;
  twin[3 * T] = twin[3 * T2] = kNone;
  stack = {3 * T + 2, 3 * T2 + 1};
  sideU = kNone;
  if (g == kNone) return true;
  const std::uint32_t U = g / 3;
  const std::uint32_t tAY = twin[next3(g)], tYB = twin[prev3(g)];
  const std::int32_t cAY = con[next3(g)], cYB = con[prev3(g)];
  tv[3 * U] = y, tv[3 * U + 1] = b, tv[3 * U + 2] = v;  // U1 = (y, b, v) in place
  const std::uint32_t U2 = newTriangle(y, v, a);
  vtri[y] = vtri[b] = U;
  link(3 * U + 2, tYB), con[3 * U + 2] = cYB;
  link(3 * U2 + 1, tAY), con[3 * U2 + 1] = cAY;
  link(3 * U + 1, 3 * U2 + 2), con[3 * U + 1] = con[3 * U2 + 2] = kFree;
  link(3 * T2, 3 * U), link(3 * T, 3 * U2);
  con[3 * U] = con[3 * U2] = split;
  stack.push_back(3 * U + 2), stack.push_back(3 * U2 + 1);
  sideU = U;
  return true;
}

// The triangles around v, in order round the fan.
std::vector<std::uint32_t> Triangulation::trianglesAround(std::uint32_t v) const {
  std::vector<std::uint32_t> around;
  aroundVertex(v, [&around](std::uint32_t t) {
    around.push_back(t);
    return kNone;
  });
  return around;
}

bool Triangulation::insertVertexByFlips(std::uint32_t v, const Location& loc, std::vector<std::uint32_t>* newTris,
                                        std::vector<std::uint32_t>* parents) {
  std::vector<std::uint32_t> stack;  // half-edges opposite v that may not be locally Delaunay
  std::uint32_t sideT = kNone, sideU = kNone, a = kNone, b = kNone;
  if (loc.kind == Location::InTriangle) {
    splitTriangleAt(v, loc.tri, stack);
    sideT = loc.tri;
  } else if (loc.kind == Location::OnEdge) {
    a = origin(loc.edge), b = dest(loc.edge);
    if (!splitEdgeAt(v, loc.edge, stack, sideU)) return false;
    sideT = loc.edge / 3;
  } else {
    return false;
  }
  // Lawson's flips. The edges at v never need one (each new triangle's circumcircle through v is
  // empty on v's side), so legalize() flips exactly the edges opposite v, in the same order.
  legalize(stack);
  if (!newTris && !parents) return true;
  const std::vector<std::uint32_t> around = trianglesAround(v);
  if (newTris) *newTris = around;
  if (parents) {
    parents->clear();
    for (std::uint32_t t : around) {
      // Triangles left of a->b came from T's side, the others from U's (flips never cross it).
      std::uint32_t from = sideT;
      if (sideU != kNone) {
        double c[2] = {0, 0};
        for (int i = 0; i < 3; ++i) c[0] += pt(tv[3 * t + i])[0] / 3, c[1] += pt(tv[3 * t + i])[1] / 3;
        if (orient2d(pt(a), pt(b), c) < 0) from = sideU;
      }
      parents->push_back(from);
    }
  }
  return true;
}

void Triangulation::legalize(std::vector<std::uint32_t>& stack, std::vector<std::uint32_t>* changed) {
  while (!stack.empty()) {
    const std::uint32_t h = stack.back();
    stack.pop_back();
    const std::uint32_t t = h / 3;
    const std::uint32_t g = twin[h];
    if (!alive(t) || con[h] != kFree || g == kNone) continue;
    if (!(incircle(pt(tv[3 * t]), pt(tv[3 * t + 1]), pt(tv[3 * t + 2]), pt(apex(g))) > 0)) continue;
    const std::uint32_t u = g / 3;
    flip(h);
    // flip() keeps the slots: the four outer edges are now T's edges 0, 2 and U's edges 0, 1.
    stack.push_back(3 * t), stack.push_back(3 * t + 2), stack.push_back(3 * u), stack.push_back(3 * u + 1);
    if (changed) changed->push_back(t), changed->push_back(u);
  }
}

void Triangulation::legalizeAll() {
  std::vector<std::uint32_t> stack;
  for (std::uint32_t h = 0; h < 3 * slotCount(); ++h)
    if (alive(h / 3) && twin[h] != kNone && h < twin[h]) stack.push_back(h);
  legalize(stack);
}

}  // namespace ruppert::detail
