// The CLI's solver formats and pipelines: --format msh|vtu|geojson,
// - as INPUT (standard input, its format from --input-format or sniffed), -o - (standard output),
// and the progress line on a terminal.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <regex>
#include <string>

#include "ruppert/ruppert.h"

namespace fs = std::filesystem;

namespace {

std::string cli() {
#ifdef RUPPERT_CLI
  return RUPPERT_CLI;
#else
  std::error_code ec;
  return (fs::read_symlink("/proc/self/exe", ec).parent_path().parent_path() / "core" / "ruppert").string();
#endif
}

bool haveCli() {
  if (fs::exists(cli())) return true;
  WARN("ruppert executable not found at '" << cli() << "': skipping");
  return false;
}

fs::path scratch() {
  struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("ruppert-cli-formats-" + std::to_string(::getpid()));
    ~Scratch() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  };
  static const Scratch s;
  fs::create_directories(s.dir);
  return s.dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

struct Run {
  int status = -1;
  std::string out, err;
};

// `prefix` goes before the program (e.g. "cat X |"); args are already quoted.
Run run(const std::string& args, const std::string& prefix = "") {
  const fs::path dir = scratch();
  const std::string command = prefix + " '" + cli() + "' " + args + " >'" + (dir / "out").string() + "' 2>'" +
                              (dir / "err").string() + "'";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir / "out"), slurp(dir / "err")};
}

// JSON output less its one varying field, the wall time.
std::string withoutTime(const std::string& json) {
  return std::regex_replace(json, std::regex("\"milliseconds\": [-+.0-9eE]+"), "");
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// A square with a marked square hole and a region, in all four input formats.
struct Inputs {
  fs::path poly, node, json, geojson;
};

Inputs inputs() {
  const fs::path dir = scratch();
  Inputs in{dir / "annulus.poly", dir / "points.node", dir / "annulus.json", dir / "annulus.geojson"};
  write(in.poly,
        "8 2 0 1\n1 0 0 1\n2 4 0 1\n3 4 4 1\n4 0 4 1\n5 1 1 2\n6 3 1 2\n7 3 3 2\n8 1 3 2\n"
        "8 1\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n5 5 6 7\n6 6 7 7\n7 7 8 7\n8 8 5 7\n1\n1 2 2\n1\n1 0.5 0.5 3 0\n");
  write(in.node, "5 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n4 0.3 0.6\n");
  write(in.json, "{\"points\": [0,0, 4,0, 4,4, 0,4, 1,1, 3,1, 3,3, 1,3],\n"
                 " \"segments\": [0,1, 1,2, 2,3, 3,0, 4,5, 5,6, 6,7, 7,4], \"holes\": [2,2]}\n");
  write(in.geojson, "{\"type\": \"Feature\", \"properties\": {}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": "
                    "[[[0,0],[4,0],[4,4],[0,4],[0,0]], [[1,1],[1,3],[3,3],[3,1],[1,1]]]}}\n");
  return in;
}

}  // namespace

TEST_CASE("cli: --format msh, vtu and geojson write what the library writes", "[cli][formats]") {
  if (!haveCli()) return;
  const Inputs in = inputs();
  const ruppert::Plc plc = ruppert::readFile(in.poly.string());
  const ruppert::Mesh mesh = ruppert::triangulate(plc);
  const fs::path base = scratch() / "out";
  REQUIRE(run("--format msh -o " + q(base) + " " + q(in.poly)).status == 0);
  CHECK(slurp(base.string() + ".msh") == ruppert::toMsh(mesh, plc));
  CHECK_THAT(slurp(base.string() + ".msh"), Catch::Contains("1 5 \"marker 5\"") && Catch::Contains("1 7 \"marker 7\"") &&
                                                Catch::Contains("2 3 \"attribute 3\""));
  REQUIRE(run("--format vtu -o " + q(base) + " " + q(in.poly)).status == 0);
  CHECK(slurp(base.string() + ".vtu") == ruppert::toVtu(mesh, {/*segmentCells=*/true}));
  REQUIRE(run("--format geojson -o " + q(base) + " " + q(in.poly)).status == 0);
  CHECK(slurp(base.string() + ".geojson") == ruppert::toGeoJson(mesh));
  // A .geojson INPUT by its extension: the same domain as the .json annulus (hole seed computed).
  const Run geo = run("--format json -o - " + q(in.geojson));
  REQUIRE(geo.status == 0);
  const ruppert::Mesh fromGeo = ruppert::triangulate(ruppert::readFile(in.geojson.string()));
  CHECK(withoutTime(geo.out) == withoutTime(ruppert::toJson(fromGeo, ruppert::readFile(in.geojson.string()))));
  CHECK(fromGeo.stats.triangles == ruppert::triangulate(ruppert::readFile(in.json.string())).stats.triangles);
}

