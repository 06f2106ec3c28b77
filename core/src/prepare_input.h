// Validation and normalisation of a PLC before triangulation.
//
// The whole input is scaled by one power of two so that the largest coordinate magnitude lies in
// [1, 2): exact (no rounding), so output coordinates of input points come back bit-identical, and
// the robust predicates then work in their safe range whatever the user's units (1e-200 or 1e200).
#pragma once

#include <cstdint>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

struct PreparedInput {
  double scale = 1;                        // internal coordinate = input coordinate * scale
  std::vector<double> xy;                  // all input points, scaled (duplicates included)
  std::vector<std::uint32_t> representative;  // per point: the lowest index of an identical point
  std::vector<std::uint32_t> insertionOrder;  // distinct points in a spatially coherent random order
  std::vector<double> holes;               // scaled
  std::vector<Region> regions;             // scaled seeds (maxArea scaled by scale^2)
  double maxArea = 0;                      // scaled; 0 = none
};

// Throws ruppert::Error naming the offending item. Appends DuplicatePoint notices.
PreparedInput prepareInput(const Plc& plc, const Options& options, std::vector<Notice>& notices);

// Human-readable number for messages (shortest round-trip form).
std::string formatNumber(double v);

}  // namespace ruppert::detail
