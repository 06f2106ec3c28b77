// libFuzzer target: bytes -> a small PLC and options -> triangulate -> the validator.
//
// Input layout (missing bytes read as 0, so every byte string is an input):
//   byte 0   minimum angle: value % 46 degrees (0..45); maximum angle: kMaxAngles[value / 46]
//            (none below 46, so inputs written before it keep their meaning)
//   byte 1   global max area: 0 = none, else (bounding-box area) / value
//   byte 2   flags: bit 0 circumcenter placement, bit 1 convex hull, bit 2 auto holes,
//            bit 3 petal placement (unless bit 0), bit 7 off-centers (unless bits 0, 3; else the
//            default, optimal points), bits 4-5 coordinate encoding (below), bit 6 the rest is
//            .poly text, not binary
//   byte 3   scale: integer coordinates are multiplied by 2^(signed byte), reaching 2^-128..2^127
//   binary:  count, then points; count, then segments (2 index bytes; 255 = one past the end);
//            count, then holes; count, then regions (x, y, attribute byte, max-area byte);
//            count, then curves (below), then the curve tolerance byte
// A curve: a type byte (bit 0: Bézier, else arc; bits 1-7: marker), its two point index bytes, then
// an arc's center as the chord's midpoint plus a signed multiple (int16 / 64) of its normal (so both
// ends are at one distance from it to rounding, as Plc::curves asks), or a Bézier's two control
// points in the coordinate encoding. Tolerance byte b: 0 the default, else the bounding box's
// diagonal / 2^(b % 24).
// Coordinate encodings: 0 int8, 1 int16, 2 raw IEEE double bits (NaN, Inf, subnormals ...),
// 3 int8 + int8/256 (near-degenerate fractions). Small integer grids make the hard cases likely:
// duplicates, collinear runs, crossings at one point, vertices on segments.
//
// ruppert::Error is an accepted outcome except ErrorCode::Internal; any other exception, a
// sanitizer report, a hang (libFuzzer -timeout) or an invalid mesh is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "curve_checks.h"
#include "mesh_judge.h"
#include "plc_invariants.h"

namespace {

// Options::maxAngle by byte 0 / 46: none, then bounds from acute (hard: the Steiner budget ends
// many runs) to loose.
constexpr double kMaxAngles[6] = {0, 80, 90, 100, 120, 150};

// 3000, not more: the judge's overlap check slows down on meshes full of flat needles (a refinement
// stopped at its budget in fans around collinear vertices). At 5000 one such mesh took 3.3 s to make
// and validate under ASan and coverage, and over 10 s on a loaded machine, which libFuzzer reports as
// a hang (-timeout=10) though meshing it took 4 ms natively.
constexpr std::uint64_t kMaxSteiner = 3000;
// With curves, 1000: a curve tangent to a segment at their shared end (an input angle that every
// split makes smaller) runs to the budget in flat needles just as above; at 3000 one such mesh
// (12 ms natively) took 7.5 s to judge under the fuzzer's instrumentation.
constexpr std::uint64_t kMaxSteinerWithCurves = 1000;
// Text-mode inputs bigger than this are skipped: fuzzing wants many small runs.
constexpr std::size_t kMaxTextPoints = 400;
// Meshes larger than this are made (the sanitizers watch the core) but not judged: curves with a
// tolerance a millionth of the input's extent are cut into tens of thousands of pieces before any
// Steiner vertex counts against the budget, and judging one such mesh of 70,000 triangles (0.2 s
// natively) took 80 s under the fuzzer's instrumentation.
constexpr std::size_t kMaxJudgedTriangles = 20000;

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}
  std::uint8_t byte() { return p_ < end_ ? *p_++ : 0; }
  std::string rest() { return std::string(reinterpret_cast<const char*>(p_), static_cast<std::size_t>(end_ - p_)); }

  double coordinate(int encoding, double scale) {
    switch (encoding) {
      case 0: return static_cast<std::int8_t>(byte()) * scale;
      case 1: {
        const std::uint16_t lo = byte(), hi = byte();
        return static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8))) * scale;
      }
      case 2: {
        std::uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(byte()) << (8 * i);
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
      }
      default: {
        const int whole = static_cast<std::int8_t>(byte());
        const int frac = static_cast<std::int8_t>(byte());
        return (whole + frac / 256.0) * scale;
      }
    }
  }

 private:
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

double boxArea(const ruppert::Plc& plc) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (std::size_t i = 0; i < plc.points.size(); ++i) {
    lo[i % 2] = std::fmin(lo[i % 2], plc.points[i]);
    hi[i % 2] = std::fmax(hi[i % 2], plc.points[i]);
  }
  const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
  return std::isfinite(area) && area > 0 ? area : 0;
}

// A bound of `box / selector`; 0 (none) for selector 0 or a degenerate box.
double areaBound(double box, std::uint8_t selector) { return selector == 0 ? 0 : box / selector; }

