// What the CLI makes of the option table (ruppert/option_table.h): a flag's spellings and value
// name, an enum option's values in the order the CLI lists them, numbers as the help prints them.
// Shared by the parser (cli_args.cpp) and the help (cli_help.cpp), so that both read the table alike.
#pragma once

#include <string>
#include <vector>

#include "ruppert/ruppert.h"

namespace ruppert::cli {

// "--min-angle DEG" -> {"--min-angle"}; "-e|--edges" -> {"-e", "--edges"}.
std::vector<std::string> spellingsOf(const char* flag);
// "--min-angle DEG" -> "DEG"; "--convex-hull" -> "".
std::string valueNameOf(const char* flag);
// 30 -> "30", 0.5 -> "0.5".
std::string numberText(double value);

// An enum option's values by name: the default first, then the others in the enum's order.
template <class Enum>
std::vector<std::string> choicesOf(Enum fallback) {
  std::vector<std::string> names{enumName(fallback)};
  for (const char* name : valueNames(fallback))
    if (names.front() != name) names.emplace_back(name);
  return names;
}

}  // namespace ruppert::cli
