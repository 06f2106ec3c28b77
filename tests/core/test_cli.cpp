// The `ruppert` executable, run as a user would: exit statuses, messages and output files.
//
// The binary is found through RUPPERT_CLI (a path the build may define) or, failing that, beside
// this test binary's build tree (build/tests/ruppert_tests -> build/core/ruppert). When it is not
// there the tests say so and skip.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "ruppert/ruppert.h"

namespace fs = std::filesystem;

namespace {

#ifdef RUPPERT_FIXTURES
const std::string kCliFixtures = std::string(RUPPERT_FIXTURES) + "/io/";
#else
const std::string kCliFixtures = "tests/fixtures/io/";
#endif

std::string cliPath() {
#ifdef RUPPERT_CLI
  return RUPPERT_CLI;
#else
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  return (self.parent_path().parent_path() / "core" / "ruppert").string();
#endif
}

struct Run {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A scratch directory per test process, removed when the process exits.
fs::path scratch() {
  struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("ruppert-cli-test-" + std::to_string(::getpid()));
    ~Scratch() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  };
  static const Scratch scratch;
  fs::create_directories(scratch.dir);
  return scratch.dir;
}

// Runs the CLI with `args` (already shell-quoted where needed).
Run run(const std::string& args) {
  const fs::path dir = scratch();
  const std::string command = "'" + cliPath() + "' " + args + " >'" + (dir / "stdout").string() + "' 2>'" +
                              (dir / "stderr").string() + "'";
  Run r;
  const int raw = std::system(command.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(dir / "stdout");
  r.err = slurp(dir / "stderr");
  return r;
}

bool haveCli() {
  if (fs::exists(cliPath())) return true;
  WARN("ruppert executable not found at '" << cliPath() << "': skipping CLI tests");
  return false;
}

}  // namespace

TEST_CASE("cli: --help and --version succeed", "[io][cli]") {
  if (!haveCli()) return;
  const Run help = run("--help");
  CHECK(help.status == 0);
  CHECK_THAT(help.out, Catch::StartsWith("usage: ruppert"));
  CHECK_THAT(help.out, Catch::Contains("--min-angle"));
  const Run version = run("--version");
  CHECK(version.status == 0);
  CHECK_THAT(version.out, Catch::StartsWith("ruppert "));
}

TEST_CASE("cli: numbers are parsed strictly", "[io][cli]") {
  if (!haveCli()) return;
  // Parsing happens before --help is acted on, so these isolate the number parser.
  CHECK(run("--max-area 5e-8 --help").status == 0);
  CHECK(run("--min-angle 20.5 --max-steiner 100 --help").status == 0);
  CHECK(run("--min-angle=25 --help").status == 0);
  for (const char* bad : {"--min-angle abc", "--min-angle ''", "--min-angle 1x", "--min-angle ' 5'",
                          "--max-area nan", "--max-area inf", "--max-steiner -1", "--max-steiner 1.5",
                          "--min-angle 61", "--max-area -1", "--min-angle"}) {
    INFO(bad);
    const Run r = run(std::string(bad) + " --help");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("usage: ruppert"));
    CHECK(r.out.empty());
  }
}

TEST_CASE("cli: usage errors exit 2", "[io][cli]") {
  if (!haveCli()) return;
  for (const char* bad : {"", "--bogus x.poly", "a.poly b.poly", "--format png x.poly", "--placement middle x.poly",
                          "--variant tree x.poly", "--stats=1 x.poly"}) {
    INFO(bad);
    const Run r = run(bad);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("error: ") && Catch::Contains("usage: ruppert"));
  }
}

TEST_CASE("cli: invalid input exits 1 with the reader's message", "[io][cli]") {
  if (!haveCli()) return;
  const Run missing = run("'" + kCliFixtures + "no-such-input.poly'");
  CHECK(missing.status == 1);
  CHECK_THAT(missing.err, Catch::StartsWith("error: ") && Catch::Contains("no-such-input.poly"));

  const fs::path bad = scratch() / "bad-segment.poly";
  std::ofstream(bad) << "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 9\n0\n";
  const Run r = run("'" + bad.string() + "'");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("bad-segment.poly:6: segment 1 refers to point 9 but there are 3 points"));
  CHECK(r.out.empty());
}