void readBinaryPlc(Bytes& in, int encoding, double scale, ruppert::Plc& plc) {
  const std::size_t points = in.byte() % 48;
  for (std::size_t i = 0; i < 2 * points; ++i) plc.points.push_back(in.coordinate(encoding, scale));
  const std::size_t segments = in.byte() % 64;
  for (std::size_t i = 0; i < 2 * segments; ++i) {
    const std::uint8_t b = in.byte();
    plc.segments.push_back(b == 255 ? static_cast<std::uint32_t>(points)
                                    : static_cast<std::uint32_t>(points ? b % points : 0));
  }
  const std::size_t holes = in.byte() % 4;
  for (std::size_t i = 0; i < 2 * holes; ++i) plc.holes.push_back(in.coordinate(encoding, scale));
  const std::size_t regions = in.byte() % 3;
  const double box = boxArea(plc);
  for (std::size_t i = 0; i < regions; ++i) {
    ruppert::Region r;
    r.x = in.coordinate(encoding, scale);
    r.y = in.coordinate(encoding, scale);
    r.attribute = in.byte();
    r.maxArea = areaBound(box, in.byte());
    plc.regions.push_back(r);
  }
}

ruppert::Curve readCurve(Bytes& in, int encoding, double scale, const ruppert::Plc& plc) {
  const std::size_t points = plc.points.size() / 2;
  ruppert::Curve c;
  const std::uint8_t kind = in.byte();
  c.type = (kind & 1) ? ruppert::CurveType::Bezier : ruppert::CurveType::Arc;
  c.marker = kind >> 1;
  c.from = points ? in.byte() % points : in.byte();
  c.to = points ? in.byte() % points : in.byte();
  if (c.type == ruppert::CurveType::Bezier) {
    for (double& v : c.controls) v = in.coordinate(encoding, scale);
    return c;
  }
  const std::uint16_t lo = in.byte(), hi = in.byte();
  const double offset = static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8))) / 64.0;
  if (c.from < points && c.to < points) {
    const double ax = plc.points[2 * c.from], ay = plc.points[2 * c.from + 1];
    const double bx = plc.points[2 * c.to], by = plc.points[2 * c.to + 1];
    c.center[0] = 0.5 * (ax + bx) - offset * (by - ay);
    c.center[1] = 0.5 * (ay + by) + offset * (bx - ax);
  }
  return c;
}

double boxDiagonal(const ruppert::Plc& plc) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (std::size_t i = 0; i < plc.points.size(); ++i) {
    lo[i % 2] = std::fmin(lo[i % 2], plc.points[i]);
    hi[i % 2] = std::fmax(hi[i % 2], plc.points[i]);
  }
  const double d = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  return std::isfinite(d) ? d : 0;
}

void readCurves(Bytes& in, int encoding, double scale, ruppert::Plc& plc, ruppert::Options& o) {
  const std::size_t curves = in.byte() % 4;
  for (std::size_t i = 0; i < curves; ++i) plc.curves.push_back(readCurve(in, encoding, scale, plc));
  const std::uint8_t tolerance = in.byte();
  if (tolerance != 0) o.curveTolerance = std::ldexp(boxDiagonal(plc), -(tolerance % 24));
}

// A plain CDT of a PLC with curves: every new vertex is an end of a curve's piece or a crossing of
// segments (the input's repair).
void checkOnlyCurveVertices(const ruppert::Mesh& mesh, const ruppert::Plc& plc, std::vector<std::string>& problems) {
  const std::size_t userPoints = plc.points.size() / 2, segments = plc.segments.size() / 2;
  std::vector<bool> onCurve(mesh.points.size() / 2, false);
  for (std::size_t k = 0; k < mesh.segmentIds.size(); ++k)
    if (mesh.segmentIds[k] >= 0 && std::size_t(mesh.segmentIds[k]) >= segments)
      onCurve[mesh.segments[2 * k]] = onCurve[mesh.segments[2 * k + 1]] = true;
  for (std::size_t v = userPoints; v < onCurve.size(); ++v)
    if (!onCurve[v] && mesh.vertexKinds[v] != static_cast<std::uint8_t>(ruppert::VertexKind::Intersection))
      problems.push_back("vertex " + std::to_string(v) + " is new in a plain CDT but on no curve");
}

