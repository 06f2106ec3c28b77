// Core benchmarks.
//   CDT (Options::minAngle = 0): uniform random points with and without the square's boundary as
//   segments, and the largest real PLC of the shared data folder.
//   Refinement (30 degrees, default options): a unit square and a real coastline with max areas that
//   give about 10^5, 10^6 (and with --big 10^7) triangles; output triangles per second.
//
// Each input is meshed once to warm up (page faults, allocator, caches), then three times (once for
// 10^7); the best is reported, since noise on a shared machine only ever adds time.
//
//   --chords: stars of 300 chords crossing near a disk's center (44,850 crossings at small angles,
//   plc_generators.h's chordStar, seeds 2-5) at 30 and 33 degrees, one run each: vertices, whether
//   refinement completed under the automatic Steiner budget, and time.
//
//   --duplicates: 10^5 uniform random points given once, and the same points each given twice (the
//   copies after the originals), at 0 and 30 degrees: best of 3 each (the two alternating, after a
//   warm-up), the ratio twice / once, and whether both meshes have the same triangles.
//
//   --placement P: the refinement rows with placement P (offcenter, circumcenter, petal, optimal)
//   instead of the default, for paired runs of two placements.
//
// Usage: ruppert_bench [--max-points N] [--big] [--chords] [--duplicates] [--placement P]
//        (N default 1000000; --big adds 10^7)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <ruppert/ruppert.h>

#include "plc_generators.h"

namespace {

ruppert::Plc uniformPoints(std::size_t n, bool boundary, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  ruppert::Plc plc;
  plc.points.reserve(2 * n + 8);
  if (boundary) {
    plc.points = {0, 0, 1, 0, 1, 1, 0, 1};
    plc.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  }
  // 53-bit uniform doubles strictly inside (0, 1).
  while (plc.points.size() < 2 * n + (boundary ? 8 : 0)) {
    const double v = (double(rng() >> 11) + 0.5) * 0x1p-53;
    plc.points.push_back(v);
  }
  return plc;
}

struct Row {
  std::string name;
  std::size_t points = 0, triangles = 0;
  double bestMs = 0;
};

Row measure(const std::string& name, const ruppert::Plc& plc, const ruppert::Options& options, int runs = 3) {
  Row row;
  row.name = name;
  row.points = plc.points.size() / 2;
  row.triangles = ruppert::triangulate(plc, options).triangles.size() / 3;  // warm-up
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const ruppert::Mesh mesh = ruppert::triangulate(plc, options);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (run == 0 || ms < row.bestMs) row.bestMs = ms;
    row.triangles = mesh.triangles.size() / 3;
  }
  std::printf("  measured %-36s %.1f ms\n", name.c_str(), row.bestMs);
  std::fflush(stdout);
  return row;
}

// The chord stars: one run each (seconds apiece), printed as a table.
void chordStars() {
  std::printf("\nStars of 300 chords (chordStar, default options), one run each\n");
  std::printf("| seed | angle | crossings | vertices | complete | ms |\n|---|---|---|---|---|---|\n");
  for (std::uint64_t seed : {2u, 3u, 4u, 5u})
    for (double angle : {30.0, 33.0}) {
      ruppert::Options o;
      o.minAngle = angle;
      const auto start = std::chrono::steady_clock::now();
      const ruppert::Mesh mesh = ruppert::triangulate(ruppert_test::chordStar(seed, 300).plc, o);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      std::printf("| %llu | %.0f | %llu | %llu | %s | %.0f |\n", static_cast<unsigned long long>(seed), angle,
                  static_cast<unsigned long long>(mesh.stats.intersectionVertices),
                  static_cast<unsigned long long>(mesh.stats.vertices), mesh.complete ? "yes" : "no", ms);
      std::fflush(stdout);
    }
}

// Every point given twice must cost about what the sort of twice the points costs: no work per
// duplicate that dominates (it once cost ~26 us each, printing every merged point's coordinates).
void duplicatedPoints() {
  const ruppert::Plc once = uniformPoints(100000, false, 7);
  ruppert::Plc twice = once;
  twice.points.insert(twice.points.end(), once.points.begin(), once.points.end());
  std::printf("\n10^5 random points given once and each given twice, best of 3 (alternating) after a warm-up\n");
  std::printf("| min angle | triangles | once ms | twice ms | twice / once | notices | same triangles |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (double angle : {0.0, 30.0}) {
    ruppert::Options o;
    o.minAngle = angle;
    auto timed = [&](const ruppert::Plc& plc, double& best, ruppert::Mesh& mesh) {
      const auto start = std::chrono::steady_clock::now();
      mesh = ruppert::triangulate(plc, o);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (best < 0 || ms < best) best = ms;
    };
    double bestOnce = -1, bestTwice = -1, ignored = -1;
    ruppert::Mesh a, b;
    timed(once, ignored, a), timed(twice, ignored, b);  // warm-up
    for (int run = 0; run < 3; ++run) timed(once, bestOnce, a), timed(twice, bestTwice, b);
    // Steiner vertices are numbered after the input points, so triangles are compared by corners.
    auto corners = [](const ruppert::Mesh& mesh) {
      std::vector<double> xy;
      for (std::uint32_t v : mesh.triangles) xy.push_back(mesh.points[2 * v]), xy.push_back(mesh.points[2 * v + 1]);
      return xy;
    };
    std::printf("| %.0f | %zu | %.1f | %.1f | %.2f | %zu | %s |\n", angle, a.triangles.size() / 3, bestOnce, bestTwice,
                bestTwice / bestOnce, b.notices.size(), corners(a) == corners(b) ? "yes" : "NO");
    std::fflush(stdout);
  }
}