TEST_CASE("cli: meshes a file, prints the summary and writes every format", "[io][cli]") {
  if (!haveCli()) return;
  // A square with a square hole and no area bounds, so --min-angle 0 gives the plain CDT.
  const fs::path annulus = scratch() / "annulus.json";
  std::ofstream(annulus) << "{\"points\": [0,0, 4,0, 4,4, 0,4, 1,1, 3,1, 3,3, 1,3],\n"
                            " \"segments\": [0,1, 1,2, 2,3, 3,0, 4,5, 5,6, 6,7, 7,4], \"holes\": [2,2]}\n";
  const std::string input = "'" + annulus.string() + "'";

  const Run summary = run("--min-angle 0 " + input);
  REQUIRE(summary.status == 0);
  const std::regex line(
      R"(ruppert: (\d+) vertices, (\d+) triangles, min angle [0-9.]+, max angle [0-9.]+, (complete|incomplete), [0-9.]+ ms\n[^]*)");
  std::smatch m;
  REQUIRE(std::regex_match(summary.out, m, line));
  const unsigned long triangles = std::stoul(m[2]);
  // The square with a square hole has 8 corners: any triangulation of that annulus has 8 triangles.
  CHECK(triangles == 8);

  const Run quiet = run("--quiet --min-angle 0 " + input);
  CHECK(quiet.status == 0);
  CHECK(quiet.out.empty());

  const fs::path base = scratch() / "square";
  const Run tri = run("--min-angle 0 -o '" + base.string() + "' " + input);
  REQUIRE(tri.status == 0);
  const ruppert::Plc written = ruppert::readFile(base.string() + ".poly");
  const ruppert::Plc input16 = ruppert::readFile(annulus.string());
  CHECK(written.points.size() >= input16.points.size());
  CHECK(written.holes == input16.holes);
  CHECK(fs::file_size(base.string() + ".node") > 0);
  // .ele: header then one line per triangle.
  std::ifstream ele(base.string() + ".ele");
  std::size_t declared = 0;
  ele >> declared;
  CHECK(declared == triangles);

  REQUIRE(run("--min-angle 0 --format json -o '" + base.string() + "' " + input).status == 0);
  const ruppert::Plc json = ruppert::readFile(base.string() + ".json");
  CHECK(json.points == written.points);
  CHECK_THAT(slurp(base.string() + ".json"), Catch::Contains("\"triangles\": ["));

  REQUIRE(run("--min-angle 0 --format svg -o '" + base.string() + "' " + input).status == 0);
  CHECK_THAT(slurp(base.string() + ".svg"), Catch::StartsWith("<svg "));

  const fs::path trace = scratch() / "trace.jsonl";
  REQUIRE(run("--quiet --stats --min-angle 0 --trace '" + trace.string() + "' " + input).status == 0);
  CHECK(fs::exists(trace));
}

TEST_CASE("cli: an unwritable output exits 3", "[io][cli]") {
  if (!haveCli()) return;
  const std::string input = "'" + kCliFixtures + "square-with-hole.json'";
  const std::string nowhere = (scratch() / "no-such-dir" / "out").string();
  const Run r = run("--min-angle 0 -o '" + nowhere + "' " + input);
  CHECK(r.status == 3);
  CHECK_THAT(r.err, Catch::StartsWith("error: cannot write"));
  const Run t = run("--min-angle 0 --trace '" + nowhere + ".jsonl' " + input);
  CHECK(t.status == 3);
}

TEST_CASE("cli: an unknown option gets the nearest one as a did-you-mean", "[io][cli]") {
  if (!haveCli()) return;
  const std::pair<const char*, const char*> near[] = {
      {"--min-angel 20", "unknown option '--min-angel' (did you mean --min-angle?)"},
      {"--min-angel=20", "unknown option '--min-angel' (did you mean --min-angle?)"},
      {"--maxarea 0.1", "unknown option '--maxarea' (did you mean --max-area?)"},
      {"-min-angle 20", "unknown option '-min-angle' (did you mean --min-angle?)"},
      {"--QUIET", "unknown option '--QUIET' (did you mean --quiet?)"},
      {"--edge", "unknown option '--edge' (did you mean --edges?)"},
      {"--no-segment-steinr", "unknown option '--no-segment-steinr' (did you mean --no-segment-steiner?)"},
  };
  for (const auto& [args, message] : near) {
    INFO(args);
    const Run r = run(std::string(args) + " x.poly");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::StartsWith(std::string("error: ") + message + "\n"));
  }
  // Nothing near enough: no guess. Short names only match ignoring case.
  for (const char* args : {"--bogus", "--angle 20", "-x", "--mesh-it"}) {
    INFO(args);
    const Run r = run(std::string(args) + " x.poly");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("unknown option"));
    CHECK_THAT(r.err, !Catch::Contains("did you mean"));
  }
}

