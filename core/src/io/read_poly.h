// What the file reader (read_file.cpp) needs of the .poly reader beyond the public parse functions.
#pragma once

#include <functional>
#include <istream>
#include <string>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

// The whole stream as text; IoError naming `name` when it fails.
std::string readStream(std::istream& in, const std::string& name);

// A .poly's text; `loadNode` supplies the points when it declares none (Triangle's "see the .node
// file"), so the .node file is read only then.
Plc parsePolyLoadingNode(const std::string& text, const std::string& name, const std::function<Plc()>& loadNode);

}  // namespace ruppert::detail
