// Readers for refining a mesh: Triangle's .ele and .area formats, as documented with Triangle:
//   .ele   first line:  <#triangles> [<nodes per triangle (3 or more)> [<#attributes>]]
//          then:        <triangle #> <node> <node> <node> [more nodes] [attributes]
//   .area  first line:  <#triangles>
//          then:        <triangle #> <maximum area>     (negative or 0: no bound)
// Node numbers count from the .node file's base (its first point's number). '#' starts a comment;
// blank lines are ignored. Each error names the file, the line and the offending value.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "message.h"
#include "ruppert/ruppert.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert {
namespace {

using detail::message;
using std::to_string;

class Records {
 public:
  Records(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  // The fields of the next non-blank line, or false at the end.
  bool next(std::vector<std::string_view>& fields) {
    fields.clear();
    while (fields.empty() && pos_ < text_.size()) {
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string::npos) end = text_.size();
      std::string_view line(text_.data() + pos_, end - pos_);
      pos_ = end + 1, ++line_;
      line = line.substr(0, line.find('#'));
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) fields.push_back(line.substr(start, i - start));
      }
    }
    return !fields.empty();
  }

  [[noreturn]] void fail(const std::string& text, ErrorCode code = ErrorCode::ParseError) const {
    throw Error(code, detail::message({name_, ":", to_string(line_), ": ", text}));
  }

  void require(std::vector<std::string_view>& fields, const std::string& what) {
    if (!next(fields)) fail(message({"expected ", what, ", found end of file"}));
  }

  void end(std::vector<std::string_view>& fields, const std::string& after) {
    if (next(fields)) fail(message({"unexpected '", fields[0], "' after the ", after}));
  }

  long long integer(std::string_view field, const std::string& what) const {
    const std::string s(field);
    char* stop = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &stop, 10);
    if (s.empty() || stop != s.c_str() + s.size() || errno == ERANGE) fail(message({what, " '", s, "' is not an integer"}));
    return v;
  }

  double real(std::string_view field, const std::string& what) const {
    const std::string s(field);
    char* stop = nullptr;
    const double v = std::strtod(s.c_str(), &stop);
    if (s.empty() || stop != s.c_str() + s.size() || std::isnan(v)) fail(message({what, " '", s, "' is not a number"}));
    return v;
  }

  // A count no larger than the rest of the text could hold (two bytes a record at least).
  std::size_t count(std::string_view field, const std::string& what) const {
    const long long v = integer(field, what);
    if (v < 0) fail(message({what, " '", field, "' is negative"}));
    if (static_cast<unsigned long long>(v) > text_.size() - std::min(pos_, text_.size()))
      fail(message({what, " ", field, " is more than the rest of the file could hold"}), ErrorCode::TooLarge);
    return static_cast<std::size_t>(v);
  }

 private:
  const std::string& text_;
  const std::string& name_;
  std::size_t pos_ = 0, line_ = 0;
};

// The corners of every triangle, 0-based.
std::vector<std::uint32_t> parseEle(const std::string& text, const std::string& name, std::size_t points, int base) {
  Records in(text, name);
  std::vector<std::string_view> f;
  in.require(f, "the triangle count line");
  const std::size_t count = in.count(f[0], "triangle count");
  const std::size_t nodes = f.size() > 1 ? in.count(f[1], "nodes per triangle") : 3;
  const std::size_t attributes = f.size() > 2 ? in.count(f[2], "number of triangle attributes") : 0;
  if (nodes < 3) in.fail(message({"nodes per triangle must be 3 or more (3 or 6 as Triangle writes), found ", to_string(nodes)}));
  std::vector<std::uint32_t> triangles;
  triangles.reserve(3 * count);
  for (std::size_t t = 0; t < count; ++t) {
    const std::string item = message({"triangle ", to_string(t + base)});
    in.require(f, message({item, " (", to_string(count), " declared)"}));
    if (f.size() != 1 + nodes + attributes)
      in.fail(message({item, ": expected ", to_string(1 + nodes + attributes), " fields (number, ", to_string(nodes), " nodes, ",
                       to_string(attributes), " attributes), found ", to_string(f.size())}));
    in.integer(f[0], message({item, ": number"}));
    for (std::size_t i = 1; i <= 3; ++i) {
      const long long v = in.integer(f[i], message({item, ": node"}));
      if (v < base || v >= static_cast<long long>(points) + base)
        in.fail(message({item, ": node ", to_string(v), " is not a point of the .node file (", to_string(points),
                         " points numbered from ", to_string(base), ")"}),
                ErrorCode::IndexOutOfRange);
      triangles.push_back(static_cast<std::uint32_t>(v - base));
    }
    for (std::size_t i = 4; i < f.size(); ++i) in.real(f[i], message({item, ": field ", to_string(i + 1)}));
  }
  in.end(f, "triangles");
  return triangles;
}

std::vector<double> parseArea(const std::string& text, const std::string& name, std::size_t triangles) {
  Records in(text, name);
  std::vector<std::string_view> f;
  in.require(f, "the triangle count line");
  const std::size_t count = in.count(f[0], "triangle count");
  if (count != triangles)
    in.fail(message({"declares ", to_string(count), " triangles, but the .ele has ", to_string(triangles)}));
  std::vector<double> areas(count);
  for (std::size_t t = 0; t < count; ++t) {
    in.require(f, message({"the maximum area of triangle ", to_string(t + 1), " of ", to_string(count)}));
    if (f.size() != 2) in.fail(message({"expected <triangle #> <maximum area>, found ", to_string(f.size()), " fields"}));
    in.integer(f[0], "triangle number");
    areas[t] = in.real(f[1], "maximum area");
  }
  in.end(f, "areas");
  return areas;
}

}  // namespace

Plc parseMeshFiles(const MeshFiles& files) {
  Plc plc = parseNode(files.node, files.nodeName);
  if (files.hasPoly) {
    const std::size_t points = plc.points.size();
    Plc poly = parsePolyWithNode(files.poly, files.node, files.polyName, files.nodeName);
    if (poly.points.size() != points)
      throw Error(ErrorCode::ParseError, message({files.polyName, ": declares ", to_string(poly.points.size() / 2), " points, but ",
                                                  files.nodeName, " has ", to_string(points / 2),
                                                  " (the .ele numbers the .node's points; declare 0 points in the .poly)"}));
    poly.points = std::move(plc.points), poly.pointMarkers = std::move(plc.pointMarkers), poly.indexBase = plc.indexBase;
    plc = std::move(poly);
  }
  plc.triangles = parseEle(files.ele, files.eleName, plc.points.size() / 2, plc.indexBase);
  if (files.hasArea) plc.triangleMaxArea = parseArea(files.area, files.areaName, plc.triangles.size() / 3);
  return plc;
}

}  // namespace ruppert
RUPPERT_COLD_END
