// What the `ruppert` executable prints about a mesh: the one-line summary, --stats and --trace.
// Texts rather than streams: the WebAssembly build prints them too, and links no iostreams.
#pragma once

#include <iosfwd>
#include <string>

#include "ruppert/ruppert.h"

namespace ruppert::cli {

// "ruppert: V vertices, T triangles, min angle A, max angle B, complete, M ms\n", and when the mesh
// is incomplete a second line "incomplete: <reasons>\n".
std::string summaryText(const Mesh& mesh);

// The Stats fields, the angle histogram folded into 10-degree groups.
std::string statsText(const Stats& stats);

// Mesh::events as JSON lines, one object per insertion, indices 0-based: as one text, or streamed
// to `out` in pieces (a trace of millions of events).
std::string traceText(const Mesh& mesh);
void writeTrace(std::ostream& out, const Mesh& mesh);

}  // namespace ruppert::cli
