// Readers for Triangle's .node and .poly formats (files by name: read_file.cpp).
//
// The formats, as documented with Triangle:
//   .node  first line:  <#points> [<dimension = 2> [<#attributes> [<#markers 0|1>]]]
//          then:        <index> <x> <y> [attributes...] [marker]
//   .poly  a .node section (or "0 ..." meaning "points are in the .node file of the same name"),
//          then:        <#segments> [<#markers 0|1>]
//                       <index> <a> <b> [marker]
//          then:        <#holes>, then <index> <x> <y>
//          optionally:  <#regions>, then <index> <x> <y> <attribute> [<max area>]
// '#' starts a comment anywhere on a line; blank lines are ignored; fields are whitespace-separated.
// The number written at the start of a record is ignored, except the first point's, which says
// whether the file counts from 0 or 1 (segment endpoints use that base).
//
// Robustness: every declared count is compared with the bytes left in the text before anything is
// allocated, so a header claiming 10^12 points fails fast with TooLarge instead of exhausting memory;
// memory is reserved only for as many records as the remaining text could hold.
// Numbers go through strtod on the exact token (streams reject forms like "-.000000E+00").
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <istream>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/read_poly.h"
#include "ruppert/ruppert.h"
#include "cold_code.h"
#include "mesh/huge_pages.h"

RUPPERT_COLD_BEGIN

namespace ruppert {
namespace {

// One non-blank line with its comment removed.
struct Record {
  std::size_t line = 0;  // 1-based line number in the text
  std::vector<std::string_view> fields;
};

// Smallest byte size of a record with `fields` fields: one character per field, one separator
// between fields, one newline. Used to bound declared counts by the text that could hold them.
constexpr std::uint64_t minRecordBytes(std::uint64_t fields) { return 2 * fields; }

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

class TriangleText {
 public:
  TriangleText(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  const std::string& name() const { return name_; }

  // The next record, or false at the end of the text.
  bool next(Record& record) {
    while (pos_ < text_.size()) {
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string::npos) end = text_.size();
      ++line_;
      std::string_view line(text_.data() + pos_, end - pos_);
      pos_ = end + 1;
      const std::size_t hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
      record.line = line_;
      record.fields.clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && isBlank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isBlank(line[i])) ++i;
        if (i > start) record.fields.push_back(line.substr(start, i - start));
      }
      if (!record.fields.empty()) return true;
    }
    return false;
  }

  std::uint64_t bytesLeft() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }

  // Line number used for "end of file" messages: the last line of the text.
  std::size_t lastLine() const { return line_; }

  [[noreturn]] void fail(ErrorCode code, std::size_t line, const std::string& message) const {
    throw Error(code, name_ + ":" + std::to_string(line) + ": " + message);
  }

  // The next record, failing with "expected <what>, found end of file" if there is none.
  void require(Record& record, const std::string& what) {
    if (!next(record)) fail(ErrorCode::ParseError, lastLine(), "expected " + what + ", found end of file");
  }

  // Fails with TooLarge when `count` exceeds the bytes left (each record takes several), and returns
  // how many records the rest could hold at most: callers reserve that, never the bare count.
  // A count between the two is a truncated file, reported as a ParseError when the records run out.
  std::uint64_t checkCount(std::uint64_t count, std::uint64_t fields, std::size_t line, const std::string& what) const {
    if (count > bytesLeft()) {
      fail(ErrorCode::TooLarge, line,
           what + " count " + std::to_string(count) + " is more than the rest of the file could hold (" +
               std::to_string(bytesLeft()) + " bytes left)");
    }
    const std::uint64_t room = (bytesLeft() + 1) / minRecordBytes(fields);
    return count < room ? count : room;
  }

 private:
  const std::string& text_;
  std::string name_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

std::string quoted(std::string_view field) { return "'" + std::string(field) + "'"; }

// A finite real number spelled by the whole field.
bool parseReal(std::string_view field, double& value) {
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  // from_chars rounds as strtod does, without a copy of the field (19 characters for a random
  // double: a heap allocation each) or a look at the locale. The forms it leaves to strtod: a
  // leading '+', hexadecimal, values beyond the range of a double.
  const char* last = field.data() + field.size();
  if (const auto [ptr, ec] = std::from_chars(field.data(), last, value); ec == std::errc() && ptr == last)
    return std::isfinite(value);
#endif
  const std::string text(field);  // strtod needs a terminator
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || text.empty()) return false;
  // ERANGE also reports underflow to a subnormal or zero, which is a fine value; overflow is not.
  return std::isfinite(value);
}