TEST_CASE("cli: -o - writes the one file to standard output and the summary to standard error", "[cli][formats]") {
  if (!haveCli()) return;
  const Inputs in = inputs();
  const fs::path base = scratch() / "same";
  for (const char* format : {"json", "svg", "msh", "vtu", "geojson"}) {
    INFO(format);
    REQUIRE(run(std::string("--format ") + format + " -o " + q(base) + " " + q(in.poly)).status == 0);
    const Run piped = run(std::string("--format ") + format + " -o - " + q(in.poly));
    REQUIRE(piped.status == 0);
    CHECK(withoutTime(piped.out) == withoutTime(slurp(base.string() + "." + format)));
    CHECK_THAT(piped.err, Catch::StartsWith("ruppert: "));
  }
  const Run triangle = run("-o - " + q(in.poly));
  CHECK(triangle.status == 2);
  CHECK_THAT(triangle.err, Catch::Contains("three") && Catch::Contains("--format"));
}

TEST_CASE("cli: - reads standard input, its format given or sniffed", "[cli][formats]") {
  if (!haveCli()) return;
  const Inputs in = inputs();
  for (const fs::path& file : {in.poly, in.node, in.json, in.geojson}) {
    INFO(file.filename().string());
    const Run fromFile = run("--format msh -o - " + q(file));
    REQUIRE(fromFile.status == 0);
    const Run sniffed = run("--format msh -o - -", "cat " + q(file) + " |");
    REQUIRE(sniffed.status == 0);
    CHECK(sniffed.out == fromFile.out);
    const std::string ext = file.extension().string().substr(1);
    const Run told = run("--input-format " + ext + " --format msh -o - -", "cat " + q(file) + " |");
    REQUIRE(told.status == 0);
    CHECK(told.out == fromFile.out);
  }
  // --input-format overrides a file's extension.
  const fs::path renamed = scratch() / "shape.txt";
  fs::copy_file(in.geojson, renamed, fs::copy_options::overwrite_existing);
  CHECK(run("--input-format geojson --format msh -o - " + q(renamed)).out == run("--format msh -o - " + q(in.geojson)).out);
  CHECK(run(q(renamed)).status == 1);  // no extension to go by
  const Run wrong = run("--input-format poly -", "cat " + q(in.json) + " |");
  CHECK(wrong.status == 1);
  CHECK_THAT(wrong.err, Catch::Contains("<stdin>"));
  const Run junk = run("-", "printf 'not a mesh' |");
  CHECK(junk.status == 1);
  CHECK_THAT(junk.err, Catch::Contains("<stdin>"));
  const Run badGeo = run("-", "printf '{\"type\": \"Point\", \"coordinates\": [0, 0]}' |");
  CHECK(badGeo.status == 1);
  CHECK_THAT(badGeo.err, Catch::Contains("<stdin>") && Catch::Contains("Point"));
  CHECK(run("--input-format svg -").status == 2);
}

TEST_CASE("cli: a progress line on a terminal for runs over a second, none otherwise", "[cli][progress]") {
  if (!haveCli()) return;
  if (std::system("script --version >/dev/null 2>&1") != 0) {
    WARN("script(1) is not available to give the CLI a terminal: skipping");
    return;
  }
  const fs::path square = scratch() / "square.poly";
  write(square, "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n");
  // About 5.3 million triangles, 3-4 s: 1.6 million (max area 1e-6) took 1.7-2.3 s on a loaded
  // machine and 0.996 s on a quiet one, which drew no line.
  const std::string args = "--max-area 3e-7 " + q(square);
  const fs::path typescript = scratch() / "typescript";
  const std::string command = "script -qec \"'" + cli() + "' " + args + "\" " + q(typescript) + " >/dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  const std::string seen = slurp(typescript);
  CHECK_THAT(seen, Catch::Contains("vertices inserted") && Catch::Contains("worst angle") &&
                       Catch::Contains("\r\033[K"));
  const Run plain = run(args);  // standard error is a file here
  REQUIRE(plain.status == 0);
  CHECK_THAT(plain.err, !Catch::Contains("vertices inserted"));
}