// With RUPPERT_FUZZ_DUMP=path set, every PLC is written there as .poly text before meshing, with
// the options in a comment: running the target on one finding turns it into a fixture.
void dumpPlc(const ruppert::Plc& plc, const ruppert::Options& o) {
  const char* path = std::getenv("RUPPERT_FUZZ_DUMP");
  if (!path) return;
  std::FILE* f = std::fopen(path, "w");
  if (!f) return;
  std::fprintf(f, "# options: minAngle %.17g maxAngle %.17g maxArea %.17g placement %s convexHull %d autoHoles %d maxSteiner %llu smooth %d\n",
               o.minAngle, o.maxAngle, o.maxArea, ruppert::enumName(o.placement),
               o.convexHull, o.autoHoles, static_cast<unsigned long long>(o.maxSteiner), o.smooth);
  std::fprintf(f, "%zu 2 0 0\n", plc.points.size() / 2);
  for (std::size_t i = 0; i < plc.points.size() / 2; ++i)
    std::fprintf(f, "%zu %.17g %.17g\n", i, plc.points[2 * i], plc.points[2 * i + 1]);
  std::fprintf(f, "%zu 0\n", plc.segments.size() / 2);
  for (std::size_t i = 0; i < plc.segments.size() / 2; ++i)
    std::fprintf(f, "%zu %u %u\n", i, plc.segments[2 * i], plc.segments[2 * i + 1]);
  std::fprintf(f, "%zu\n", plc.holes.size() / 2);
  for (std::size_t i = 0; i < plc.holes.size() / 2; ++i)
    std::fprintf(f, "%zu %.17g %.17g\n", i, plc.holes[2 * i], plc.holes[2 * i + 1]);
  std::fprintf(f, "%zu\n", plc.regions.size());
  for (std::size_t i = 0; i < plc.regions.size(); ++i)
    std::fprintf(f, "%zu %.17g %.17g %.17g %.17g\n", i, plc.regions[i].x, plc.regions[i].y, plc.regions[i].attribute,
                 plc.regions[i].maxArea);
  std::fprintf(f, "# curveTolerance %.17g; curves: type from to center-or-controls marker\n", o.curveTolerance);
  for (const ruppert::Curve& c : plc.curves)
    std::fprintf(f, "# curve %s %u %u %.17g %.17g %.17g %.17g %.17g %.17g %d\n", ruppert::enumName(c.type), c.from, c.to,
                 c.center[0], c.center[1], c.controls[0], c.controls[1], c.controls[2], c.controls[3], c.marker);
  std::fclose(f);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  ruppert::Options o;
  const std::uint8_t angleByte = in.byte();
  o.minAngle = angleByte % 46;
  o.maxAngle = kMaxAngles[angleByte / 46];
  // The angle byte's quotient also picks smoothing (a third of the inputs, 1 to 3 passes), so the
  // byte layout of the corpus stays as it was.
  o.smooth = angleByte / 46 % 3 == 2 ? 1 + angleByte % 3 : 0;
  const std::uint8_t areaSelector = in.byte();
  const std::uint8_t flags = in.byte();
  const double scale = std::ldexp(1.0, static_cast<std::int8_t>(in.byte()));
  o.placement = (flags & 1) ? ruppert::Placement::Circumcenter
                : (flags & 8) ? ruppert::Placement::Petal
                : (flags & 128) ? ruppert::Placement::OffCenter
                               : ruppert::Placement::Optimal;
  o.convexHull = (flags & 2) != 0;
  o.autoHoles = (flags & 4) != 0;
  o.maxSteiner = kMaxSteiner;

  ruppert::Plc plc;
  if (flags & 64) {
    std::istringstream text(in.rest());
    try {
      plc = ruppert::readPoly(text, "fuzz.poly");
    } catch (const ruppert::Error& e) {
      ruppert_fuzz::checkReaderError(e);
      return 0;
    }
    if (plc.points.size() / 2 > kMaxTextPoints || plc.segments.size() / 2 > kMaxTextPoints) return 0;
  } else {
    readBinaryPlc(in, (flags >> 4) & 3, scale, plc);
    readCurves(in, (flags >> 4) & 3, scale, plc, o);
    if (!plc.curves.empty()) o.maxSteiner = kMaxSteinerWithCurves;
  }
  o.maxArea = areaBound(boxArea(plc), areaSelector);

  dumpPlc(plc, o);
  ruppert::Mesh mesh;
  try {
    mesh = ruppert::triangulate(plc, o);
  } catch (const ruppert::Error& e) {
    if (e.code() == ruppert::ErrorCode::Internal) ruppert_fuzz::finding(e.what());
    return 0;
  }
  if (mesh.triangles.size() / 3 > kMaxJudgedTriangles) return 0;
  std::vector<std::string> problems = ruppert_fuzz::judgeMesh(mesh, plc, o);
  if (!plc.curves.empty()) {
    const double tolerance = o.curveTolerance > 0 ? o.curveTolerance : 1e-3 * boxDiagonal(plc);
    for (std::string& p : ruppert_test::checkCurves(mesh, plc, tolerance, false).problems) problems.push_back(std::move(p));
    if (ruppert_fuzz::asksNoRefinement(plc, o)) checkOnlyCurveVertices(mesh, plc, problems);
  }
  if (!problems.empty()) {
    std::fprintf(stderr, "minAngle %g maxAngle %g maxArea %g placement %d convexHull %d autoHoles %d smooth %d complete %d\n",
                 o.minAngle, o.maxAngle, o.maxArea, static_cast<int>(o.placement), o.convexHull, o.autoHoles, o.smooth, mesh.complete);
    std::fprintf(stderr, "%s\n", ruppert_test::describeProblems(problems).c_str());
    ruppert_fuzz::finding("invalid mesh");
  }
  return 0;
}
