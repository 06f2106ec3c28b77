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

#include <vector>

#include "curve_pieces.h"
#include "prepared_input.h"
#include "ruppert/ruppert.h"

namespace ruppert::detail {


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