bool placementNamed(const char* name, ruppert::Placement& placement) {
  for (std::size_t i = 0; i < std::size(ruppert::kPlacementNames); ++i)
    if (!std::strcmp(name, ruppert::kPlacementNames[i])) {
      placement = static_cast<ruppert::Placement>(i);
      return true;
    }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t maxPoints = 1000000;
  bool big = false, chords = false, duplicates = false;
  ruppert::Placement placement = ruppert::Options().placement;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max-points") && i + 1 < argc) {
      maxPoints = std::strtoull(argv[++i], nullptr, 10);
    } else if (!std::strcmp(argv[i], "--big")) {
      big = true;
    } else if (!std::strcmp(argv[i], "--chords")) {
      chords = true;
    } else if (!std::strcmp(argv[i], "--duplicates")) {
      duplicates = true;
    } else if (!std::strcmp(argv[i], "--placement") && i + 1 < argc && placementNamed(argv[i + 1], placement)) {
      ++i;
    } else {
      std::fprintf(stderr, "usage: %s [--max-points N] [--big] [--chords] [--duplicates] [--placement P]\n",
                   argv[0]);
      return 2;
    }
  }
  if (chords) {
    chordStars();
    return 0;
  }
  if (duplicates) {
    duplicatedPoints();
    return 0;
  }

  ruppert::Options cdtOptions;
  cdtOptions.minAngle = 0;
  std::vector<Row> rows, refined;
  try {
    for (std::size_t n : {std::size_t(100000), std::size_t(1000000)}) {
      if (n > maxPoints) continue;
      const std::string count = n == 100000 ? "1e5" : "1e6";
      rows.push_back(measure("uniform " + count + " points", uniformPoints(n, false, 1), cdtOptions));
      rows.push_back(measure("uniform " + count + " points + square boundary", uniformPoints(n, true, 1), cdtOptions));
    }
#ifdef RUPPERT_SHARED_DATA
    const std::string huge = std::string(RUPPERT_SHARED_DATA) + "/earcut_water_huge3.poly";
    if (std::ifstream(huge).good())
      rows.push_back(measure("earcut_water_huge3.poly", ruppert::readFile(huge), cdtOptions));
    else
      std::printf("  (%s not found: skipping the real PLC)\n", huge.c_str());
#endif
    // Refinement: a triangle of area a has ~ a / maxArea * 1.6 triangles at 30 degrees, empirically.
    ruppert::Plc square = uniformPoints(0, true, 1);
    for (double area : {1e-5, 1e-6, 1e-7}) {
      if (area < 1e-6 && !big) continue;
      ruppert::Options o;
      o.maxArea = area;
      o.placement = placement;
      char name[64];
      std::snprintf(name, sizeof name, "square, 30 deg, max area %g", area);
      refined.push_back(measure(name, square, o, area < 1e-6 ? 1 : 3));
    }
#ifdef RUPPERT_SHARED_DATA
    if (std::ifstream(huge).good()) {
      const ruppert::Plc coast = ruppert::readFile(huge);
      for (double area : {1e2, 1e1}) {  // the coastline spans about 4096 x 4096 units
        ruppert::Options o;
        o.maxArea = area;
        o.placement = placement;
        char name[64];
        std::snprintf(name, sizeof name, "earcut_water_huge3, 30 deg, max area %g", area);
        refined.push_back(measure(name, coast, o));
      }
    }
#endif
  } catch (const std::exception& e) {
    std::fprintf(stderr, "benchmark failed: %s\n", e.what());
    return 1;
  }

  std::printf("\nCDT (minAngle 0), best of 3 after a warm-up\n");
  std::printf("| %-40s | %9s | %9s | %10s | %12s |\n", "input", "points", "triangles", "ms", "points/s");
  std::printf("|%s|%s|%s|%s|%s|\n", std::string(42, '-').c_str(), std::string(11, '-').c_str(),
              std::string(11, '-').c_str(), std::string(12, '-').c_str(), std::string(14, '-').c_str());
  for (const Row& r : rows)
    std::printf("| %-40s | %9zu | %9zu | %10.1f | %12.0f |\n", r.name.c_str(), r.points, r.triangles, r.bestMs,
                double(r.points) / (r.bestMs / 1000.0));
  std::printf("\nRefinement (minAngle 30, placement %s, lenses), best of 3 after a warm-up (10^7: one run)\n",
              ruppert::enumName(placement));
  std::printf("| %-42s | %10s | %10s | %14s |\n", "input", "triangles", "ms", "triangles/s");
  std::printf("|%s|%s|%s|%s|\n", std::string(44, '-').c_str(), std::string(12, '-').c_str(),
              std::string(12, '-').c_str(), std::string(16, '-').c_str());
  for (const Row& r : refined)
    std::printf("| %-42s | %10zu | %10.1f | %14.0f |\n", r.name.c_str(), r.triangles, r.bestMs,
                double(r.triangles) / (r.bestMs / 1000.0));
  return 0;
}
