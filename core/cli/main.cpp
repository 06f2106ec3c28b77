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

#include "cli_args.h"
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

void writeOutputs(const ruppert::cli::CliArgs& args, const ruppert::Mesh& mesh, const ruppert::Plc& plc) {
  using ruppert::cli::OutputFormat;
  const std::string& base = args.outputBase;
  if (!base.empty()) {
    switch (args.format) {
      case OutputFormat::Triangle:
        writeFile(base + ".node", [&](std::ostream& out) { ruppert::writeNode(out, mesh); });
        writeFile(base + ".ele", [&](std::ostream& out) { ruppert::writeEle(out, mesh); });
        writeFile(base + ".poly", [&](std::ostream& out) { ruppert::writePoly(out, mesh, plc); });
        if (args.options.edges) writeFile(base + ".edge", [&](std::ostream& out) { ruppert::writeEdge(out, mesh); });
        break;
      case OutputFormat::Json:
        writeFile(base + ".json", [&](std::ostream& out) { ruppert::writeJson(out, mesh, plc); });
        break;
      case OutputFormat::Svg:
        writeFile(base + ".svg", [&](std::ostream& out) { ruppert::writeSvg(out, mesh); });
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
    plc = ruppert::readFile(args.input);
    mesh = ruppert::triangulate(plc, args.options);
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
  if (!args.quiet) std::cout << ruppert::cli::summaryText(mesh);
  if (args.stats) std::cout << ruppert::cli::statsText(mesh.stats);
  std::cout.flush();
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
