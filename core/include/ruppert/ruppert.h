// ruppert — 2D quality triangle meshing by Delaunay refinement.
//
// This header is the manual. Everything a caller can use is declared here, with the layout of every
// buffer. Conventions that hold throughout:
//   * Coordinates are interleaved doubles: points = { x0, y0, x1, y1, ... }.
//   * Indices are 0-based uint32 unless a field says otherwise.
//   * Triangles are counter-clockwise (positive orientation in a y-up frame).
//   * Edge i of triangle t is the edge opposite its vertex triangles[3t+i], i.e. it runs from
//     triangles[3t+(i+1)%3] to triangles[3t+(i+2)%3]; neighbors[3t+i] is the triangle across it.
//   * Sentinels are named constants (kNoNeighbor, kNoInputSegment), never bare -1.
//   * Errors are thrown as ruppert::Error with a stable ErrorCode and a message naming the item
//     (index and value). Nothing here calls exit() or keeps global state.
//
// Chapter references (Cheng, Dey & Shewchuk, "Delaunay Mesh Generation", ch. 6) are given as §6.x.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace ruppert {

// ---------------------------------------------------------------------------------------------
// Sentinels
// ---------------------------------------------------------------------------------------------
inline constexpr std::int32_t kNoNeighbor = -1;      // neighbors[]: edge on the domain boundary
inline constexpr std::int32_t kNoInputSegment = -1;  // segmentIds[]: convex-hull edge added by us
inline constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;  // Event vertex ids not in the output
inline constexpr std::uint64_t kAutoSteinerBudget = std::numeric_limits<std::uint64_t>::max();

// ---------------------------------------------------------------------------------------------
// Names
// ---------------------------------------------------------------------------------------------
// Every enum below has its names written once, in a table beside it (k...Names, in the enum's order)
// and read through enumName(). The CLI prints them, and the WebAssembly binding exports the tables to
// the npm package (wasm/binding/describe.cpp), whose constants, option checks and index.d.ts use the
// same names (tests/package/names.test.mjs compares them). A published name never changes; a new
// enumerator gets a new name at the end of its table.
namespace detail {
template <class Enum, std::size_t N>
constexpr const char* nameIn(const char* const (&names)[N], Enum value, int first = 0) {
  const int i = static_cast<int>(value) - first;
  return i >= 0 && i < static_cast<int>(N) ? names[i] : "UNKNOWN";  // never null, even for a bad cast
}
template <std::size_t N>
constexpr std::size_t countOf(const char* const (&)[N]) { return N; }
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------------------------
enum class ErrorCode : int {
  EmptyInput = 1,          // no points at all
  NonFiniteCoordinate,     // NaN or +-Inf in points, holes or regions
  CoordinateRange,         // a coordinate whose magnitude the exact predicates cannot handle
  IndexOutOfRange,         // a segment refers to a point that does not exist
  DegenerateInput,         // fewer than 3 distinct points, or all points collinear
  HoleOnSegment,           // a hole seed lies exactly on a segment or vertex
  InvalidRegion,           // a region with NaN/negative max area, or seed on a segment
  InvalidOption,           // min angle out of [0, 60], negative max area, ...
  ParseError,              // malformed .poly/.node/.json text (line and field named)
  IoError,                 // a file could not be read or written
  TooLarge,                // a count that cannot be allocated (e.g. 10^12 points declared)
  Cancelled,               // the progress callback asked to stop (only thrown before a mesh exists)
  MalformedInput,          // wrong shape: odd-length coordinate arrays, non-integer indices, wrong types
  EmptyDomain,             // hole seeds remove everything (a hole's boundary is not closed)
  Internal,                // a bug: please report the input
};
// ErrorCode's names, from EmptyInput (1) on.
inline constexpr const char* kErrorCodeNames[] = {
    "EMPTY_INPUT", "NON_FINITE_COORDINATE", "COORDINATE_RANGE", "INDEX_OUT_OF_RANGE", "DEGENERATE_INPUT",
    "HOLE_ON_SEGMENT", "INVALID_REGION", "INVALID_OPTION", "PARSE_ERROR", "IO_ERROR", "TOO_LARGE", "CANCELLED",
    "MALFORMED_INPUT", "EMPTY_DOMAIN", "INTERNAL"};
static_assert(detail::countOf(kErrorCodeNames) == static_cast<std::size_t>(ErrorCode::Internal));
constexpr const char* enumName(ErrorCode code) { return detail::nameIn(kErrorCodeNames, code, 1); }

// Stable upper-case name, e.g. "INDEX_OUT_OF_RANGE" (enumName(code)); used as MeshError.code in JavaScript.
const char* errorCodeName(ErrorCode code);

class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const { return code_; }

