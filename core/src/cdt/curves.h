// Curved boundaries (Plc::curves): their geometry, and their cutting into the pieces that
// the rest of the pipeline treats as input segments.
//
// Before prepare, each curve is cut into pieces by parameter, each within the tolerance of its curve
// and lying in its chord's closed diametral disk (an arc piece turns by at most 60 degrees; a
// Bézier piece's control points lie in the disk, and so does the piece, their convex hull). The
// pieces' inner ends become new points after the input's and the pieces new segments after its. The
// disk matters: the sliver between a piece's chord and its curve lies in it, so any vertex there
// encroaches the piece (refinement tests curve pieces against the disk whatever the rule for
// segments), and refinement splits the piece before such a vertex can be left on the wrong side of
// the curve. Refinement splits a piece at the curve point of its parameters' midpoint
// (refine/refine_curve.cpp) and keeps the two tests on every new piece.
//
// An input point can lie in that sliver on the side where the domain has no triangle yet (the curve
// bulges out of the domain's chords): it is dropped with the triangles outside, and a later split
// would add the triangle (a, p, b) over it, leaving an input point inside the mesh unused. So the
// first cut also halves a piece while an input point other than its ends lies strictly inside its
// hull (CurveShape::hull); each new triangle of a split lies in its piece's hull, and a piece's
// halves' hulls in its own, so no dropped point is ever covered. A cut that lands on an input point
// (within 2^-40 of the largest coordinate, the validator's near-duplicates) ends its pieces at that
// point rather than beside it.
#pragma once

#include <climits>
#include <cstdint>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

struct PreparedInput;

// One curve over the parameter t in [0, 1].
struct CurveShape {
  CurveType type = CurveType::Arc;
  // Arc: centre x, y, radius, start angle, sweep (radians, > 0). Bezier: the control points P0 .. P3.
  double c[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  void point(double t, double out[2]) const;
  // The control points of the piece [t0, t1] (Bezier), by the derivative at its ends.
  void pieceControls(double t0, double t1, double q[8]) const;
  // An upper bound on the distance from the piece [t0, t1] to its chord: the sagitta of an arc, the
  // largest distance of a Bézier piece's control points.
  double chordError(double t0, double t1) const;
  // Whether the piece [t0, t1] lies in the closed diametral disk of its chord.
  bool withinDisk(double t0, double t1) const;
  // Four points whose convex hull holds the piece [t0, t1], its ends first and last: a Bézier
  // piece's control points, an arc piece's ends and the meeting point of its end tangents (twice).
  void hull(double t0, double t1, double q[8]) const;
  void scale(double factor);  // by a power of two: exact
};

struct CurvePieces {
  std::int32_t first = INT32_MAX;  // the first piece's segment index; pieces are the segments after it
  std::uint32_t firstPoint = UINT32_MAX;  // the first point made on a curve (the input's point count)
  std::vector<CurveShape> shapes;   // per curve; in internal coordinates once scaled
  std::vector<std::uint32_t> curveOf;  // per piece: its curve
  std::vector<double> t0, t1;       // per piece: its parameters at its segment's first and second end
  double tolerance = 0;             // the largest distance of a piece from its curve (internal units once scaled)

  bool isPiece(std::int32_t segment) const { return segment >= first; }
  const CurveShape& shapeOf(std::int32_t segment) const { return shapes[curveOf[std::size_t(segment - first)]]; }
  // Mesh::segmentIds for segment index `segment`: a piece's is the user's segment count + its curve.
  std::int32_t outputId(std::int32_t segment) const {
    return isPiece(segment) ? first + static_cast<std::int32_t>(curveOf[std::size_t(segment - first)]) : segment;
  }
};

// What a PLC without curves has.
inline const CurvePieces kNoCurves{};

// The PLC to mesh: `plc` with every curve cut into pieces (new points after its points, new segments
// after its segments; one segment marker per curve after its segment markers, as outputId numbers
// them). Throws ruppert::Error naming the curve for a bad one.
Plc withCurvePieces(const Plc& plc, const Options& options, CurvePieces& pieces);

// The shapes and tolerance in internal coordinates (after prepare).
void scaleCurves(CurvePieces& pieces, const PreparedInput& input);

// After constrain: a repair that touched a piece (a crossing, a point on it, an overlap) would put a
// vertex off its curve. Throws ruppert::Error naming the curve instead.
void rejectRepairedCurves(const std::vector<Notice>& notices, const CurvePieces& pieces);

}  // namespace ruppert::detail
