// Shape families: generated PLCs of the kinds of shape where refinement is judged, each
// parameterised by a seed and a size, used by the refinement tests ("[families]") and, written to
// .poly files by tests/tools/write_shape_families.cpp, by tests/bench/compare-triangle.mjs --dir.
//
// Every member is a valid PLC: segments meet only at shared endpoints, no point lies on a segment
// it is not an end of, no two points coincide, and every hole has a seed strictly inside it.
// Deterministic on every platform: the draws come from SplitMix64 mapped to values by this code
// (no std::*_distribution, whose algorithms differ between standard libraries), each in a statement
// of its own or a braced list (C++ leaves the order of calls among function arguments open, and
// GCC and Clang take them in opposite orders), and every
// coordinate, hole seed and region seed is rounded to a multiple of 2^-20, so an ulp of difference
// in a library's sin or cos cannot change the output (and integer translations are exact).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "plc_generators.h"

namespace ruppert_test {

struct ShapeFamily {
  const char* name;  // kebab-case, used in file names: <name>-<seed>.poly
  const char* what;  // one line for the writer's listing
  GeneratedPlc (*make)(std::uint64_t seed, int size);
  int minSize, maxSize;  // the size parameter's range; the size of a seed is familySize()
};

// Every family, in a fixed order.
const std::vector<ShapeFamily>& shapeFamilies();
// The family of that name, or nullptr.
const ShapeFamily* findShapeFamily(const std::string& name);
// The size a seed gets (drawn from the seed, in [minSize, maxSize]): sizes vary with the seed.
int familySize(const ShapeFamily& family, std::uint64_t seed);
// family.make(seed, familySize(family, seed)).
GeneratedPlc familyMember(const ShapeFamily& family, std::uint64_t seed);

// The PLC as Triangle's .poly text, 0-based, coordinates with 17 significant digits (bit-exact on
// reading back), hole seeds and regions (attribute and max area) included; `comment` (one line) is
// written first after '#'.
std::string plcToPolyText(const ruppert::Plc& plc, const std::string& comment);

// The families one by one (size: see each family's range in shapeFamilies()).
GeneratedPlc skyline(std::uint64_t seed, int buildings);
GeneratedPlc combOfSlots(std::uint64_t seed, int slots);
GeneratedPlc spikyStar(std::uint64_t seed, int spikes);
GeneratedPlc channelWithObstacles(std::uint64_t seed, int obstacles);
GeneratedPlc airfoilInBox(std::uint64_t seed, int pointsPerSurface);
GeneratedPlc serpentineCorridor(std::uint64_t seed, int walls);
GeneratedPlc jitteredSubdivision(std::uint64_t seed, int cellsPerSide);
GeneratedPlc perforatedDisk(std::uint64_t seed, int holes);
GeneratedPlc vNotchedOutline(std::uint64_t seed, int notches);
GeneratedPlc stripWithBumps(std::uint64_t seed, int bumps);
GeneratedPlc pointCloudInSquare(std::uint64_t seed, int points);
GeneratedPlc nestedRings(std::uint64_t seed, int rings);
GeneratedPlc blockLetters(std::uint64_t seed, int letters);
GeneratedPlc gearWithHoles(std::uint64_t seed, int teeth);
GeneratedPlc squareWithCracks(std::uint64_t seed, int cracks);

}  // namespace ruppert_test