 private:
  ErrorCode code_;
};

// ---------------------------------------------------------------------------------------------
// Input: a planar straight-line graph (PLC)
// ---------------------------------------------------------------------------------------------
struct Region {
  double x = 0, y = 0;      // seed point inside the region
  double attribute = 0;     // copied to every triangle of the region (Mesh::triangleAttributes)
  double maxArea = 0;       // <= 0: no area bound in this region; otherwise an upper bound
};

// A curved boundary piece between two input points. It bounds regions, holes and the
// domain exactly as a segment does; refinement splits it at points on the curve (its parameter
// midpoint, rounded to the nearest doubles), so every vertex of its pieces lies on the curve.
enum class CurveType : std::uint8_t {
  Arc = 0,     // counter-clockwise from `from` to `to` around `center`; both points at the same
               // distance from it (within a relative 1e-9: rounding); a full circle is two arcs
  Bezier = 1,  // the cubic from `from` to `to` with the two inner control points `controls`
};
inline constexpr const char* kCurveTypeNames[] = {"arc", "bezier"};  // Curve's "type" in JSON and JavaScript
static_assert(detail::countOf(kCurveTypeNames) == 1 + static_cast<std::size_t>(CurveType::Bezier));
constexpr const char* enumName(CurveType t) { return detail::nameIn(kCurveTypeNames, t); }

struct Curve {
  CurveType type = CurveType::Arc;
  std::uint32_t from = 0, to = 0;   // point indices (distinct)
  double center[2] = {0, 0};        // Arc
  double controls[4] = {0, 0, 0, 0};  // Bezier: x1, y1, x2, y2
  std::int32_t marker = 0;          // boundary marker of its pieces, as Plc::segmentMarkers
};

struct Plc {
  std::vector<double> points;           // x0, y0, x1, y1, ...
  std::vector<std::uint32_t> segments;  // a0, b0, a1, b1, ... indices into points
  // Curved boundaries (Curve above). Their pieces are the mesh's subsegments like segments' pieces,
  // with Mesh::segmentIds = segments.size() / 2 + the curve's index. Not with `triangles`.
  std::vector<Curve> curves;
  std::vector<double> holes;            // hole seeds: hx0, hy0, hx1, hy1, ...
  std::vector<Region> regions;
  // Boundary markers (Triangle's): tags a solver uses to find its boundary conditions; may be empty
  // (all 0). The mesh's markers follow from them, see "Boundary markers" at Mesh.
  std::vector<std::int32_t> pointMarkers;    // one per point, or empty
  std::vector<std::int32_t> segmentMarkers;  // one per segment, or empty
  // Per-point attributes (a .node's attribute columns): attributesPerPoint values per point, point
  // after point, or empty. Interpolated linearly onto every new vertex (Mesh::pointAttributes).
  std::uint32_t attributesPerPoint = 0;
  std::vector<double> pointAttributes;
  int indexBase = 0;  // 0 or 1: the index base the file used; writers print indices in this base
  // Refining a mesh (Triangle's -r, with -a and a .area file): when `triangles` is not empty, the
  // domain is the union of these triangles (3 point indices each, either orientation, none of zero
  // area), and segments are the given ones plus every boundary edge of this mesh (an edge of one
  // triangle only) that is not among them, numbered after them (Mesh::segmentIds); holes and regions
  // apply as usual. The mesh is refined under the usual options. triangleMaxArea: empty, or one
  // maximum area per triangle (<= 0 or +inf: none). The rule: a new triangle's bound is the smallest
  // bound among the old triangles whose interiors meet its interior (exact tests), so every triangle
  // of the result lying within an old triangle meets that triangle's bound (its area computed in
  // doubles; refinement aims a relative 1e-9 below the bound against rounding) when complete.
  std::vector<std::uint32_t> triangles;
  std::vector<double> triangleMaxArea;
};

