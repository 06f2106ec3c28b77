// What the `ruppert` executable prints about a mesh: the one-line summary, --stats and --trace.
#pragma once

#include <iosfwd>

#include "ruppert/ruppert.h"

namespace ruppert::cli {

// "ruppert: V vertices, T triangles, min angle A, max angle B, complete, M ms", and when the mesh is
// incomplete a second line "incomplete: <reasons>".
void printSummary(std::ostream& out, const Mesh& mesh);

// The Stats fields, the angle histogram folded into 10-degree groups.
void printStats(std::ostream& out, const Stats& stats);

// Mesh::events as JSON lines, one object per insertion, indices 0-based.
void writeTrace(std::ostream& out, const Mesh& mesh);

}  // namespace ruppert::cli
