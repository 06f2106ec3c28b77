// PLCs with curved boundaries (Plc::curves) for the tests, each with its exact area.
#pragma once

#include <cstdint>

#include <ruppert/ruppert.h>

namespace ruppert_test {

struct CurvedShape {
  ruppert::Plc plc;
  double area;  // of the curved domain, exactly (to rounding)
};

// A circle of radius r around (cx, cy) as two arcs between two new points, its right and left ends.
void addCircle(ruppert::Plc& plc, double cx, double cy, double r);

// The unit square with a round hole of radius r at its center (two arcs and a hole seed).
CurvedShape squareWithRoundHole(double r);
// The quarter of the unit disk in the first quadrant: two segments and one arc.
CurvedShape quarterDisk();
// The region between the segment (0,0)-(1,0) and the cubic from (1,0) to (0,0) with controls
// (1, h) and (0, h).
CurvedShape underBezier(double h);
// A disk of radius 1 with `holes` round holes (a seeded pseudo-random layout that keeps them apart).
CurvedShape diskWithHoles(int holes, std::uint32_t seed);
// A w x h rectangle with corners rounded to radius r: four segments and four quarter arcs.
CurvedShape roundedRectangle(double w, double h, double r);
// The intersection of two disks of radius 1 whose centers lie 2d apart: two arcs meeting at tips of
// 2 acos(d) radians... sharp as d nears 1.
CurvedShape lens(double d);
// The unit disk minus a disk of radius r2 centered at (d, 0) that crosses its circle: two arcs
// meeting at two sharp tips.
CurvedShape crescent(double d, double r2);

// A gear of `teeth` teeth: arcs of the unit circle over their tops and of radius `inner` over the
// gaps between them, joined by straight flanks.
CurvedShape gear(int teeth, double inner);

}  // namespace ruppert_test