// A signed integer spelled by the whole field (digits with an optional sign).
bool parseInteger(std::string_view field, long long& value) {
  const std::string text(field);
  if (text.empty()) return false;
  const std::size_t digits = (text[0] == '+' || text[0] == '-') ? 1 : 0;
  if (digits == text.size()) return false;
  for (std::size_t i = digits; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(text.c_str(), &end, 10);
  return errno != ERANGE && end == text.c_str() + text.size();
}

class TriangleReader {
 public:
  explicit TriangleReader(TriangleText& text) : in_(text) {}

  double real(const Record& r, std::size_t i, const std::string& item, const char* field) {
    double v = 0;
    if (!parseReal(r.fields[i], v)) {
      in_.fail(ErrorCode::ParseError, r.line,
               item + ": " + field + " " + quoted(r.fields[i]) + " is not a finite number");
    }
    return v;
  }

  long long integer(const Record& r, std::size_t i, const std::string& item, const char* field) {
    long long v = 0;
    if (!parseInteger(r.fields[i], v)) {
      in_.fail(ErrorCode::ParseError, r.line, item + ": " + field + " " + quoted(r.fields[i]) + " is not an integer");
    }
    return v;
  }

  std::int32_t marker(const Record& r, std::size_t i, const std::string& item) {
    const long long v = integer(r, i, item, "boundary marker");
    if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max()) {
      in_.fail(ErrorCode::ParseError, r.line, item + ": boundary marker " + quoted(r.fields[i]) + " does not fit in 32 bits");
    }
    return static_cast<std::int32_t>(v);
  }

  // A non-negative count in header field i.
  std::uint64_t count(const Record& r, std::size_t i, const std::string& what) {
    const std::string_view f = r.fields[i];
    bool digits = !f.empty();
    for (char c : f) digits = digits && c >= '0' && c <= '9';
    if (!digits) {
      in_.fail(ErrorCode::ParseError, r.line, what + " " + quoted(f) + " is not a non-negative integer");
    }
    errno = 0;
    const std::string text(f);
    const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
    if (errno == ERANGE) in_.fail(ErrorCode::TooLarge, r.line, what + " " + quoted(f) + " is too large");
    return v;
  }

  // A 0/1 flag in optional header field i ("number of boundary markers").
  bool flag(const Record& r, std::size_t i, const std::string& what) {
    if (i >= r.fields.size()) return false;
    const std::uint64_t v = count(r, i, what);
    if (v > 1) in_.fail(ErrorCode::ParseError, r.line, what + " must be 0 or 1, found " + quoted(r.fields[i]));
    return v == 1;
  }

  // The points section (header already consumed): fills plc.points, pointMarkers and indexBase.
  void points(const Record& header, std::uint64_t n, Plc& plc) {
    std::uint64_t attributes = 0;
    if (header.fields.size() > 1) {
      const std::uint64_t dim = count(header, 1, "dimension");
      if (dim != 2) in_.fail(ErrorCode::ParseError, header.line, "dimension must be 2, found " + quoted(header.fields[1]));
    }
    if (header.fields.size() > 2) attributes = count(header, 2, "number of point attributes");
    const bool markers = flag(header, 3, "number of point boundary markers");
    if (n > std::numeric_limits<std::uint32_t>::max()) {
      in_.fail(ErrorCode::TooLarge, header.line, "point count " + std::to_string(n) + " exceeds 2^32 - 1");
    }
    const std::uint64_t room = in_.checkCount(n, 3, header.line, "point");
    detail::reserveHuge(plc.points, 2 * room);
    if (markers) plc.pointMarkers.reserve(room);
    // Attribute columns are kept (Plc::pointAttributes) up to kMaxAttributes per point and 2^27 values
    // in all (missing trailing fields read as 0, as Triangle reads them, so the count alone sets the
    // memory). A larger declared count is accepted only when no point gives an attribute.
    constexpr std::uint64_t kMaxAttributes = 65535, kMaxAttributeValues = std::uint64_t(1) << 27;
    const bool keep = attributes > 0 && attributes <= kMaxAttributes && n * attributes <= kMaxAttributeValues;
    if (keep) {
      plc.attributesPerPoint = static_cast<std::uint32_t>(attributes);
      plc.pointAttributes.reserve(static_cast<std::size_t>(room * attributes));
    }
    // A point's name ("point 12") is spelled only for a message, or where attributes or a marker
    // are read: once per point it costs more than parsing the coordinates.
    auto name = [&plc](std::uint64_t i) { return "point " + std::to_string(i + static_cast<std::uint64_t>(plc.indexBase)); };
    Record r;
    for (std::uint64_t i = 0; i < n; ++i) {
      if (!in_.next(r)) in_.fail(ErrorCode::ParseError, in_.lastLine(), "expected " + name(i) + ", found end of file");
      if (i == 0) {
        // The first point's number sets the index base of the whole file.
        const long long first = integer(r, 0, "first point", "index");
        if (first != 0 && first != 1) {
          in_.fail(ErrorCode::ParseError, r.line,
                   "first point: index " + quoted(r.fields[0]) + " must be 0 or 1 (it sets the index base)");
        }
        plc.indexBase = static_cast<int>(first);
      }
      if (r.fields.size() < 3) {
        in_.fail(ErrorCode::ParseError, r.line,
                 name(i) + ": expected an index, x and y, found " + std::to_string(r.fields.size()) + " field" +
                     (r.fields.size() == 1 ? "" : "s"));
      }
      double x = 0, y = 0;
      if (!parseReal(r.fields[1], x)) real(r, 1, name(i), "x");  // (fails, naming the point)
      if (!parseReal(r.fields[2], y)) real(r, 2, name(i), "y");
      plc.points.push_back(x);
      plc.points.push_back(y);
      const std::size_t given = r.fields.size() - 3;  // attributes, then the marker
      const std::string named = keep || markers || given > 0 ? name(i) : std::string();
      if (keep) {
        for (std::size_t j = 0; j < attributes; ++j)
          plc.pointAttributes.push_back(j < given ? real(r, 3 + j, named, "attribute") : 0.0);
      } else if (attributes > 0 && given > 0) {
        in_.fail(ErrorCode::TooLarge, r.line,
                 named + ": " + std::to_string(attributes) + " attributes per point for " + std::to_string(n) +
                     " points are more than ruppert keeps (at most 65535 per point and 2^27 in all)");
      }
      // Triangle treats missing trailing fields as zero, and so do we.
      if (markers) {
        // (Compared without adding, so an absurd attribute count cannot wrap around.)
        const bool present = attributes < r.fields.size() && r.fields.size() - attributes > 3;
        plc.pointMarkers.push_back(present ? marker(r, static_cast<std::size_t>(3 + attributes), named) : 0);
      }
    }
  }

  void segments(std::uint64_t pointCount, Plc& plc) {
    Record header;
    in_.require(header, "the segment count line");
    const std::uint64_t n = count(header, 0, "segment count");
    const bool markers = flag(header, 1, "number of segment boundary markers");
    const std::uint64_t room = in_.checkCount(n, 3, header.line, "segment");
    plc.segments.reserve(2 * room);
    if (markers) plc.segmentMarkers.reserve(room);
    const long long base = plc.indexBase;
    Record r;
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string item = "segment " + std::to_string(i + static_cast<std::uint64_t>(base));
      in_.require(r, item);
      if (r.fields.size() < 3) {
        const std::size_t found = r.fields.size() - 1;
        in_.fail(ErrorCode::ParseError, r.line,
                 item + ": expected 2 endpoint indices, found " + std::to_string(found));
      }
      for (std::size_t k = 1; k <= 2; ++k) {
        const long long v = integer(r, k, item, "endpoint");
        if (v < base || static_cast<unsigned long long>(v - base) >= pointCount) {
          in_.fail(ErrorCode::IndexOutOfRange, r.line,
                   item + " refers to point " + std::string(r.fields[k]) + " but there are " +
                       std::to_string(pointCount) + " points (numbered from " + std::to_string(base) + ")");
        }
        plc.segments.push_back(static_cast<std::uint32_t>(v - base));
      }
      if (markers) plc.segmentMarkers.push_back(r.fields.size() > 3 ? marker(r, 3, item) : 0);
    }
  }

  // Holes are optional at the very end of the file (Triangle requires the line; we accept its absence).
  void holes(Plc& plc) {
    Record header;
    if (!in_.next(header)) return;
    const std::uint64_t n = count(header, 0, "hole count");
    plc.holes.reserve(2 * in_.checkCount(n, 3, header.line, "hole"));
    Record r;
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string item = "hole " + std::to_string(i + static_cast<std::uint64_t>(plc.indexBase));
      in_.require(r, item);
      if (r.fields.size() < 3) {
        in_.fail(ErrorCode::ParseError, r.line,
                 item + ": expected an index, x and y, found " + std::to_string(r.fields.size()) + " fields");
      }
      plc.holes.push_back(real(r, 1, item, "x"));
      plc.holes.push_back(real(r, 2, item, "y"));
    }
  }

  void regions(Plc& plc) {
    Record header;
    if (!in_.next(header)) return;
    const std::uint64_t n = count(header, 0, "region count");
    plc.regions.reserve(in_.checkCount(n, 4, header.line, "region"));
    Record r;
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string item = "region " + std::to_string(i + static_cast<std::uint64_t>(plc.indexBase));
      in_.require(r, item);
      if (r.fields.size() < 4) {
        in_.fail(ErrorCode::ParseError, r.line,
                 item + ": expected an index, x, y and attribute, found " + std::to_string(r.fields.size()) + " fields");
      }
      Region region;
      region.x = real(r, 1, item, "x");
      region.y = real(r, 2, item, "y");
      region.attribute = real(r, 3, item, "attribute");
      // Triangle: a missing or negative maximum area means "no bound", which Plc spells 0.
      if (r.fields.size() > 4) region.maxArea = real(r, 4, item, "maximum area");
      if (region.maxArea < 0) region.maxArea = 0;
      plc.regions.push_back(region);
    }
  }

  void end(const char* after) {
    Record r;
    if (in_.next(r)) {
      in_.fail(ErrorCode::ParseError, r.line,
               std::string("unexpected ") + quoted(r.fields[0]) + " after the " + after + " section");
    }
  }

  TriangleText& text() { return in_; }

 private:
  TriangleText& in_;
};