TEST_CASE("cli: --help and the usage line fit 80 columns", "[io][cli]") {
  if (!haveCli()) return;
  const Run help = run("--help");
  REQUIRE(help.status == 0);
  const Run usage = run("--bogus x.poly");
  REQUIRE(usage.status == 2);
  for (const std::string& text : {help.out, usage.err}) {
    std::istringstream lines(text);
    std::size_t count = 0;
    for (std::string line; std::getline(lines, line); ++count) {
      INFO(line);
      CHECK(line.size() <= 80);
    }
    CHECK(count >= 8);  // the usage line alone takes eight
  }
  CHECK_THAT(help.out, Catch::Contains("\nExamples"));
}

TEST_CASE("cli: every example of --help runs as written on the shipped inputs", "[io][cli]") {
  if (!haveCli()) return;
  // The examples name docs/examples/... from the top of the source tree (RUPPERT_FIXTURES is
  // tests/fixtures): run them in a scratch folder holding a link to docs/, with `ruppert` the binary.
  const fs::path source = fs::path(kCliFixtures).parent_path().parent_path().parent_path().parent_path();
  REQUIRE(fs::exists(source / "docs" / "examples"));
  const fs::path dir = scratch() / "help-examples";
  fs::create_directories(dir);
  std::error_code ec;
  fs::create_directory_symlink(source / "docs", dir / "docs", ec);
  const Run help = run("--help");
  std::istringstream lines(help.out);
  int examples = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  ruppert ", 0) != 0) continue;
    ++examples;
    INFO(line);
    const std::string command = "cd '" + dir.string() + "' && ('" + cliPath() + "'" + line.substr(9) + ") >/dev/null 2>&1";
    const int raw = std::system(command.c_str());
    CHECK((WIFEXITED(raw) && WEXITSTATUS(raw) == 0));
  }
  CHECK(examples >= 3);
  CHECK(fs::file_size(dir / "lake.ele") > 0);
  CHECK(fs::file_size(dir / "plate.vtu") > 0);
  CHECK_THAT(slurp(dir / "park.msh"), Catch::StartsWith("$MeshFormat"));
}

namespace {

// The option table's spellings of one option ("-e|--edges DEG" -> "-e", "--edges").
std::vector<std::string> spellings(const char* flag) {
  std::string text = flag;
  text = text.substr(0, text.find(' '));
  std::vector<std::string> out;
  std::istringstream parts(text);
  for (std::string part; std::getline(parts, part, '|');) out.push_back(part);
  return out;
}

// Values the option must accept, as the command line spells them.
template <class Spec>
std::vector<std::string> acceptedValues() {
  using T = std::decay_t<decltype(Spec::fallback)>;
  if constexpr (std::is_same_v<T, bool>) {
    return {""};
  } else if constexpr (std::is_enum_v<T>) {
    return {std::begin(ruppert::valueNames(Spec::fallback)), std::end(ruppert::valueNames(Spec::fallback))};
  } else if constexpr (std::is_same_v<T, int>) {
    if (Spec::high - Spec::low > 3) return {std::to_string(int(Spec::low)), std::to_string(int(Spec::high))};
    std::vector<std::string> out;
    for (int i = static_cast<int>(Spec::low); i <= static_cast<int>(Spec::high); ++i) out.push_back(std::to_string(i));
    return out;
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    return {"0", "5"};
  } else {
    return {std::to_string(Spec::low), "5"};
  }
}

// Every spelling of a flagged option: in the usage line and --help, and parsed with each value it
// accepts (parsing happens before --help is acted on); a number just outside its range is refused.
template <class Spec>
void checkFlag(const std::string& help) {
  if (*Spec::flag == '\0') return;
  const std::string usage = help.substr(0, help.find("\n\n"));
  for (const std::string& spelling : spellings(Spec::flag)) {
    INFO(spelling);
    CHECK_THAT(usage, Catch::Contains("[" + spelling) || Catch::Contains("|" + spelling));
    CHECK_THAT(help.substr(usage.size()), Catch::Contains("  " + spelling) || Catch::Contains(", " + spelling));
    for (const std::string& value : acceptedValues<Spec>()) {
      INFO(value);
      CHECK(run(spelling + " " + value + " --help").status == 0);
    }
    if constexpr (std::is_same_v<std::decay_t<decltype(Spec::fallback)>, double>) {
      const double outside = Spec::high < ruppert::kUnbounded ? Spec::high + 1 : Spec::low - 1;
      const Run r = run(spelling + " " + std::to_string(outside) + " --help");
      CHECK(r.status == 2);
      if (Spec::high < ruppert::kUnbounded) CHECK_THAT(r.err, Catch::Contains(" must be between "));
    }
  }
}

}  // namespace

