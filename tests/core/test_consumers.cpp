// The .msh and .vtu writers judged by the programs that read them: meshio
// (Debian's python3-meshio, through /usr/bin/python3) reads both files back and must find the same
// points, triangles (count and connectivity), lines and cell data as the mesh in memory; Gmsh opens
// the .msh (`gmsh -check`) and must report no error and the right node and element counts. Both
// checks are first shown to fail on corrupted copies, so a silent consumer cannot pass them.
// Inputs: several ../shared/data files (skipped with a warning when absent) and generated PLCs with
// markers and region attributes. Without meshio or Gmsh installed the tests warn and skip
// (.ci/setup.sh installs both).
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "plc_generators.h"
#include "ruppert/ruppert.h"

namespace fs = std::filesystem;

namespace {

#ifdef RUPPERT_FIXTURES
const fs::path kTools = fs::path(RUPPERT_FIXTURES) / ".." / "tools";
#else
const fs::path kTools = "tests/tools";
#endif

struct Output {
  int status = -1;
  std::string text;  // stdout and stderr together
};

Output shell(const std::string& command) {
  const fs::path log = fs::temp_directory_path() / ("ruppert-consumers-" + std::to_string(::getpid()) + ".log");
  const int raw = std::system((command + " >'" + log.string() + "' 2>&1").c_str());
  Output out;
  out.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(log);
  std::ostringstream s;
  s << in.rdbuf();
  out.text = s.str();
  fs::remove(log);
  return out;
}

bool haveMeshio() {
  static const bool have = shell("/usr/bin/python3 -c 'import meshio'").status == 0;
  if (!have) WARN("python3-meshio is not installed (.ci/setup.sh installs it): skipping the meshio checks");
  return have;
}

bool haveGmsh() {
  static const bool have = shell("gmsh --version").status == 0;
  if (!have) WARN("gmsh is not installed (.ci/setup.sh installs it): skipping the Gmsh checks");
  return have;
}

fs::path scratch() {
  struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("ruppert-consumers-" + std::to_string(::getpid()));
    ~Scratch() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  };
  static const Scratch s;
  fs::create_directories(s.dir);
  return s.dir;
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Physical tags as the .msh writer documents them, computed here from the rule, not from its code:
// a whole number in [1, 2^31 - 1] is its own tag, the rest follow the largest such, by value.
std::map<double, long long> physicalTags(const std::set<double>& values) {
  long long next = 1;
  auto own = [](double v) { return v >= 1 && v <= 2147483647.0 && v == std::floor(v); };
  for (double v : values) {
    if (own(v)) next = std::max(next, static_cast<long long>(v) + 1);
  }
  std::map<double, long long> tags;
  for (double v : values) tags[v] = own(v) ? static_cast<long long>(v) : next++;
  return tags;
}

double smallestAngle(const ruppert::Mesh& m, std::size_t t) {
  double best = 180;
  for (int k = 0; k < 3; ++k) {
    const std::size_t a = m.triangles[3 * t + k], b = m.triangles[3 * t + (k + 1) % 3], c = m.triangles[3 * t + (k + 2) % 3];
    const double ux = m.points[2 * b] - m.points[2 * a], uy = m.points[2 * b + 1] - m.points[2 * a + 1];
    const double wx = m.points[2 * c] - m.points[2 * a], wy = m.points[2 * c + 1] - m.points[2 * a + 1];
    best = std::min(best, std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / M_PI);
  }
  return best;
}

std::string real(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// What meshio must find, from the mesh in memory (see check_with_meshio.py for the layout).
std::string expectedText(const ruppert::Mesh& m, const ruppert::Plc& input) {
  const std::size_t n = m.points.size() / 2, t = m.triangles.size() / 3, l = m.segments.size() / 2;
  auto attribute = [&](std::size_t i) { return i < m.triangleAttributes.size() ? m.triangleAttributes[i] : 0.0; };
  // The subsegment's boundary marker as the mesh carries it (Mesh::segmentMarkers: its input
  // segment's nonzero marker, else 1 on the boundary, 0 inside; test_markers.cpp checks the rule).
  (void)input;
  auto marker = [&](std::size_t s) { return m.segmentMarkers.at(s); };
  std::set<double> attributes, markers;
  for (std::size_t i = 0; i < t; ++i) attributes.insert(attribute(i));
  for (std::size_t s = 0; s < l; ++s) markers.insert(marker(s));
  const auto surfaceTag = physicalTags(attributes), curveTag = physicalTags(markers);
  std::ostringstream out;
  out << "points " << n << '\n';
  for (std::size_t i = 0; i < n; ++i) {
    out << real(m.points[2 * i]) << ' ' << real(m.points[2 * i + 1]) << ' ' << int(m.vertexKinds[i]) << ' '
        << (m.pointMarkers.size() == n ? std::to_string(m.pointMarkers[i]) : "-") << '\n';
  }
  out << "triangles " << t << '\n';
  for (std::size_t i = 0; i < t; ++i) {
    out << m.triangles[3 * i] << ' ' << m.triangles[3 * i + 1] << ' ' << m.triangles[3 * i + 2] << ' '
        << surfaceTag.at(attribute(i)) << ' ' << real(attribute(i)) << ' ' << real(smallestAngle(m, i)) << '\n';
  }
  out << "lines " << l << '\n';
  for (std::size_t s = 0; s < l; ++s) {
    out << m.segments[2 * s] << ' ' << m.segments[2 * s + 1] << ' ' << curveTag.at(marker(s)) << '\n';
  }
  return out.str();
}

Output meshioCheck(const fs::path& expected, const fs::path& msh, const fs::path& vtu) {
  return shell("/usr/bin/python3 '" + (kTools / "check_with_meshio.py").string() + "' '" + expected.string() + "' '" +
               msh.string() + "' '" + vtu.string() + "'");
}

// Gmsh's verdict: exit status 0, no "Error" line, and the node and element counts it read equal
// ours (a truncated file reads "successfully" with fewer elements).
std::string gmshProblem(const fs::path& msh, std::size_t nodes, std::size_t elements) {
  const Output r = shell("gmsh -check '" + msh.string() + "'");
  if (r.status != 0) return "gmsh exited " + std::to_string(r.status) + ":\n" + r.text;
  if (r.text.find("Error") != std::string::npos) return "gmsh reported an error:\n" + r.text;
  if (!std::regex_search(r.text, std::regex("Info +: " + std::to_string(nodes) + " nodes\\b")) ||
      !std::regex_search(r.text, std::regex("Info +: " + std::to_string(elements) + " elements\\b"))) {
    return "gmsh did not read " + std::to_string(nodes) + " nodes and " + std::to_string(elements) + " elements:\n" + r.text;
  }
  return "";
}

void checkWithConsumers(const std::string& label, const ruppert::Plc& plc, const ruppert::Options& options) {
  INFO(label);
  const ruppert::Mesh mesh = ruppert::triangulate(plc, options);
  const fs::path dir = scratch();
  const fs::path expected = dir / "expected.txt", msh = dir / "mesh.msh", vtu = dir / "mesh.vtu";
  writeText(expected, expectedText(mesh, plc));
  writeText(msh, ruppert::toMsh(mesh, plc));
  writeText(vtu, ruppert::toVtu(mesh));
  if (haveMeshio()) {
    const Output r = meshioCheck(expected, msh, vtu);
    INFO(r.text);
    CHECK(r.status == 0);
  }
  if (haveGmsh()) {
    const std::string problem = gmshProblem(msh, mesh.points.size() / 2, mesh.triangles.size() / 3 + mesh.segments.size() / 2);
    INFO(problem);
    CHECK(problem.empty());
  }
}

// Four quadrants split by segments, with segment markers 0, 4, 9 and region attributes 2, 7.5, -1
// (and one quadrant without a region: attribute 0).
ruppert::Plc markedQuadrants() {
  ruppert::Plc plc = ruppert_test::gridPlc(5, 5, 1.0, true).plc;
  const int markers[3] = {0, 4, 9};
  for (std::size_t s = 0; s < plc.segments.size() / 2; ++s) plc.segmentMarkers.push_back(markers[s % 3]);
  plc.regions = {{0.5, 0.5, 2, 0}, {3.5, 0.5, 7.5, 0}, {0.5, 3.5, -1, 0}};
  return plc;
}

}  // namespace

TEST_CASE("consumers: meshio and Gmsh reject corrupted copies", "[consumers]") {
  const ruppert::Plc plc = markedQuadrants();
  const ruppert::Mesh mesh = ruppert::triangulate(plc, {});
  const fs::path dir = scratch();
  const std::string msh = ruppert::toMsh(mesh, plc), vtu = ruppert::toVtu(mesh);
  writeText(dir / "expected.txt", expectedText(mesh, plc));
  // One triangle's first two vertices swapped: same counts, other connectivity and orientation.
  // The newline before the first element: after "$Elements", its count line and the first block's.
  const std::size_t at = msh.find('\n', msh.find('\n', msh.find("$Elements\n") + 10) + 1);
  REQUIRE(at != std::string::npos);
  std::istringstream line(msh.substr(at + 1, msh.find('\n', at + 1) - at - 1));
  std::string tag, a, b, c;
  line >> tag >> a >> b >> c;
  std::string swapped = msh;
  swapped.replace(at + 1, msh.find('\n', at + 1) - at - 1, tag + " " + b + " " + a + " " + c);
  writeText(dir / "swapped.msh", swapped);
  writeText(dir / "good.msh", msh);
  writeText(dir / "good.vtu", vtu);
  // A triangle naming a node that does not exist, and a file cut short in its elements.
  std::string unknownNode = msh;
  unknownNode.replace(at + 1, msh.find('\n', at + 1) - at - 1, tag + " " + a + " " + b + " 999999");
  writeText(dir / "unknown-node.msh", unknownNode);
  writeText(dir / "truncated.msh", msh.substr(0, msh.find("$Elements") + (msh.size() - msh.find("$Elements")) / 2));

  if (haveMeshio()) {
    CHECK(meshioCheck(dir / "expected.txt", dir / "good.msh", dir / "good.vtu").status == 0);
    CHECK(meshioCheck(dir / "expected.txt", dir / "swapped.msh", dir / "good.vtu").status != 0);
    std::string vtuShifted = vtu;
    const std::size_t points = vtuShifted.find("<Points>");
    const std::size_t first = vtuShifted.find("\n          ", points + 1);
    vtuShifted.insert(first + 11, "1");  // one coordinate gains a leading digit
    writeText(dir / "shifted.vtu", vtuShifted);
    CHECK(meshioCheck(dir / "expected.txt", dir / "good.msh", dir / "shifted.vtu").status != 0);
  }
  if (haveGmsh()) {
    const std::size_t nodes = mesh.points.size() / 2, elements = mesh.triangles.size() / 3 + mesh.segments.size() / 2;
    CHECK(gmshProblem(dir / "good.msh", nodes, elements).empty());
    CHECK_FALSE(gmshProblem(dir / "unknown-node.msh", nodes, elements).empty());
    CHECK_FALSE(gmshProblem(dir / "truncated.msh", nodes, elements).empty());
  }
}

TEST_CASE("consumers: generated PLCs with markers and region attributes", "[consumers]") {
  ruppert::Options options;
  checkWithConsumers("marked quadrants, 30 degrees", markedQuadrants(), options);
  options.maxArea = 0.05;
  checkWithConsumers("marked quadrants, area 0.05", markedQuadrants(), options);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    checkWithConsumers("random points in a square, seed " + std::to_string(seed),
                       ruppert_test::randomPointsInSquare(seed, 40).plc, ruppert::Options{});
  }
  ruppert::Plc star = ruppert_test::randomStarPolygon(7, 30, 2).plc;
  checkWithConsumers("random star polygon with 2 holes", star, ruppert::Options{});
}

TEST_CASE("consumers: shared data inputs", "[consumers]") {
#ifndef RUPPERT_SHARED_DATA
  WARN("RUPPERT_SHARED_DATA not defined: skipping the shared-data consumer test");
#else
  const fs::path dir(RUPPERT_SHARED_DATA);
  if (!fs::is_directory(dir)) {
    WARN("shared data not found at " << dir.string() << ": skipping");
    return;
  }
  for (const char* name : {"box.poly", "A.poly", "double_hex.poly", "cdt_guitar.poly", "earcut_dude.poly",
                           "cdt_island.poly"}) {
    const fs::path path = dir / name;
    if (!fs::exists(path)) {
      WARN(path.string() << " is missing: skipped");
      continue;
    }
    checkWithConsumers(name, ruppert::readFile(path.string()), ruppert::Options{});
  }
#endif
}
