// write_shape_families OUT_DIR [--seeds N] [--first-seed S] [--family NAME[,NAME...]] [--list]
//
// Writes every shape family (tests/core/shape_families.h) at seeds S .. S+N-1 (default 1 .. 20) to
// OUT_DIR/<family>-<seed>.poly (Triangle's .poly format, 0-based), the input of
// `node tests/bench/compare-triangle.mjs --dir OUT_DIR`. --list prints the families and exits.
// Exit status 0 on success, 1 when a file cannot be written, 2 on a usage error.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "shape_families.h"

namespace {

struct Arguments {
  std::string outDir;
  long seeds = 20, firstSeed = 1;
  std::vector<const ruppert_test::ShapeFamily*> families;
  bool list = false;
};

int usage(const std::string& problem) {
  std::cerr << "write_shape_families: " << problem << "\n"
            << "usage: write_shape_families OUT_DIR [--seeds N] [--first-seed S] [--family NAME[,NAME...]] [--list]\n";
  return 2;
}

bool parseCount(const char* text, long& value, long minimum) {
  char* end = nullptr;
  value = std::strtol(text, &end, 10);
  return end != text && *end == '\0' && value >= minimum;
}

// Returns "" on success, else the problem.
std::string parse(int argc, char** argv, Arguments& args) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--list") {
      args.list = true;
    } else if (a == "--seeds" && hasValue) {
      if (!parseCount(argv[++i], args.seeds, 1)) return "--seeds needs a positive integer";
    } else if (a == "--first-seed" && hasValue) {
      if (!parseCount(argv[++i], args.firstSeed, 0)) return "--first-seed needs a non-negative integer";
    } else if (a == "--family" && hasValue) {
      std::stringstream names(argv[++i]);
      for (std::string name; std::getline(names, name, ',');) {
        const auto* family = ruppert_test::findShapeFamily(name);
        if (!family) return "unknown family '" + name + "' (--list shows them)";
        args.families.push_back(family);
      }
    } else if (!a.empty() && a[0] != '-' && args.outDir.empty()) {
      args.outDir = a;
    } else {
      return "unexpected argument '" + a + "'";
    }
  }
  if (args.families.empty())
    for (const auto& f : ruppert_test::shapeFamilies()) args.families.push_back(&f);
  if (!args.list && args.outDir.empty()) return "OUT_DIR is missing";
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  const std::string problem = parse(argc, argv, args);
  if (!problem.empty()) return usage(problem);
  if (args.list) {
    for (const auto* f : args.families)
      std::cout << f->name << " (size " << f->minSize << ".." << f->maxSize << "): " << f->what << "\n";
    return 0;
  }
  std::error_code error;
  std::filesystem::create_directories(args.outDir, error);
  std::size_t written = 0;
  for (const auto* family : args.families)
    for (long seed = args.firstSeed; seed < args.firstSeed + args.seeds; ++seed) {
      const auto member = ruppert_test::familyMember(*family, std::uint64_t(seed));
      std::ostringstream comment;
      comment << family->name << " seed " << seed << " size " << ruppert_test::familySize(*family, std::uint64_t(seed))
              << " area " << member.area << " (tests/core/shape_families.cpp)";
      const std::string path = args.outDir + "/" + family->name + "-" + std::to_string(seed) + ".poly";
      std::ofstream out(path);
      out << ruppert_test::plcToPolyText(member.plc, comment.str());
      if (!out.flush()) {
        std::cerr << "write_shape_families: cannot write " << path << "\n";
        return 1;
      }
      ++written;
    }
  std::cout << "wrote " << written << " PLCs (" << args.families.size() << " families x " << args.seeds
            << " seeds) to " << args.outDir << "\n";
  return 0;
}
