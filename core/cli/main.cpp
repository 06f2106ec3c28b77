// `ruppert`: mesh a .poly/.node/.json file from the command line.
//
// Exit status: 0 success, 1 invalid input (or an internal failure), 2 usage error, 3 an output file
// could not be written. Every exception is caught here: the program reports, it never crashes.
#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <unistd.h>  // isatty: the progress line is for terminals only

#include "cli_args.h"
#include "cli_input.h"
#include "cli_progress.h"
#include "cli_report.h"
#include "ruppert/ruppert.h"

#ifndef RUPPERT_VERSION
#define RUPPERT_VERSION "0.1.0"  // keep in step with project(VERSION) in the top CMakeLists.txt
#endif

namespace {

constexpr int kExitOk = 0;
constexpr int kExitInvalidInput = 1;
constexpr int kExitUsage = 2;
constexpr int kExitWriteFailed = 3;

// An output file that could not be written; carries the message for stderr.
struct WriteFailure {
  std::string message;
};

void writeFile(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw WriteFailure{"cannot write '" + path + "': " + std::strerror(errno)};
  try {
    write(file);
  } catch (const ruppert::Error& e) {
    if (e.code() != ruppert::ErrorCode::IoError) throw;
    throw WriteFailure{"writing '" + path + "' failed: " + e.what()};
  }
  file.close();
  if (!file) throw WriteFailure{"writing '" + path + "' failed"};
}

// The one file of a single-file format: BASE + ext, or standard output for -o -.
void writeSingle(const std::string& base, const char* ext, const std::function<void(std::ostream&)>& write) {
  if (base != "-") return writeFile(base + ext, write);
  try {
    write(std::cout);
  } catch (const ruppert::Error& e) {
    if (e.code() != ruppert::ErrorCode::IoError) throw;
    throw WriteFailure{std::string("writing to standard output failed: ") + e.what()};
  }
  std::cout.flush();
  if (!std::cout) throw WriteFailure{"writing to standard output failed"};
}

void writeOutputs(const ruppert::cli::CliArgs& args, ruppert::Mesh& mesh, const ruppert::Plc& plc) {
  using ruppert::cli::OutputFormat;
  const std::string& base = args.outputBase;
  if (!base.empty() && args.voronoi) {
    const ruppert::Voronoi voronoi = ruppert::voronoiDiagram(mesh);
    writeFile(base + ".v.node", [&](std::ostream& out) { ruppert::writeVoronoiNode(out, voronoi, mesh); });
    writeFile(base + ".v.edge", [&](std::ostream& out) { ruppert::writeVoronoiEdge(out, voronoi, mesh); });
  }
  if (!base.empty() && args.order == 2) ruppert::addQuadraticNodes(mesh);
  if (!base.empty()) {
    switch (args.format) {
      case OutputFormat::Triangle:
        writeFile(base + ".node", [&](std::ostream& out) { ruppert::writeNode(out, mesh); });
        writeFile(base + ".ele", [&](std::ostream& out) { ruppert::writeEle(out, mesh); });
        writeFile(base + ".poly", [&](std::ostream& out) { ruppert::writePoly(out, mesh, plc); });
        if (args.options.edges) writeFile(base + ".edge", [&](std::ostream& out) { ruppert::writeEdge(out, mesh); });
        break;
      case OutputFormat::Json:
        writeSingle(base, ".json", [&](std::ostream& out) { ruppert::writeJson(out, mesh, plc); });
        break;
      case OutputFormat::Svg:
        writeSingle(base, ".svg", [&](std::ostream& out) { ruppert::writeSvg(out, mesh); });
        break;
      case OutputFormat::Msh:
        writeSingle(base, ".msh", [&](std::ostream& out) { ruppert::writeMsh(out, mesh, plc); });
        break;
      case OutputFormat::Vtu:
        writeSingle(base, ".vtu", [&](std::ostream& out) { ruppert::writeVtu(out, mesh, {/*segmentCells=*/true}); });
        break;
      case OutputFormat::GeoJson:
        writeSingle(base, ".geojson", [&](std::ostream& out) { ruppert::writeGeoJson(out, mesh); });
        break;
    }
  }
  if (!args.tracePath.empty()) {
    writeFile(args.tracePath, [&](std::ostream& out) {
      ruppert::cli::writeTrace(out, mesh);
      out.flush();
      if (!out) throw ruppert::Error(ruppert::ErrorCode::IoError, "trace output failed");
    });
  }
}

int run(int argc, char** argv) {
  ruppert::cli::CliArgs args;
  try {
    args = ruppert::cli::parseArgs(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const ruppert::cli::UsageError& e) {
    std::cerr << "error: " << e.what() << '\n' << ruppert::cli::usageLine() << '\n';
    return kExitUsage;
  }
  if (args.help) {
    std::cout << ruppert::cli::helpText();
    return kExitOk;
  }
  if (args.version) {
    std::cout << "ruppert " << RUPPERT_VERSION << '\n';
    return kExitOk;
  }

  ruppert::Plc plc;
  ruppert::Mesh mesh;
  try {
    plc = ruppert::cli::readInput(args.input, args.inputFormat);
    // A progress line for runs over a second, on a terminal only (see cli_progress.h).
    ruppert::cli::ProgressLine progress(!args.quiet && isatty(STDERR_FILENO));
    args.options.onProgress = [&progress](const ruppert::Progress& p) { return progress.update(p); };
    mesh = ruppert::triangulate(plc, args.options);
    progress.finish();
    args.options.onProgress = nullptr;  // it refers to `progress`, which ends here
  } catch (const ruppert::Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    if (e.code() == ruppert::ErrorCode::InvalidOption) {
      std::cerr << ruppert::cli::usageLine() << '\n';
      return kExitUsage;
    }
    return kExitInvalidInput;
  }

  if (!args.quiet) {
    for (const ruppert::Notice& n : mesh.notices) std::cerr << "warning: " << n.message << '\n';
  }
  try {
    writeOutputs(args, mesh, plc);
  } catch (const WriteFailure& f) {
    std::cerr << "error: " << f.message << '\n';
    return kExitWriteFailed;
  }
  // With -o - standard output holds the mesh, so the reports go to standard error.
  std::ostream& report = args.outputBase == "-" ? std::cerr : std::cout;
  if (!args.quiet) report << ruppert::cli::summaryText(mesh);
  if (args.stats) report << ruppert::cli::statsText(mesh.stats);
  report.flush();
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const ruppert::Error& e) {
    std::cerr << "error: " << e.what() << '\n';
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << "error: internal: " << e.what() << '\n';
  } catch (...) {
    std::cerr << "error: internal: unknown exception\n";
  }
  return kExitInvalidInput;
}
