#include "cli_input.h"

#include <fstream>
#include <iostream>
#include <iterator>

namespace ruppert::cli {
namespace {

std::string readStream(std::istream& in, const std::string& name) {
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(ErrorCode::IoError, name + ": read failed");
  return text;
}

std::string readPath(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(ErrorCode::IoError, path + ": cannot open for reading");
  return readStream(file, path);
}

// Triangle's text without an extension: a .poly has a segment section after its points, a .node
// ends there. Parsing as .poly first and falling back to .node tells them apart; when both fail the
// .poly reader's message is the one shown (it names the line where the text stopped making sense).
Plc parseTriangleText(const std::string& text, const std::string& name) {
  try {
    return parsePoly(text, name);
  } catch (const Error& polyError) {
    if (polyError.code() != ErrorCode::ParseError) throw;
    try {
      return parseNode(text, name);
    } catch (const Error&) {
      throw polyError;
    }
  }
}

Plc parseAs(const std::string& format, const std::string& text, const std::string& name) {
  if (format == "poly") return parsePoly(text, name);
  if (format == "node") return parseNode(text, name);
  if (format == "json") return parseJson(text, name);
  if (format == "geojson") return parseGeoJson(text, name);
  return parseTriangleText(text, name);
}

}  // namespace

std::string sniffFormat(const std::string& text) {
  std::size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) ++i;
  if (i == text.size() || text[i] != '{') return "triangle";
  const bool geo = text.find("\"type\"") != std::string::npos && text.find("\"points\"") == std::string::npos;
  return geo ? "geojson" : "json";
}

Plc readInput(const std::string& input, const std::string& format) {
  if (input == "-") {
    const std::string name = "<stdin>";
    const std::string text = readStream(std::cin, name);
    return parseAs(format.empty() ? sniffFormat(text) : format, text, name);
  }
  // Without --input-format, readFile goes by the extension (and finds a .poly's .node file).
  if (format.empty()) return readFile(input);
  return parseAs(format, readPath(input), input);
}

}  // namespace ruppert::cli
