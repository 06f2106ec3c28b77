// libFuzzer target: bytes -> a small PLC and options -> triangulate -> the validator.
//
// Input layout (missing bytes read as 0, so every byte string is an input):
//   byte 0   minimum angle: value % 46 degrees (0..45)
//   byte 1   global max area: 0 = none, else (bounding-box area) / value
//   byte 2   flags: bit 0 circumcenter placement, bit 1 convex hull, bit 2 auto holes,
//            bit 3 petal placement (unless bit 0), bit 7 off-centers (unless bits 0, 3; else the
//            default, optimal points), bits 4-5 coordinate encoding (below), bit 6 the rest is
//            .poly text, not binary
//   byte 3   scale: integer coordinates are multiplied by 2^(signed byte), reaching 2^-128..2^127
//   binary:  count, then points; count, then segments (2 index bytes; 255 = one past the end);
//            count, then holes; count, then regions (x, y, attribute byte, max-area byte)
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

#include "mesh_judge.h"
#include "plc_invariants.h"

namespace {

// 3000, not more: the judge's overlap check slows down on meshes full of flat needles (a refinement
// stopped at its budget in fans around collinear vertices). At 5000 one such mesh took 3.3 s to make
// and validate under ASan and coverage, and over 10 s on a loaded machine, which libFuzzer reports as
// a hang (-timeout=10) though meshing it took 4 ms natively.
constexpr std::uint64_t kMaxSteiner = 3000;
// Text-mode inputs bigger than this are skipped: fuzzing wants many small runs.
constexpr std::size_t kMaxTextPoints = 400;

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

// With RUPPERT_FUZZ_DUMP=path set, every PLC is written there as .poly text before meshing, with
// the options in a comment: running the target on one finding turns it into a fixture.
void dumpPlc(const ruppert::Plc& plc, const ruppert::Options& o) {
  const char* path = std::getenv("RUPPERT_FUZZ_DUMP");
  if (!path) return;
  std::FILE* f = std::fopen(path, "w");
  if (!f) return;
  std::fprintf(f, "# options: minAngle %.17g maxArea %.17g placement %s convexHull %d autoHoles %d maxSteiner %llu\n",
               o.minAngle, o.maxArea, ruppert::enumName(o.placement),
               o.convexHull, o.autoHoles, static_cast<unsigned long long>(o.maxSteiner));
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
  std::fclose(f);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  ruppert::Options o;
  o.minAngle = in.byte() % 46;
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
  const std::vector<std::string> problems = ruppert_fuzz::judgeMesh(mesh, plc, o);
  if (!problems.empty()) {
    std::fprintf(stderr, "minAngle %g maxArea %g placement %d convexHull %d autoHoles %d complete %d\n", o.minAngle,
                 o.maxArea, static_cast<int>(o.placement), o.convexHull, o.autoHoles, mesh.complete);
    std::fprintf(stderr, "%s\n", ruppert_test::describeProblems(problems).c_str());
    ruppert_fuzz::finding("invalid mesh");
  }
  return 0;
}
