// An independent check of meshes with curved boundaries (Plc::curves): computed from the input's
// curves and the output alone, with none of the core's curve code.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <ruppert/ruppert.h>

namespace ruppert_test {

struct CurveCheck {
  std::vector<std::string> problems;  // empty: every check passed
  std::vector<std::size_t> pieces;    // per curve: its subsegments in the mesh
  double worstOffCurve = 0;           // largest distance of a piece's vertex from its curve, over the curve's size
  double worstChordError = 0;         // largest distance from a piece's chord to its stretch of curve
  double chordAreaBound = 0;          // the sum of chord length x that distance: bounds the area between chords and curves
};

// Every subsegment with a curve's segmentId: both ends on the curve within 1e-12 of the curve's size
// (an arc's radius, a Bézier's control polygon's extent), its stretch of curve within `tolerance`
// (plus 1e-12 of the size) of its chord, and each curve's pieces one chain from `from` to `to`; or,
// without wholeChains (curves may run through holes, whose pieces are not the mesh's), no vertex
// where more than two of a curve's pieces meet.
CurveCheck checkCurves(const ruppert::Mesh& mesh, const ruppert::Plc& input, double tolerance, bool wholeChains = true);

}  // namespace ruppert_test
