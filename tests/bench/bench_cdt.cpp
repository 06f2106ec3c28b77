// CDT benchmark (Options::minAngle = 0): uniform random points with and without the square's
// boundary as segments, and the largest real PLC of the shared data folder.
//
// Each input is triangulated once to warm up (page faults, allocator, caches), then three times;
// the best of the three is reported, since noise on a shared machine only ever adds time.
//
// Usage: ruppert_bench [--max-points N]   (default 1000000; smaller N for a quick run)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <ruppert/ruppert.h>

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

Row measure(const std::string& name, const ruppert::Plc& plc) {
  ruppert::Options options;
  options.minAngle = 0;
  Row row;
  row.name = name;
  row.points = plc.points.size() / 2;
  row.triangles = ruppert::triangulate(plc, options).triangles.size() / 3;  // warm-up
  for (int run = 0; run < 3; ++run) {
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

}  // namespace

int main(int argc, char** argv) {
  std::size_t maxPoints = 1000000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max-points") && i + 1 < argc) {
      maxPoints = std::strtoull(argv[++i], nullptr, 10);
    } else {
      std::fprintf(stderr, "usage: %s [--max-points N]\n", argv[0]);
      return 2;
    }
  }

  std::vector<Row> rows;
  try {
    for (std::size_t n : {std::size_t(100000), std::size_t(1000000)}) {
      if (n > maxPoints) continue;
      const std::string count = n == 100000 ? "1e5" : "1e6";
      rows.push_back(measure("uniform " + count + " points", uniformPoints(n, false, 1)));
      rows.push_back(measure("uniform " + count + " points + square boundary", uniformPoints(n, true, 1)));
    }
#ifdef RUPPERT_SHARED_DATA
    const std::string huge = std::string(RUPPERT_SHARED_DATA) + "/earcut_water_huge3.poly";
    if (std::ifstream(huge).good())
      rows.push_back(measure("earcut_water_huge3.poly", ruppert::readFile(huge)));
    else
      std::printf("  (%s not found: skipping the real PLC)\n", huge.c_str());
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
  return 0;
}
