// A curve's shape (an arc or a cubic Bézier over t in [0, 1]) and the pieces it is cut into, as
// every stage from constrain to output reads them; cdt/curves.h cuts them and explains why each
// piece lies in its chord's diametral disk.
#pragma once

#include <climits>
#include <cstdint>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// An arc piece turns by at most 60 degrees: well inside its chord's diametral disk.
inline constexpr double kArcPieceTurn = 6.28318530717958647692 / 6;

// One curve over the parameter t in [0, 1].
struct CurveShape {
  CurveType type = CurveType::Arc;
  // Arc: center x, y, radius, start angle, sweep (radians, > 0). Bezier: the control points P0 .. P3.
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

}  // namespace ruppert::detail