Plc nodeFromText(const std::string& text, const std::string& name) {
  TriangleText in(text, name);
  TriangleReader reader(in);
  Record header;
  in.require(header, "the point count line");
  Plc plc;
  reader.points(header, reader.count(header, 0, "point count"), plc);
  reader.end("points");
  return plc;
}

// `loadNode` supplies the points when the .poly declares none (Triangle's "see the .node file").
Plc polyFromText(const std::string& text, const std::string& name, const std::function<Plc()>& loadNode) {
  TriangleText in(text, name);
  TriangleReader reader(in);
  Record header;
  in.require(header, "the point count line");
  const std::uint64_t n = reader.count(header, 0, "point count");
  Plc plc;
  if (n == 0) {
    plc = loadNode();
    plc.segments.clear();
    plc.segmentMarkers.clear();
    plc.holes.clear();
    plc.regions.clear();
  } else {
    reader.points(header, n, plc);
  }
  reader.segments(plc.points.size() / 2, plc);
  reader.holes(plc);
  reader.regions(plc);
  reader.end("regions");
  return plc;
}

}  // namespace

Plc parseNode(const std::string& text, const std::string& name) { return nodeFromText(text, name); }

Plc parsePoly(const std::string& text, const std::string& name) {
  return polyFromText(text, name, [&name]() -> Plc {
    throw Error(ErrorCode::ParseError,
                name + ":1: the .poly declares 0 points, so its points are in a .node file of the same name; "
                       "pass that file's text too (JavaScript: parsePoly(polyText, { node: nodeText }); "
                       "C++: parsePolyWithNode, or readFile, which reads both files)");
  });
}

Plc parsePolyWithNode(const std::string& polyText, const std::string& nodeText, const std::string& polyName,
                      const std::string& nodeName) {
  return polyFromText(polyText, polyName, [&]() { return nodeFromText(nodeText, nodeName); });
}

namespace detail {

std::string readStream(std::istream& in, const std::string& name) {
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(ErrorCode::IoError, name + ": read failed");
  return text;
}

Plc parsePolyLoadingNode(const std::string& text, const std::string& name, const std::function<Plc()>& loadNode) {
  return polyFromText(text, name, loadNode);
}

}  // namespace detail

Plc readNode(std::istream& in, const std::string& name) { return parseNode(detail::readStream(in, name), name); }

Plc readPoly(std::istream& in, const std::string& name) { return parsePoly(detail::readStream(in, name), name); }

}  // namespace ruppert
RUPPERT_COLD_END
