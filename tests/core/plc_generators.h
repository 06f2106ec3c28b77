// Random and structured PLC generators for tests, refinement checks and fuzzing.
//
// Every generator is deterministic for a given seed on every platform: it draws from std::mt19937_64
// (whose output sequence the C++ standard fixes) and maps bits to values itself, instead of using
// std::uniform_*_distribution (whose algorithms differ between standard libraries).
// Coordinates are dyadic (multiples of 2^-20 inside the unit square, or small integers for grids), so
// translating by integers, scaling by powers of two and rotating by 90 degrees are exact.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <ruppert/ruppert.h>

namespace ruppert_test {

// A generated PLC and what a correct mesh of it must satisfy.
struct GeneratedPlc {
  ruppert::Plc plc;
  double area = 0;  // area of the domain (the region that segments and hole seeds define)
};

// The unit square's four corners and four boundary segments, plus n random points strictly inside.
GeneratedPlc randomPointsInSquare(std::uint64_t seed, std::size_t n);

// n random points strictly inside the unit square and no segments (the domain is their convex hull;
// area = 0, not computed).
GeneratedPlc randomPointSet(std::uint64_t seed, std::size_t n);

// A simple polygon with n vertices, star-shaped around (0.5, 0.5) (sorted random angles, random radii),
// with up to `holes` small square holes inside it (each with a hole seed at its center).
GeneratedPlc randomStarPolygon(std::uint64_t seed, std::size_t n, std::size_t holes);

// A map-like outline centered on the origin: a star-shaped ring of n (rounded up to a multiple of 4,
// at least 8) vertices at radii 0.7 to 1.3 and, with `hole`, an 8-vertex hole ring at radii 0.1 to
// 0.2 around the origin (its seed at the origin). Coordinates use every bit of a double (not dyadic),
// and each ring edge that crosses an axis runs from (+c, y1) to (-c, y2) (or (x1, +c) to (x2, -c)),
// so its midpoint lies on the axis and the rest of it rounds. No trigonometric functions: the
// directions come from the rational parametrisation of the circle, the same bits everywhere.
GeneratedPlc originCenteredOutline(std::uint64_t seed, std::size_t n, bool hole);

// The unit square's boundary and random segments strictly inside it, drawn `attempts` times and kept
// only when they touch no segment kept so far (not even at an endpoint).
GeneratedPlc randomNonCrossingSegments(std::uint64_t seed, std::size_t attempts);

// The unit square's boundary and n random segments strictly inside it, not filtered: they cross each
// other freely (input repair must split them at intersection vertices).
GeneratedPlc randomCrossingSegments(std::uint64_t seed, std::size_t n);

// The square [0, g]^2's boundary and n random segments whose endpoints are integer grid points of
// [0, g]^2 (boundary included). With a small g this produces every degeneracy repair must handle:
// zero-length and duplicate segments, overlaps with each other and with the boundary, endpoints in
// other segments' interiors, and crossings exactly at grid points or between them.
GeneratedPlc randomGridSegments(std::uint64_t seed, std::size_t n, std::uint32_t g);

// n chords of the unit disk through (nearly) its center: from angle a in [0, pi) to the antipode,
// its x moved by up to 0.01. They cross about n^2 / 2 times, at small angles and in tight clusters,
// and enclose the domain themselves (area = 0, not computed).
GeneratedPlc chordStar(std::uint64_t seed, std::size_t n);

// The square [-1, 1]^2, shifted by up to 2, and one to three clusters of 2 to 7 short segments that
// cross each other: each cluster 10^-1 to 10^-(1 + decades) across, at the origin, at a random
// point or on the square's right edge, its segments at random directions or within 1e-12 rad of one
// another, some joined to a corner of the square. Crossings then fall among input points a few
// hundred ulps apart (area = 0, not computed).
GeneratedPlc crossingClusters(std::uint64_t seed, double decades);

// The square [-1, 1]^2, shifted by up to 2, and one to three bundles of 2 to 5 segments that nearly
// overlap: a pair or fan from one apex (inside the square, at a corner or on its right edge) at
// angles of 1e-3 to 1e-12 rad from the first segment, or from apexes a hair (2^-20 to 2^-45) apart;
// some end at near-duplicate points, some end on the square's boundary, and 0 to 3 other segments
// cross each bundle. Segments meeting at tiny angles, not crossing ones, are the point here
// (area = 0, not computed).
GeneratedPlc nearOverlaps(std::uint64_t seed);

// A segment from (-1, 0) to (1, 0) under a chain of 2 to 4 boundary edges from (-1, 0) to (1, 0)
// whose inner points sit 1e-4 to 3e-4 above it (nearly collinear), closed below by an apex at
// (0, -0.3..-0.7): a sliver that needs tens of thousands of triangles at 30 degrees, with input
// angles of about 1e-4 rad at both ends. Shifted by up to 2 (area = 0, not computed).
GeneratedPlc nearCollinearSliver(std::uint64_t seed);

// An nx-by-ny grid of points spaced `step` apart with the grid's boundary as segments between
// neighboring boundary points (so every boundary side is a chain of collinear points), plus, when
// `crossLines` is set, the middle row and column as chains of segments. Every unit cell's corners are
// cocircular: the Delaunay triangulation is maximally degenerate.
GeneratedPlc gridPlc(std::size_t nx, std::size_t ny, double step = 1.0, bool crossLines = false);

// --- exact transformations used by the metamorphic tests -------------------------------------------
ruppert::Plc scaled(const ruppert::Plc& plc, double factor);             // points, holes, region seeds
ruppert::Plc translated(const ruppert::Plc& plc, double dx, double dy);
ruppert::Plc rotated90(const ruppert::Plc& plc);                         // (x, y) -> (-y, x)
ruppert::Plc mirrored(const ruppert::Plc& plc, bool flipX, bool flipY);  // x -> -x and/or y -> -y
// Points permuted (newIndex[old] gives the new index) and segments reversed in order.
ruppert::Plc permuted(const ruppert::Plc& plc, std::uint64_t seed, std::vector<std::uint32_t>* newIndex);
// The PLC plus a copy shifted by (dx, 0).
ruppert::Plc withShiftedCopy(const ruppert::Plc& plc, double dx);

// Appends a closed ring of segments through the points xy (x0, y0, x1, y1, ...) to plc.
void addRing(ruppert::Plc& plc, const std::vector<double>& xy);

// True when closed segments pq and rs share a point (exact predicates). Used to keep generated PLCs clean.
bool segmentsTouch(const double* p, const double* q, const double* r, const double* s);

// --- real inputs ---------------------------------------------------------------------------------
// The shared data folder (RUPPERT_SHARED_DATA from CMake), or "" when it does not exist.
std::string sharedDataDir();
// Sorted paths of the .poly files directly in `dir` (not in subfolders); empty if dir is missing.
std::vector<std::string> polyFilesIn(const std::string& dir);
// The repository's tests/fixtures folder (RUPPERT_FIXTURES from CMake).
std::string fixturesDir();

}  // namespace ruppert_test