// ---------------------------------------------------------------------------------------------
// Options
// ---------------------------------------------------------------------------------------------
enum class Placement : std::uint8_t {
  Circumcenter = 0,  // Ruppert's rule (§6.2)
  OffCenter = 1,     // Üngör's off-centers (§6.8): fewer triangles at the same angle
  Petal = 2,         // off-centers, but where one would itself make a skinny triangle, the point of
                     // the shortest edge's petal that makes none and lies farthest from its
                     // neighbors (after Erten and Üngör): fewer triangles still, slower without an
                     // area bound (with one it is the same as OffCenter)
  Optimal = 3,       // the default: off-centers, but where one would itself make a skinny triangle,
                     // the point that maximises the smallest angle of the triangles it makes (Erten
                     // and Üngör's locally optimal Steiner point), if that angle meets the bound, and
                     // relocation of free vertices: the fewest triangles, and bounds of 35-40 degrees,
                     // which off-centers rarely reach (with an area bound it places as OffCenter)
};
// The CLI's --placement and JavaScript's options.placement.
inline constexpr const char* kPlacementNames[] = {"circumcenter", "offcenter", "petal", "optimal"};
static_assert(detail::countOf(kPlacementNames) == 1 + static_cast<std::size_t>(Placement::Optimal));
constexpr const char* enumName(Placement p) { return detail::nameIn(kPlacementNames, p); }

// When a vertex v encroaches a subsegment ab (and so ab is split, or v rejected).
enum class Encroachment : std::uint8_t {
  DiametralDisk = 0,  // v in the closed disk with diameter ab: angle avb >= 90 degrees (§6.2, Def. 6.1)
  DiametralLens = 1,  // angle avb >= max(90, 180 - 2 minAngle) degrees: a lens inside that disk
                      // (Chew; §6.8). Fewer segment splits: fewer triangles, and refinement completes at
                      // higher angles in practice.
};
inline constexpr const char* kEncroachmentNames[] = {"disk", "lens"};  // --encroachment, options.encroachment
static_assert(detail::countOf(kEncroachmentNames) == 1 + static_cast<std::size_t>(Encroachment::DiametralLens));
constexpr const char* enumName(Encroachment e) { return detail::nameIn(kEncroachmentNames, e); }

enum class Variant : std::uint8_t {
  Constrained = 0,   // constrained Delaunay refinement (§6.7): no triangles outside the domain
  BoundingBox = 1,   // Ruppert's original: conforming Delaunay mesh of an enclosing box (§6.3, Fig 6.16)
};
inline constexpr const char* kVariantNames[] = {"cdt", "box"};  // --variant, options.variant
static_assert(detail::countOf(kVariantNames) == 1 + static_cast<std::size_t>(Variant::BoundingBox));
constexpr const char* enumName(Variant v) { return detail::nameIn(kVariantNames, v); }

}  // namespace ruppert

// The options' keys, CLI flags, defaults, ranges and help, written once, after the enums they name.
#include "ruppert/option_table.h"