TEST_CASE("cli: every flag of the option table is parsed, listed and range-checked", "[io][cli]") {
  if (!haveCli()) return;
  const std::string help = run("--help").out;
#define CHECK_FLAG_(KEY, ...) checkFlag<ruppert::option::KEY>(help);
  RUPPERT_MESH_OPTIONS(CHECK_FLAG_)
  RUPPERT_DERIVED_OPTIONS(CHECK_FLAG_)
#undef CHECK_FLAG_
}

TEST_CASE("cli: --smooth takes an optional number of passes, in range", "[io][cli][smooth]") {
  if (!haveCli()) return;
  const std::string input = "'" + kCliFixtures + "square-with-round-hole.json' -o -";
  const Run plain = run("--min-angle 30 --format json " + input);
  const Run alone = run("--min-angle 30 --format json --smooth " + input);
  const std::string passes = std::to_string(ruppert::kSmoothPassesWhenOn);
  const Run given = run("--min-angle 30 --format json --smooth " + passes + " " + input);
  const Run inlined = run("--min-angle 30 --format json --smooth=" + passes + " " + input);
  INFO(plain.err << alone.err << given.err);
  REQUIRE(plain.status == 0);
  REQUIRE(alone.status == 0);
  // The points come first in the JSON, before the stats (whose time differs from run to run).
  const auto points = [](const Run& r) { return r.out.substr(0, r.out.find("\"segments\"")); };
  CHECK(points(alone) != points(plain));  // vertices moved
  CHECK(points(given) == points(alone));  // alone: kSmoothPassesWhenOn passes
  CHECK(points(inlined) == points(alone));
  CHECK(points(run("--smooth 0 --min-angle 30 --format json " + input)) == points(plain));
  const Run over = run("--smooth 101 x.poly");
  CHECK(over.status == 2);
  CHECK_THAT(over.err, Catch::Contains("--smooth: '101' is not an integer from 0 to 100"));
  CHECK(run("--smooth=x x.poly").status == 2);
}

TEST_CASE("cli: --help gives the option table's numbers, no placeholder", "[io][cli]") {
  if (!haveCli()) return;
  const std::string help = run("--help").out;
  using Angle = ruppert::option::minAngle;
  char range[64];
  std::snprintf(range, sizeof range, "%g..%g (default %g)", Angle::low, Angle::high, Angle::fallback);
  CHECK_THAT(help, Catch::Contains(range));
  for (const char* placeholder : {"{min}", "{max}", "{default}"}) CHECK_THAT(help, !Catch::Contains(placeholder));
  const Run r = run("--min-angle " + std::to_string(Angle::high + 1) + " x.poly");
  std::snprintf(range, sizeof range, "must be between %g and %g %s", Angle::low, Angle::high, Angle::unit);
  CHECK_THAT(r.err, Catch::Contains(range));
}

TEST_CASE("cli: curves from JSON are meshed to --curve-tolerance", "[io][cli][curves]") {
  if (!haveCli()) return;
  const std::string input = "'" + kCliFixtures + "square-with-round-hole.json'";
  const Run coarse = run("--min-angle 30 --curve-tolerance 1e-3 " + input);
  const Run fine = run("--min-angle 30 --curve-tolerance 1e-5 " + input);
  INFO(coarse.out << coarse.err << fine.out << fine.err);
  REQUIRE(coarse.status == 0);
  REQUIRE(fine.status == 0);
  CHECK_THAT(coarse.out, Catch::Contains("min angle 30.00") && Catch::Contains("complete"));
  CHECK_THAT(fine.out, Catch::Contains("complete"));
  // "ruppert: V vertices, ...": a hundredth of the tolerance takes many more vertices on the circle.
  auto vertices = [](const std::string& summary) { return std::stoi(summary.substr(summary.find(": ") + 2)); };
  CHECK(vertices(fine.out) > 4 * vertices(coarse.out));
  CHECK(run("--curve-tolerance -1 " + input).status == 2);
}
