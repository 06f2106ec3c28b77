// Locally optimal Steiner points, after Erten and Üngör ("Quality triangulations with locally optimal
// Steiner points", SIAM J. Sci. Comput. 31(3), 2009), as free functions on coordinates.
//
// A new vertex x inserted into a cavity (a star-shaped polygon, counter-clockwise) forms one triangle
// (u, v, x) with every boundary edge u->v. Each such triangle has all three angles >= a only in the
// region R_a(uv): x left of the rays from u and from v that leave the edge at angle a (the two base
// angles), and inside the arc through u and v from which uv is seen at angle a (the apex angle).
// R_a(uv) is an intersection of two half-planes and a disk, hence convex; so the smallest new angle,
// f(x) = min over the edges of the smallest angle of (u, v, x), has convex superlevel sets
// {f >= a} = intersection of the R_a: f is quasi-concave and its local maxima are global (no plateaus:
// each angle changes strictly along any direction that changes it at all).
// The petal of the skinny triangle's shortest edge pq (R_theta(pq), Erten and Üngör's constraint
// that the point stays close enough to pq to make a good triangle with it) is one more term of f.
// A constrained edge of the boundary adds a hard constraint: its apex angle must stay below the
// encroachment angle (90 degrees for the diametral disk, 180 - 2 theta for the lens), or x would be
// rejected.
#pragma once

#include <cmath>
#include <cstddef>

namespace ruppert::detail {

// One boundary edge of the new vertex's cavity, directed so that the cavity lies to its left.
struct CavityEdge {
  double u[2], v[2];
  bool constrained;  // a subsegment: x must not encroach it
};

struct OptimalPointQuery {
  const double* p = nullptr;  // the shortest edge p->q, the skinny triangle to its left
  const double* q = nullptr;
  const CavityEdge* edges = nullptr;
  std::size_t edgeCount = 0;
  double maxApex = 0;  // radians: the apex angle at which x starts to encroach a constrained edge
  bool petal = true;   // whether the triangle (p, q, x) counts too (else p-q only places the seeds)
  // Radians: the search may stop at the first point whose smallest angle exceeds this (infinity:
  // maximise). Refinement needs a point that meets its bound, not the best one: stopping there made
  // the same number of triangles over the shape families.
  double goodEnough = HUGE_VAL;
};

struct OptimalPoint {
  double x[2];
  double minAngle;  // radians: the smallest angle f(x) predicts; <= 0 when x is right of some edge
  bool encroaches;  // x encroaches a constrained edge (f is then not a valid prediction)
};

// The smallest angle of the triangles x would form with the petal edge and every cavity edge, in
// radians (negative when x lies on the wrong side of an edge), and whether it encroaches.
OptimalPoint evaluateSteinerPoint(const OptimalPointQuery& query, const double* x);

// The point that maximises f, by compass search from the best of the given seeds and of points of
// the petal of pq (on its bisector, where the apex angle is 60 degrees and where it is theta... ).
// Points that encroach a constrained edge count as worse than any that does not. Always returns a
// point; the caller decides from minAngle whether to use it. Stops early past query.goodEnough.
OptimalPoint optimalSteinerPoint(const OptimalPointQuery& query, const double* seeds, std::size_t seedCount);

}  // namespace ruppert::detail
