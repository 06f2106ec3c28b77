// Reading a PLC from files by name: the one place that maps an extension to its reader, and the
// sibling files some formats need (a .poly's .node, an .ele's .node, .poly and .area).
#include <cctype>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "io/read_poly.h"
#include "mesh/huge_pages.h"
#include "ruppert/ruppert.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert {
namespace {

using detail::readStream;

std::string lowerExtension(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return ext;
}

// In one read of the file's size where it has one: read character by character, the string grows
// by doubling, and 10^6 points' 47 MB of text are copied several times over.
std::string readWholeFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) throw Error(ErrorCode::IoError, path + ": cannot open for reading");
  const std::streamoff size = file.tellg();
  file.seekg(0);
  if (size <= 0 || !file) {  // no size (a pipe, a device): read as a stream
    file.clear();
    file.seekg(0);
    return readStream(file, path);
  }
  std::string text;
  detail::reserveHuge(text, static_cast<std::size_t>(size));
  text.resize(static_cast<std::size_t>(size));
  file.read(&text[0], size);
  if (file.bad()) throw Error(ErrorCode::IoError, path + ": read failed");
  text.resize(static_cast<std::size_t>(file.gcount()));
  if (file) text += readStream(file, path);  // whatever the file gained since its size was taken
  return text;
}

std::string slurpFile(const std::string& path, bool& exists) {
  std::ifstream file(path, std::ios::binary);
  exists = static_cast<bool>(file);
  if (!exists) return "";
  std::ostringstream s;
  s << file.rdbuf();
  if (file.bad()) throw Error(ErrorCode::IoError, path + ": read failed");
  return s.str();
}

}  // namespace

Plc readFile(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".node") return parseNode(readWholeFile(path), path);
  if (ext == ".ele") return readEleFiles(path);  // refining a mesh
  if (ext == ".json") {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(ErrorCode::IoError, path + ": cannot open for reading");
    return readJson(file, path);
  }
  if (ext == ".geojson") return parseGeoJson(readWholeFile(path), path);
  if (ext == ".poly") {
    // Same base name; keep the case of the extension the user wrote ("A.POLY" -> "A.NODE").
    const std::string written = path.substr(path.size() - ext.size());
    const std::string nodePath = path.substr(0, path.size() - ext.size()) + (written == ext ? ".node" : ".NODE");
    return detail::parsePolyLoadingNode(readWholeFile(path), path, [&nodePath]() { return parseNode(readWholeFile(nodePath), nodePath); });
  }
  throw Error(ErrorCode::IoError, path + ": unknown extension; expected .poly, .node, .ele, .json or .geojson");
}

Plc readEleFiles(const std::string& elePath) {
  const std::size_t dot = elePath.find_last_of('.');
  const std::string stem = elePath.substr(0, dot);
  const bool upper = elePath.substr(dot) == ".ELE";
  auto sibling = [&](const char* ext) {
    std::string e = ext;
    if (upper)
      for (char& c : e) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return stem + e;
  };
  MeshFiles files;
  bool exists = false;
  files.eleName = elePath, files.nodeName = sibling(".node"), files.polyName = sibling(".poly"), files.areaName = sibling(".area");
  files.ele = slurpFile(elePath, exists);
  if (!exists) throw Error(ErrorCode::IoError, elePath + ": cannot open for reading");
  files.node = slurpFile(files.nodeName, exists);
  if (!exists) throw Error(ErrorCode::IoError, files.nodeName + ": cannot open for reading (refining " + elePath + " needs its points)");
  files.poly = slurpFile(files.polyName, files.hasPoly);
  files.area = slurpFile(files.areaName, files.hasArea);
  return parseMeshFiles(files);
}

}  // namespace ruppert
RUPPERT_COLD_END