namespace ruppert {

struct Progress {
  std::uint64_t insertedVertices = 0;
  std::uint64_t triangles = 0;
  double worstAngle = 0;  // degrees: smallest angle among triangles still queued as bad
};

// One member per entry of option_table.h's RUPPERT_MESH_OPTIONS, of its default's type and value;
// what each one does is written there, beside its name, default and range.
struct Options {
#define RUPPERT_OPTION_MEMBER_(KEY, FLAG, FALLBACK, ...) std::decay_t<decltype(FALLBACK)> KEY = FALLBACK;
  RUPPERT_MESH_OPTIONS(RUPPERT_OPTION_MEMBER_)
#undef RUPPERT_OPTION_MEMBER_
  // Optional size field: max triangle area at (x, y); return <= 0 or +inf for "no bound here".
  std::function<double(double x, double y)> sizeFunction;
  // Called every few thousand insertions; return false to stop early (complete=false, "cancelled").
  std::function<bool(const Progress&)> onProgress;
};
// The table's callbacks are members too.
#define RUPPERT_OPTION_IS_MEMBER_(KEY, ...) static_assert(sizeof(Options::KEY) > 0);
RUPPERT_CALLBACK_OPTIONS(RUPPERT_OPTION_IS_MEMBER_)
#undef RUPPERT_OPTION_IS_MEMBER_

// ---------------------------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------------------------
enum class VertexKind : std::uint8_t {
  Input = 0,         // an input point that the mesh uses
  SegmentSplit = 1,  // inserted on a segment (encroachment midpoint or concentric-shell split)
  Interior = 2,      // circumcenter of a skinny or large triangle
  OffCenter = 3,     // off-center of a skinny triangle (§6.8), or of one over its area bound
  Intersection = 4,  // where two input segments cross (repair of the input)
  Unused = 5,        // an input point no triangle uses: a merged duplicate, or outside the domain
};
// JavaScript's VertexKind keys.
inline constexpr const char* kVertexKindNames[] = {"INPUT", "SEGMENT_SPLIT", "INTERIOR", "OFF_CENTER",
                                                   "INTERSECTION", "UNUSED"};
static_assert(detail::countOf(kVertexKindNames) == 1 + static_cast<std::size_t>(VertexKind::Unused));
constexpr const char* enumName(VertexKind k) { return detail::nameIn(kVertexKindNames, k); }

// What the input repair did; the mesh is valid, but the caller should know. The rules:
//   * Duplicate points are merged; zero-length and duplicate segments are dropped.
//   * A point lying exactly on a segment's interior splits it there (VertexOnSegment).
//   * Two segments that cross are both split at their crossing, a new Intersection vertex rounded
//     to the nearest doubles (SegmentsCross); collinear segments share their common piece.
//   * Segments that meet at a tiny angle or nearly overlap (sharing an endpoint, or ending a hair
//     apart) stay two constrained chains all the way, however small the angle: the sliver between
//     them is meshed, and refinement leaves the triangles it cannot improve there as SmallInputAngle
//     or SeditiousEdge reasons. They are merged only within rounding: a vertex counts as on a piece
//     of a segment within 2^-48 (about 16 ulps) of the larger of the coordinates' magnitude and the
//     shorter segment's length, and a crossing within 2^-40 of the largest coordinate magnitude of
//     such a vertex is that vertex. Where this makes two segments share subsegments, a SegmentsOverlap notice names both
//     segments and the stretch between the shared subsegments' extreme vertices.
enum class NoticeKind : std::uint8_t {
  DuplicatePoint,      // a = duplicate point index, b = the point it was merged into
  ZeroLengthSegment,   // a = segment index (dropped)
  DuplicateSegment,    // a = segment index, b = the earlier identical segment (dropped)
  VertexOnSegment,     // a = segment index, b = point index lying in its interior (split there)
  SegmentsCross,       // a, b = the two segment indices; x, y = the crossing point (both split)
  SegmentsOverlap,     // a < b = the two segment indices sharing subsegments (a collinear piece, or a
                       // stretch within rounding of each other); x, y = one end of the shared stretch
  HoleOutsideDomain,   // a = hole index: it lies outside the domain and removes nothing
  RegionOutsideDomain, // a = region index
  NothingEnclosed,     // the segments enclose no region: the convex hull was meshed instead
};
// Notice::kind in JavaScript.
inline constexpr const char* kNoticeKindNames[] = {
    "DUPLICATE_POINT", "ZERO_LENGTH_SEGMENT", "DUPLICATE_SEGMENT", "VERTEX_ON_SEGMENT", "SEGMENTS_CROSS",
    "SEGMENTS_OVERLAP", "HOLE_OUTSIDE_DOMAIN", "REGION_OUTSIDE_DOMAIN", "NOTHING_ENCLOSED"};
static_assert(detail::countOf(kNoticeKindNames) == 1 + static_cast<std::size_t>(NoticeKind::NothingEnclosed));
constexpr const char* enumName(NoticeKind k) { return detail::nameIn(kNoticeKindNames, k); }

struct Notice {
  NoticeKind kind;
  std::int64_t a = -1, b = -1;
  double x = 0, y = 0;
  std::string message;  // human-readable, names indices and values
};

// Why a refinement did not reach every bound.
enum class ReasonKind : std::uint8_t {
  SmallInputAngle,  // triangles nestled in an input angle < 60 deg cannot be fixed (§6.6)
  SeditiousEdge,    // triangles whose shortest edge is seditious (between segments meeting at under
                    // 45 degrees, §6.6) are left alone on purpose
  SteinerBudget,    // maxSteiner reached
  PrecisionFloor,   // an edge would become shorter than doubles can place points on
  Cancelled,        // onProgress returned false
  AngleUnreachable, // minAngle above 34: refinement met 33 degrees, raised the bound a degree at a
                    // time while the mesh improved, and stopped short; the mesh is the best it
                    // reached (Stats::reachedAngle), never worse than the 33-degree mesh
  SegmentSplitForbidden,  // Options::noBoundarySteiner / noSegmentSteiner: triangles left bad because
                          // the only cure was a vertex on a subsegment that may not be split (count:
                          // those triangles; the message also says how many splits were refused)
};
// Reason::kind in JavaScript.
inline constexpr const char* kReasonKindNames[] = {
    "SMALL_INPUT_ANGLE", "SEDITIOUS_EDGE", "STEINER_BUDGET", "PRECISION_FLOOR", "CANCELLED", "ANGLE_UNREACHABLE",
    "SEGMENT_SPLIT_FORBIDDEN"};
static_assert(detail::countOf(kReasonKindNames) == 1 + static_cast<std::size_t>(ReasonKind::SegmentSplitForbidden));
constexpr const char* enumName(ReasonKind k) { return detail::nameIn(kReasonKindNames, k); }

struct Reason {
  ReasonKind kind;
  std::uint64_t count = 0;  // how many triangles or subsegments remain because of it
  std::string message;
};

struct Stats {
  std::uint64_t vertices = 0;  // vertices used by triangles
  std::uint64_t triangles = 0;
  double minAngle = 0, maxAngle = 0;  // degrees, over all triangles
  // Degrees: the smallest angle over the triangles the angle bound applies to (those in small input
  // angles and on seditious edges, §6.6, left out): >= Options::minAngle when complete, and what
  // was reached when the bound was out of reach (ReasonKind::AngleUnreachable).
  double reachedAngle = 0;
  std::vector<std::uint64_t> angleHistogram;  // 180 bins of 1 degree over all 3 angles of every triangle
  std::uint64_t inputVertices = 0, segmentVertices = 0, interiorVertices = 0, offCenterVertices = 0,
                intersectionVertices = 0;
  std::uint64_t rejectedCircumcenters = 0;
  // Estimate of the integral of 1/lfs^2 over the domain (§6.5), with the size-measure option (option_table.h); else 0.
  // lfs is bounded from above from the mesh (see size_measure.cpp), so this tends to be low.
  double lfsIntegral = 0;
  double trianglesPerLfsIntegral = 0;
  double milliseconds = 0;  // wall time of triangulate()
};

enum class EventKind : std::uint8_t {
  SegmentSplit = 0,  // a subsegment (a,b) encroached by vertex `by` was split at (x, y)
  Circumcenter = 1,  // circumcenter of skinny/large triangle (t0,t1,t2) inserted at (x, y)
  OffCenter = 2,     // off-center of triangle (t0,t1,t2) inserted at (x, y)
  Rejected = 3,      // circumcenter (cx, cy) of (t0,t1,t2) encroached subsegment (a,b): it was split at (x, y)
  // Placement::Petal and Placement::Optimal: the point they chose for (t0,t1,t2) instead of the
  // off-center, inserted at (x, y). Never rejected: both choose only points that encroach nothing.
  PetalPoint = 4,
  OptimalPoint = 5,
  // Placement::Optimal, where no point meets the bound for (t0,t1,t2): an endpoint of its shortest
  // edge, `vertex` (a free vertex refinement placed), moved from (cx, cy) to (x, y). No vertex is
  // added; the move counts against the Steiner budget like an insertion.
  Relocated = 6,
};
// JavaScript's EventKind keys; the CLI's --trace file spells them in camelCase ("segmentSplit").
inline constexpr const char* kEventKindNames[] = {"SEGMENT_SPLIT", "CIRCUMCENTER", "OFF_CENTER", "REJECTED",
                                                  "PETAL_POINT", "OPTIMAL_POINT", "RELOCATED"};
static_assert(detail::countOf(kEventKindNames) == 1 + static_cast<std::size_t>(EventKind::Relocated));
constexpr const char* enumName(EventKind k) { return detail::nameIn(kEventKindNames, k); }

// Mesh::triangleExemptions' values: a triangle that meets the bounds (or is not exempt), one whose
// smallest angle is an input angle (both edges there are subsegments), one whose shortest edge is
// seditious (between split vertices of segments meeting at under 45 degrees, on one shell).
inline constexpr std::uint8_t kNotExempt = 0, kExemptSmallInputAngle = 1, kExemptSeditiousEdge = 2;

// Vertex ids are indices into Mesh::points, or kNoVertex for a vertex that is not in the output (in
// the bounding-box variant, vertices inserted outside the domain are removed with it).
struct Event {
  EventKind kind;
  std::uint32_t vertex = 0;          // id of the vertex inserted (Relocated: moved)
  double x = 0, y = 0;               // where
  std::uint32_t a = 0, b = 0;        // subsegment endpoints (SegmentSplit, Rejected)
  std::int64_t by = -1;              // encroaching vertex (SegmentSplit), -1 if none
  std::uint32_t t0 = 0, t1 = 0, t2 = 0;  // skinny triangle's vertices (all but SegmentSplit)
  double cx = 0, cy = 0;             // rejected circumcenter (Rejected); where the vertex was (Relocated)
};

// Boundary markers (Triangle's convention), in Mesh::pointMarkers, segmentMarkers and edgeMarkers:
//   * a subsegment or edge that is part of an input segment with a nonzero marker has that marker;
//     else 1 if it lies on the mesh's boundary (outer boundary or a hole's), else 0;
//   * a point with a nonzero input marker keeps it; else a vertex on an input segment with a nonzero
//     marker (its endpoints and every vertex inserted on it) has that marker (on several such
//     segments: the one of the lowest segment index); else 1 on the mesh's boundary, else 0.
// So without any input markers boundary vertices and edges get 1 and interior ones 0.
struct Mesh {
  std::vector<double> points;             // input points first, same indices; then the new vertices
                                          // that triangles use, in the order they were inserted
  std::vector<std::uint32_t> triangles;   // 3 vertex indices per triangle, CCW
  std::vector<std::int32_t> neighbors;    // 3 per triangle, see conventions; kNoNeighbor on the boundary
  std::vector<std::uint32_t> segments;    // 2 per subsegment: every input segment is a chain of these
  std::vector<std::int32_t> segmentIds;   // 1 per subsegment: input segment index, segments.size()/2
                                          // + c for a piece of Plc::curves[c], or kNoInputSegment
  std::vector<std::uint8_t> vertexKinds;  // 1 per point: VertexKind
  std::vector<double> triangleAttributes; // 1 per triangle: its region's attribute (0 outside regions)
  std::vector<std::int32_t> pointMarkers; // 1 per point: boundary markers (see above)
  std::vector<std::int32_t> segmentMarkers; // 1 per subsegment: boundary markers (see above)
  // With Options::edges (else empty): every edge of the mesh once, 2 vertex indices each, in the order
  // meshEdges() gives them, and its boundary marker.
  std::vector<std::uint32_t> edges;
  std::vector<std::int32_t> edgeMarkers;
  // Plc::attributesPerPoint values per point: an input point's own; a new vertex's interpolated
  // linearly from the triangle it was inserted in (barycentric), or from the ends of the subsegment
  // it split, so a linear field given at the input points is reproduced at every vertex.
  std::uint32_t attributesPerPoint = 0;
  std::vector<double> pointAttributes;
  // With Options::jettison (else empty, and an input point's index in points is its own): 1 per input
  // point, its index in points: a merged duplicate maps to the point it was merged into, a point
  // outside the domain (or otherwise unused) to -1. Unused points are then left out of points, and
  // every other array is numbered accordingly.
  std::vector<std::int32_t> inputToOutput;
  // With Options::exemptions (else empty): 1 per triangle, why refinement left it below the angle
  // bounds on purpose (§6.6): kNotExempt, kExemptSmallInputAngle or kExemptSeditiousEdge.
  std::vector<std::uint8_t> triangleExemptions;
  int indexBase = 0;                      // copied from the input, for writers
  bool complete = true;                   // every bound met, except the chapter's exemptions (§6.6)
  std::vector<Reason> reasons;            // what is unmet and why; SmallInputAngle / SeditiousEdge
                                          // entries are exemptions and may appear when complete
  std::vector<Notice> notices;            // repairs made to the input
  Stats stats;
  std::vector<Event> events;              // only with Options::trace
  // Quadratic elements (addQuadraticNodes): 6 per triangle, empty otherwise.
  std::vector<std::uint32_t> triangles6;
};

// Mesh a PLC. Throws ruppert::Error on input that cannot be repaired.
Mesh triangulate(const Plc& plc, const Options& options = {});

// Every edge of a mesh once (from triangles and neighbors): for each triangle t and edge i, the edge
// from triangles[3t+(i+1)%3] to triangles[3t+(i+2)%3] when neighbors[3t+i] is kNoNeighbor or > t.
// So there are (3 T + B) / 2 edges for T triangles and B boundary edges. Markers as above (from
// mesh.segments and mesh.segmentMarkers).
struct MeshEdges {
  std::vector<std::uint32_t> edges;   // 2 vertex indices per edge
  std::vector<std::int32_t> markers;  // 1 per edge
};
MeshEdges meshEdges(const Mesh& mesh);

// ---------------------------------------------------------------------------------------------
// Readers and writers (Triangle's .node/.poly/.ele, JSON, SVG)
// ---------------------------------------------------------------------------------------------
// .poly: Triangle's format (comments '#', 0- or 1-based indices, attributes, markers, holes, regions).
Plc readPoly(std::istream& in, const std::string& name = "<poly>");
// .node: points only (attributes and markers allowed).
Plc readNode(std::istream& in, const std::string& name = "<node>");
// JSON: { "points": [x0,y0,...], "segments": [a0,b0,...], "holes": [x,y,...],
//         "regions": [{"x":..,"y":..,"attribute":..,"maxArea":..}],
//         "pointMarkers": [...], "segmentMarkers": [...], "pointAttributes": [...], "attributesPerPoint": k,
//         "curves": [{"type": "arc", "from": i, "to": j, "center": [x, y], "marker": m},
//                    {"type": "bezier", "from": i, "to": j, "controls": [x1, y1, x2, y2]}] }
// (markers one per point / segment; attributes k per point, k defaulting to their count / points)
Plc readJson(std::istream& in, const std::string& name = "<json>");
// By extension: .poly, .node, .json or .geojson. Throws IoError if unreadable.
Plc readFile(const std::string& path);
// The same readers over text already in memory (`name` appears in error messages).
Plc parsePoly(const std::string& text, const std::string& name = "<poly>");
Plc parseNode(const std::string& text, const std::string& name = "<node>");
Plc parseJson(const std::string& text, const std::string& name = "<json>");
// Triangle's .poly that declares 0 points, with the text of its .node file, which holds them (as
// readFile does for files; the .node text is used only when the .poly declares 0 points).
Plc parsePolyWithNode(const std::string& polyText, const std::string& nodeText,
                      const std::string& polyName = "<poly>", const std::string& nodeName = "<node>");

// Writers print coordinates with 17 significant digits (they read back bit-exact) and indices in
// mesh.indexBase.
void writeNode(std::ostream& out, const Mesh& mesh);
void writeEle(std::ostream& out, const Mesh& mesh);
void writePoly(std::ostream& out, const Mesh& mesh, const Plc& input);  // subsegments + input holes/regions
void writeJson(std::ostream& out, const Mesh& mesh, const Plc& input);  // input JSON shape + "triangles" etc.
void writeSvg(std::ostream& out, const Mesh& mesh);
// .edge: Triangle's format ("count 1", then index, two endpoints, marker), every edge once: the mesh's
// edges if it has them, else meshEdges(mesh).
void writeEdge(std::ostream& out, const Mesh& mesh);
std::string toEdge(const Mesh& mesh);

// ---------------------------------------------------------------------------------------------
// Derived outputs: quadratic elements and the Voronoi diagram (Triangle's -o2 and -v)
// ---------------------------------------------------------------------------------------------
// Quadratic (6-node) triangles: appends one node per mesh edge, at its midpoint (a/2 + b/2 in
// doubles: the correctly rounded midpoint), to mesh.points after the corner vertices, numbered in
// the order the edges first appear in mesh.triangles (triangle by triangle, edges 0, 1, 2), one node
// shared by the two triangles of an interior edge: V + E nodes in all. Fills mesh.triangles6: per
// triangle its three corners (counter-clockwise, as in triangles), then the midpoints of the edges
// opposite corners 0, 1 and 2 (Triangle's -o2 order). pointMarkers gets one marker per new node: a
// subsegment's marker (segmentMarkers) on a subsegment, 1 on another boundary edge, 0 inside (first
// filled for the corners by Triangle's convention, 1 on subsegments, when empty); pointAttributes
// the mean of the edge's ends' (linear interpolation), when the mesh has attributes. vertexKinds,
// neighbors and stats stay about the corners. writeEle writes 6-node triangles when triangles6 is
// filled. Call it once, on a mesh with its neighbors (as
// triangulate() returns it: the shared nodes are found through them).
void addQuadraticNodes(Mesh& mesh);

// The dual of the mesh: one vertex per triangle (its circumcenter, which in a constrained mesh may
// lie outside its triangle and even outside the domain) and one edge per mesh edge, the edges in
// the order they first appear in mesh.triangles (triangle by triangle, edges 0, 1, 2). An interior
// edge's dual joins the circumcenters of its two triangles; a boundary edge's dual is a ray from its
// triangle's circumcenter along the edge's outward normal (edge b - a rotated clockwise: its length
// is the edge's). It is the Voronoi diagram of the vertices only where the mesh is Delaunay (not
// merely constrained Delaunay). Needs mesh.neighbors, as triangulate() returns them.
struct Voronoi {
  std::vector<double> points;          // 2 per triangle: circumcenter x, y
  std::vector<std::int32_t> edges;     // 2 per mesh edge: Voronoi vertex indices; the second is -1 for a ray
  std::vector<double> rayDirections;   // 2 per mesh edge: the ray's direction, 0 0 for a finite edge
  std::vector<std::uint32_t> meshEdges;  // 2 per mesh edge: the mesh edge each dual edge crosses
};
Voronoi voronoiDiagram(const Mesh& mesh);
// Triangle's .v.node (the circumcenters, no attributes or markers) and .v.edge (rays as
// "<edge #> <vertex> -1 <dx> <dy>"), indices in mesh.indexBase.
void writeVoronoiNode(std::ostream& out, const Voronoi& voronoi, const Mesh& mesh);
void writeVoronoiEdge(std::ostream& out, const Voronoi& voronoi, const Mesh& mesh);
std::string toVoronoiNode(const Voronoi& voronoi, const Mesh& mesh);
std::string toVoronoiEdge(const Voronoi& voronoi, const Mesh& mesh);

// Refining a mesh: Triangle's .ele (3 or more nodes per triangle: the first three are the corners;
// attributes are read and ignored) with the .node that holds its points and, when given, the .poly
// for segments, holes and regions (declaring 0 points, or the same points as the .node) and the .area
// (<#triangles>, then <triangle #> <maximum area>, -1 or <= 0: none). Errors name file, line, value.
// Every point of the .node is a point of the PLC: one that no triangle uses (a 6-node .ele's
// midpoint nodes) becomes a vertex of the refined mesh where it lies in the domain.
struct MeshFiles {
  std::string ele, node, poly, area;  // texts; poly and area are used when hasPoly / hasArea
  bool hasPoly = false, hasArea = false;
  std::string eleName = "<ele>", nodeName = "<node>", polyName = "<poly>", areaName = "<area>";
};
Plc parseMeshFiles(const MeshFiles& files);
// BASE.ele with BASE.node, and BASE.poly and BASE.area when they exist (readFile does this for .ele).
Plc readEleFiles(const std::string& elePath);
// The same texts as strings.
std::string toNode(const Mesh& mesh);
std::string toEle(const Mesh& mesh);
std::string toPoly(const Mesh& mesh, const Plc& input);
std::string toJson(const Mesh& mesh, const Plc& input);
std::string toSvg(const Mesh& mesh);

// ---------------------------------------------------------------------------------------------
// Formats solvers, viewers and GIS read (write_msh.cpp, write_vtu.cpp, write_geojson.cpp,
// read_geojson.cpp say exactly what is written)
// ---------------------------------------------------------------------------------------------
// Gmsh MSH 4.1 ASCII: nodes (tag = index + 1), triangles (type 2) and subsegments (type 1, lines);
// one physical group per region attribute (triangles) and per segment marker (lines). A marker or
// attribute that is a whole number >= 1 is its own physical tag; others get the tags after the largest.
void writeMsh(std::ostream& out, const Mesh& mesh, const Plc& input);
std::string toMsh(const Mesh& mesh, const Plc& input);
// VTK XML UnstructuredGrid (.vtu), ASCII: points (z = 0), triangles; point data "pointMarker" (when
// the mesh has them) and "vertexKind"; cell data "regionAttribute" and "minAngle" (degrees).
struct VtuOptions {
  // The boundary as .msh has it: one line cell per subsegment after the triangles, and a cell array
  // "segmentMarker" with each line's marker (Mesh::segmentMarkers; 0 for the triangles, and 0 for
  // the lines in the triangles' arrays), so that a viewer can pick a boundary out by its marker.
  // The CLI's --format vtu writes them.
  bool segmentCells = false;
};
void writeVtu(std::ostream& out, const Mesh& mesh, const VtuOptions& options = {});
std::string toVtu(const Mesh& mesh, const VtuOptions& options = {});
// GeoJSON FeatureCollection: one Polygon Feature per triangle with properties "triangle",
// "vertices", "regionAttribute" and "minAngle".
void writeGeoJson(std::ostream& out, const Mesh& mesh);
std::string toGeoJson(const Mesh& mesh);
// GeoJSON in: Polygon, MultiPolygon, Feature, FeatureCollection, GeometryCollection. Rings become
// closed chains of segments; equal positions are one point; inner rings get hole seeds (none needed
// from the caller). Errors name the path (features[3].geometry.coordinates[1]) and line:column.
Plc parseGeoJson(const std::string& text, const std::string& name = "<geojson>");
Plc readGeoJson(std::istream& in, const std::string& name = "<geojson>");

}  // namespace ruppert
