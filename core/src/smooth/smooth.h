// Smoothing after refinement (Options::smooth): free vertices move to improve the triangles' shapes
// while the mesh keeps every bound refinement met, its triangle count and its grading.
//
// Literature (the mathematics only; the code is written from it):
//   * L. Chen and J. Xu, "Optimal Delaunay triangulations", J. Comput. Math. 22(2), 2004, and L. Chen
//     and M. Holst, "Efficient mesh optimization schemes based on optimal Delaunay triangulations",
//     CMAME 200, 2011. The optimal Delaunay triangulation (ODT) minimises the L1 error of
//     interpolating |x|^2; for a fixed connectivity, the best place of an interior vertex is the
//     area-weighted average of its star's circumcenters, x* = sum |T| c_T / sum |T|. Alternating
//     that move with Delaunay flips makes triangles rounder without Lloyd's (CVT's) pull towards
//     uniform sizes: each vertex stays among the circumcenters of its own star, so the sizes stay
//     where they were.
//   * L. Freitag, M. Jones and P. Plassmann, "An efficient parallel algorithm for mesh smoothing"
//     (IMR 1995), and T. Zhou and K. Shimada, "An angle-based approach to two-dimensional mesh
//     smoothing" (IMR 2000): a "smart" smoother only keeps moves that do not worsen the star's
//     worst angle; that guard is what lets the bound survive here.
//
// Terminology:
//   free vertex  a vertex refinement put inside the domain (VertexKind Interior or OffCenter) whose
//                triangles close around it, none of whose edges is a subsegment. Input points,
//                intersection vertices and vertices on segments never move, so every segment, the
//                domain's boundary and every region keep their exact shape.
//   star         the triangles around a free vertex; the ring: their edges opposite it.
//
// A move is kept only if, once Lawson flips have restored the constrained Delaunay property, every
// triangle it changed (the star and every flipped one) is counter-clockwise, has its smallest angle
// at least min(Options::minAngle, the old star's smallest angle), and has an area within every
// bound that applies to it (maxArea, its region's, the size function, a refined mesh's); and if it
// raised the star's mean smallest angle. Otherwise the flips are undone in reverse and the vertex
// goes back, exactly. Flips keep the triangle count; a fixed number of passes bounds the time.
#pragma once

#include <cstdint>

#include "mesh_state.h"

namespace ruppert::detail {

// Runs `passes` passes over the free vertices of m's triangulation (after refinement, with only
// the domain's triangles left). Returns how many moves were kept.
std::uint64_t smoothMesh(MeshState& m, int passes);

}  // namespace ruppert::detail
