// Every option of triangulate(), the npm package and the `ruppert` CLI, written once. Options'
// defaults (ruppert.h), the CLI's parsing, usage line and --help (core/cli/cli_args.cpp), the
// binding's heap table (wasm/binding/heap_layout.h, heap_triangulate.cpp) and the package's option
// checks (wasm/input-checks.js, through the description wasm/binding/describe.cpp exports) are all
// made from these lists; index.d.ts, which TypeScript needs spelled out, is compared with them by
// tests/package/names.test.mjs. Included by ruppert.h after the enums and sentinels it names.
//
// Each list calls X(key, flag, fallback, low, high, unit, help) per option:
//   key       its name: the Options member (or CliArgs member), the package's and JSON's key
//   flag      the CLI's spellings, '|' between them, then the value's name if it takes one;
//             "" where the CLI sets it some other way (--trace FILE, --stats) or not at all
//   fallback  the default; its type is the option's (double, count, bool, enum, int)
//   low, high the range of a number, both ends included (kUnbounded: no upper end); 0, 0 otherwise
//   unit      what a number measures, for messages ("degrees in [0, 60]"); "" otherwise
//   help      the CLI's --help, one line that the CLI wraps; {min}, {max} and {default} stand for
//             the numbers above, so that no number is written twice
#pragma once

namespace ruppert {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// Options::smooth's passes where it is asked for without a number (CLI --smooth, smooth: true).
inline constexpr int kSmoothPassesWhenOn = 4;
#define RUPPERT_SMOOTH_PASSES_TEXT "4"  // the same, for the help text
static_assert(RUPPERT_SMOOTH_PASSES_TEXT[0] - '0' == kSmoothPassesWhenOn && RUPPERT_SMOOTH_PASSES_TEXT[1] == '\0');

// triangulate()'s Options that the binding passes as numbers, in the heap table's order; each is
// the ruppert::Options member of that name, of its default's type. What they do, for C++ callers:
//   minAngle     degrees in [low, high]; 0 with maxArea <= 0 and no size function: the plain CDT.
//                Up to 33 degrees refinement ends with every angle met (outside the §6.6
//                exemptions). Above ~34 completion is not guaranteed: the bound search
//                (refine/bound_search/) tries it directly and with capped attempts, else returns
//                the best mesh of a push from the 33-degree mesh with complete = false,
//                ReasonKind::AngleUnreachable and Stats::reachedAngle, never below 33 degrees nor
//                over four times the 33-degree mesh's triangles whenever 33 degrees completes
//                (docs/usage.md, "Above 34 degrees").
//   maxAngle     degrees; 0: no bound; else above 60 and below 180 (checked by triangulate(): the
//                table's range is [0, 180]). No triangle gets a larger angle, outside the §6.6
//                exemptions (nestled in a small input angle, seditious shortest edge), whatever
//                minAngle is: any bound above 60 is compatible with any minAngle (the equilateral
//                triangle meets both), and one at or above 180 - 2 minAngle changes nothing (the
//                smallest angle bound implies it). A triangle over it that meets minAngle is
//                fixed by moving one of its free corners (or sliding one along its segment) where
//                every triangle around it meets both bounds, else by inserting the best of a few
//                points near its longest edge, else its circumcenter (rejected for an encroached
//                subsegment, which is split instead): refine_wide.cpp. Not proved to terminate:
//                the Steiner budget's guard ends it and reports what remains, as for minAngle.
//   maxArea      <= 0: no global area bound.
//   maxSteiner   kAutoSteinerBudget: no fixed count; refinement stops only once its vertices
//                exceed a multiple of the chapter's size measure (§6.5), i.e. when it is not
//                converging. Running out is not an error: complete becomes false.
//   placement, encroachment, variant: the enums above.
//   convexHull   mesh the whole convex hull, not only what segments enclose.
//   autoHoles    with no hole seeds: regions at odd nesting depth are domain, even are holes.
//   trace        record Mesh::events (every insertion, for step-by-step replay).
//   sizeMeasure  compute Stats::lfsIntegral (§6.5; one shortest-path pass over the mesh).
//   exemptions   fill Mesh::triangleExemptions: per triangle, whether §6.6 exempts it, by the rules
//                refinement itself applies (refine/exemptions.h), for pages that draw them.
//   edges        fill Mesh::edges and Mesh::edgeMarkers (meshEdges), after Triangle's -e.
//   noBoundarySteiner  no new vertex on a subsegment of the domain's boundary (Triangle's -Y).
//   noSegmentSteiner   no new vertex on any subsegment (-YY); implies noBoundarySteiner.
//   jettison     leave Unused input points out of Mesh::points (-j), see Mesh::inputToOutput.
//   smooth       passes of smoothing after refinement (smooth/smooth.h): free vertices move towards
//                the area-weighted mean of their star's circumcenters (optimal Delaunay
//                triangulation), flips restore the constrained Delaunay property, and a move stays
//                only if every triangle it changed keeps the angle bound (or its star's old smallest
//                angle, if lower) and every area bound. Segments, input points and vertices on
//                segments stay; the triangle count stays. 0: none. The CLI's --smooth and the
//                package's smooth: true mean kSmoothPassesWhenOn.
//   curveTolerance  Plc::curves: the largest distance from a boundary edge to the curve it
//                follows (user units); <= 0: 1e-3 of the diagonal of the input points' bounding
//                box. Pieces are split until each is within it.
#define RUPPERT_MESH_OPTIONS(X)                                                                          \
  X(minAngle, "--min-angle DEG", 30.0, 0, 60, "degrees",                                                \
    "smallest angle to reach, {min}..{max} (default {default}); above 34, where out of reach: the best "  \
    "mesh reached (at least 33 degrees), marked incomplete")                                             \
  X(maxAngle, "--max-angle DEG", 0.0, 0, 180, "degrees",                                                 \
    "largest angle allowed, above 60 and below 180 (default 0: no bound), section 6.6's exemptions "      \
    "aside; where out of reach, the mesh is marked incomplete")                                          \
  X(maxArea, "--max-area A", 0.0, 0, kUnbounded, "area",                                                 \
    "largest triangle area (default: no bound); --min-angle 0 without --max-area gives the plain "        \
    "constrained Delaunay triangulation")                                                                \
  X(maxSteiner, "--max-steiner N", kAutoSteinerBudget, 0, kUnbounded, "vertices",                              \
    "at most N new vertices (default: automatic)")                                                       \
  X(placement, "--placement P", Placement::Optimal, 0, 0, "",                                            \
    "optimal (default: off-centers, but where one would make a skinny triangle the point maximising "     \
    "the smallest new angle; the fewest triangles, and 35-40 degrees), offcenter (faster), circumcenter, " \
    "or petal (a point of the shortest edge's petal there)")                                             \
  X(encroachment, "--encroachment E", Encroachment::DiametralLens, 0, 0, "",                             \
    "lens (default: diametral lenses) or disk (closed diametral disks)")                                 \
  X(variant, "--variant V", Variant::Constrained, 0, 0, "",                                              \
    "cdt (default: constrained, no triangles outside the domain) or box (Ruppert's original: "            \
    "conforming mesh of an enclosing box)")                                                              \
  X(convexHull, "--convex-hull", false, 0, 0, "", "mesh the whole convex hull, not only what segments enclose") \
  X(autoHoles, "--auto-holes", false, 0, 0, "", "without hole seeds: regions at even nesting depth become holes") \
  X(trace, "", false, 0, 0, "", "")                                                                      \
  X(sizeMeasure, "", false, 0, 0, "", "")                                                                \
  X(exemptions, "", false, 0, 0, "", "")                                                                 \
  X(edges, "-e|--edges", false, 0, 0, "",                                                                \
    "also write BASE.edge: every edge once, with its boundary marker (triangle format only)")             \
  X(noBoundarySteiner, "--no-boundary-steiner", false, 0, 0, "",                                         \
    "no new vertex on the domain's boundary (Triangle's -Y); what quality that leaves unreachable is "    \
    "reported, not looped over")                                                                         \
  X(noSegmentSteiner, "--no-segment-steiner", false, 0, 0, "", "no new vertex on any segment (Triangle's -YY)") \
  X(jettison, "-j|--jettison", false, 0, 0, "",                                                          \
    "leave unused input points (merged duplicates, points outside the domain) out of the output; the "    \
    "others are renumbered in order")                                                                    \
  X(curveTolerance, "--curve-tolerance T", 0.0, 0, kUnbounded, "length",                                 \
    "largest distance from a boundary edge to the curve it follows (JSON curves; default: 1e-3 of the "   \
    "input's bounding-box diagonal)")                                                                  \
  X(smooth, "--smooth [N]", 0, 0, 100, "passes",                                                          \
    "after refinement, N passes (alone: " RUPPERT_SMOOTH_PASSES_TEXT ") of optimal-Delaunay moves of "    \
    "free vertices, with flips: rounder triangles, the same count and sizes, every bound kept")

// Outputs derived from the mesh after triangulate() (ruppert.h's addQuadraticNodes, voronoiDiagram):
// the package's options and the CLI's flags, not Options members.
#define RUPPERT_DERIVED_OPTIONS(X)                                                                       \
  X(order, "--order 1|2", 1, 1, 2, "",                                                                   \
    "2 for quadratic triangles (default {default}): .ele gets 6 nodes per triangle (corners, then the "   \
    "midpoints of the edges opposite them), .node the midpoints after the corners")                                             \
  X(voronoi, "--voronoi", false, 0, 0, "", "also write the dual: BASE.v.node (circumcenters) and BASE.v.edge")

// Options members that are functions: the package takes JavaScript functions, the CLI has none.
#define RUPPERT_CALLBACK_OPTIONS(X)             \
  X(sizeFunction, "", nullptr, 0, 0, "", "")   \
  X(onProgress, "", nullptr, 0, 0, "", "")

#define RUPPERT_ALL_OPTIONS(X) RUPPERT_MESH_OPTIONS(X) RUPPERT_DERIVED_OPTIONS(X) RUPPERT_CALLBACK_OPTIONS(X)

// option::minAngle::fallback, ::low, ::flag, ...: one type per option, so that code which needs one
// option's default or range names it, and code over all of them is a template over these types.
namespace option {
#define RUPPERT_OPTION_TYPE_(KEY, FLAG, FALLBACK, LOW, HIGH, UNIT, HELP) \
  struct KEY {                                                         \
    static constexpr const char* key = #KEY;                           \
    static constexpr const char* flag = FLAG;                          \
    static constexpr auto fallback = FALLBACK;                         \
    static constexpr double low = LOW, high = HIGH;                    \
    static constexpr const char* unit = UNIT;                          \
    static constexpr const char* help = HELP;                          \
  };
RUPPERT_ALL_OPTIONS(RUPPERT_OPTION_TYPE_)
#undef RUPPERT_OPTION_TYPE_
}  // namespace option

// The names of an enum option's values (the tables beside the enums), for the CLI and the binding.
constexpr const auto& valueNames(Placement) { return kPlacementNames; }
constexpr const auto& valueNames(Encroachment) { return kEncroachmentNames; }
constexpr const auto& valueNames(Variant) { return kVariantNames; }

}  // namespace ruppert
