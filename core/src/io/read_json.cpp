// JSON reader for the PLC shape documented in ruppert.h:
//   { "points": [x0,y0,...], "segments": [a0,b0,...], "holes": [x,y,...],
//     "regions": [{"x":..,"y":..,"attribute":..,"maxArea":..}] }
// "points" is required; the rest are optional, "pointMarkers" and "segmentMarkers" (one integer per
// point / segment), "pointAttributes" (attributesPerPoint numbers per point) and "attributesPerPoint"
// among them, and "curves" (see curves() below). Unknown keys (and "triangles", which our own writer emits) are parsed for syntax and
// ignored, so a written mesh reads back as its PLC.
//
// The parser is a small recursive-descent reader of RFC 8259 JSON that fills the Plc directly instead
// of building a document tree: a million points cost 16 MB, not a tree of tagged values. Nesting is
// limited (kMaxDepth) so input like [[[[... cannot exhaust the stack. Errors name the path of the
// offending value ("points[7] is not a number") and its line and column. Text that is not JSON is a
// ParseError; JSON of the wrong shape (odd-length arrays, non-integer indices, wrong types, missing
// keys) is MalformedInput, as ruppert.h defines it; a segment naming a missing point is IndexOutOfRange.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <istream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "ruppert/ruppert.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert {
namespace {

constexpr int kMaxDepth = 256;
// What JsonReader::integers says of a value it refuses.
constexpr const char* kNotIndex = "is not an integer index (non-negative)";
constexpr const char* kTooLargeIndex = "is larger than any point index (2^32 - 1)";
constexpr const char* kNotMarker = "is not a 32-bit integer marker";

class JsonReader {
 public:
  JsonReader(const std::string& text, const std::string& name)
      : begin_(text.data()), p_(text.data()), end_(text.data() + text.size()), name_(name) {}

  Plc document() {
    // A UTF-8 byte order mark is not JSON, but editors add it; skipping it harms nothing.
    if (end_ - p_ >= 3 && static_cast<unsigned char>(p_[0]) == 0xEF && static_cast<unsigned char>(p_[1]) == 0xBB &&
        static_cast<unsigned char>(p_[2]) == 0xBF) {
      p_ += 3;
    }
    skipSpace();
    if (p_ == end_) fail(ErrorCode::ParseError, "the input is empty; expected a JSON object");
    if (*p_ != '{') fail(ErrorCode::MalformedInput, "the top level must be an object ({ \"points\": [...] })");
    Plc plc;
    constexpr int kKeys = 9;
    bool seen[kKeys] = {};
    static const char* const kKnown[kKeys] = {"points", "segments", "holes", "regions", "pointMarkers",
                                              "segmentMarkers", "pointAttributes", "attributesPerPoint", "curves"};
    double attributesPerPoint = -1;  // -1: not given
    members(1, [&](const std::string& key, int depth) {
      for (int k = 0; k < kKeys; ++k) {
        if (key != kKnown[k]) continue;
        if (seen[k]) fail(ErrorCode::MalformedInput, "duplicate key \"" + key + "\"");
        seen[k] = true;
        switch (k) {
          case 0: numbers(key, depth, plc.points); return;
          case 1: integers(key, depth, plc.segments, kNotIndex, kTooLargeIndex); return;
          case 2: numbers(key, depth, plc.holes); return;
          case 3: regions(key, depth, plc.regions); return;
          case 4: integers(key, depth, plc.pointMarkers, kNotMarker); return;
          case 5: integers(key, depth, plc.segmentMarkers, kNotMarker); return;
          case 6: numbers(key, depth, plc.pointAttributes); return;
          case 8: curves(key, depth, plc.curves); return;
          default: attributesPerPoint = count(key); return;
        }
      }
      skipValue(depth);
    });
    skipSpace();
    if (p_ != end_) fail(ErrorCode::ParseError, "unexpected text after the top-level object");

    if (!seen[0]) failAt(begin_, ErrorCode::MalformedInput, "missing \"points\"");
    checkPairs("points", plc.points.size(), "numbers (x, y pairs)");
    checkPairs("segments", plc.segments.size(), "indices (a, b pairs)");
    checkPairs("holes", plc.holes.size(), "numbers (x, y pairs)");
    const std::uint64_t pointCount = plc.points.size() / 2;
    for (std::size_t i = 0; i < plc.segments.size(); ++i) {
      if (plc.segments[i] >= pointCount) {
        failAt(begin_, ErrorCode::IndexOutOfRange,
               "segment " + std::to_string(i / 2) + " (segments[" + std::to_string(i) + "]) refers to point " +
                   std::to_string(plc.segments[i]) + " but there are " + std::to_string(pointCount) + " points");
      }
    }
    checkPerItem(plc, attributesPerPoint);
    plc.indexBase = 0;
    return plc;
  }

 private:
  [[noreturn]] void failAt(const char* at, ErrorCode code, const std::string& message) const {
    std::size_t line = 1, column = 1;
    for (const char* q = begin_; q < at; ++q) {
      if (*q == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw Error(code, name_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message);
  }
  [[noreturn]] void fail(ErrorCode code, const std::string& message) const { failAt(p_, code, message); }

  void checkPairs(const char* key, std::size_t n, const char* what) const {
    if (n % 2 != 0) {
      failAt(begin_, ErrorCode::MalformedInput,
             std::string(key) + " has " + std::to_string(n) + " " + what + "; expected an even count");
    }
  }

  void skipSpace() {
    while (p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\n' || *p_ == '\r')) ++p_;
  }

  void enter(int depth) const {
    if (depth > kMaxDepth) fail(ErrorCode::ParseError, "nesting deeper than " + std::to_string(kMaxDepth) + " levels");
  }

  std::string describeHere() const {
    if (p_ == end_) return "end of input";
    const char c = *p_;
    if (c >= 0x20 && c < 0x7f) return std::string("'") + c + "'";
    return "byte " + std::to_string(static_cast<unsigned char>(c));
  }

  void expect(char c, const char* context) {
    skipSpace();
    if (p_ == end_ || *p_ != c) {
      fail(ErrorCode::ParseError, std::string("expected '") + c + "' " + context + ", found " + describeHere());
    }
    ++p_;
  }

  bool startsNumber() const { return p_ != end_ && (*p_ == '-' || (*p_ >= '0' && *p_ <= '9')); }

  // Parses a JSON number at p_ (startsNumber() holds); `text` receives its spelling for messages.
  double number(const std::string& path, std::string& text) {
    const char* start = p_;
    auto digits = [this]() {
      const char* s = p_;
      while (p_ != end_ && *p_ >= '0' && *p_ <= '9') ++p_;
      return p_ - s;
    };
    if (*p_ == '-') ++p_;
    if (p_ != end_ && *p_ == '0') {
      ++p_;
    } else if (digits() == 0) {
      fail(ErrorCode::ParseError, path + ": '-' must be followed by digits");
    }
    if (p_ != end_ && *p_ == '.') {
      ++p_;
      if (digits() == 0) fail(ErrorCode::ParseError, path + ": expected digits after the decimal point");
    }
    if (p_ != end_ && (*p_ == 'e' || *p_ == 'E')) {
      ++p_;
      if (p_ != end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (digits() == 0) fail(ErrorCode::ParseError, path + ": expected digits in the exponent");
    }
    text.assign(start, p_);
    // The grammar above is a subset of what strtod accepts, so strtod consumes exactly `text`.
    const double v = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(v)) failAt(start, ErrorCode::ParseError, path + " = " + text + " is outside the range of doubles");
    return v;
  }

  // Reads a string at p_ (which is '"'), decoding escapes to UTF-8.
  std::string string() {
    const char* start = p_;
    ++p_;
    std::string out;
    while (true) {
      if (p_ == end_) failAt(start, ErrorCode::ParseError, "unterminated string");
      const unsigned char c = static_cast<unsigned char>(*p_++);
      if (c == '"') return out;
      if (c < 0x20) failAt(p_ - 1, ErrorCode::ParseError, "control character in a string (escape it)");
      if (c != '\\') {
        out.push_back(static_cast<char>(c));
        continue;
      }
      if (p_ == end_) failAt(start, ErrorCode::ParseError, "unterminated string");
      const char e = *p_++;
      switch (e) {
        case '"': out.push_back('"'); break;
        case '\\': out.push_back('\\'); break;
        case '/': out.push_back('/'); break;
        case 'b': out.push_back('\b'); break;
        case 'f': out.push_back('\f'); break;
        case 'n': out.push_back('\n'); break;
        case 'r': out.push_back('\r'); break;
        case 't': out.push_back('\t'); break;
        case 'u': appendUtf8(out, codePoint()); break;
        default: failAt(p_ - 1, ErrorCode::ParseError, std::string("invalid escape '\\") + e + "' in a string");
      }
    }
  }

  unsigned hex4() {
    if (end_ - p_ < 4) fail(ErrorCode::ParseError, "expected 4 hex digits after \\u");
    unsigned v = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = *p_;
      unsigned d;
      if (c >= '0' && c <= '9') d = static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') d = static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') d = static_cast<unsigned>(c - 'A' + 10);
      else fail(ErrorCode::ParseError, "expected 4 hex digits after \\u");
      v = v * 16 + d;
      ++p_;
    }
    return v;
  }

  // After "\u": one code point, combining a UTF-16 surrogate pair when present.
  unsigned codePoint() {
    const unsigned hi = hex4();
    if (hi >= 0xDC00 && hi <= 0xDFFF) fail(ErrorCode::ParseError, "unpaired low surrogate in \\u escape");
    if (hi < 0xD800 || hi > 0xDBFF) return hi;
    if (end_ - p_ < 2 || p_[0] != '\\' || p_[1] != 'u') fail(ErrorCode::ParseError, "unpaired high surrogate in \\u escape");
    p_ += 2;
    const unsigned lo = hex4();
    if (lo < 0xDC00 || lo > 0xDFFF) fail(ErrorCode::ParseError, "unpaired high surrogate in \\u escape");
    return 0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00);
  }

  static void appendUtf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out.push_back(static_cast<char>(cp));
    } else if (cp < 0x800) {
      out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
      out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else if (cp < 0x10000) {
      out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
      out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else {
      out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
      out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    }
  }

  bool literal(const char* word) {
    const char* q = p_;
    for (const char* w = word; *w; ++w, ++q) {
      if (q == end_ || *q != *w) return false;
    }
    p_ = q;
    return true;
  }

  // Parses any value for syntax only.
  void skipValue(int depth) {
    enter(depth);
    skipSpace();
    if (p_ == end_) fail(ErrorCode::ParseError, "expected a value, found end of input");
    const char c = *p_;
    if (c == '{') {
      members(depth, [this](const std::string&, int inner) { skipValue(inner); });
    } else if (c == '[') {
      elements(depth, "", [this](const std::string&, int inner) { skipValue(inner); });
    } else if (c == '"') {
      string();
    } else if (startsNumber()) {
      std::string text;
      number("number", text);
    } else if (!literal("true") && !literal("false") && !literal("null")) {
      fail(ErrorCode::ParseError, "expected a value, found " + describeHere());
    }
  }

  // An object at p_: calls onMember(key, depth + 1) with p_ at each member's value.
  template <typename OnMember>
  void members(int depth, OnMember onMember) {
    enter(depth);
    expect('{', "to open an object");
    skipSpace();
    if (p_ != end_ && *p_ == '}') {
      ++p_;
      return;
    }
    while (true) {
      skipSpace();
      if (p_ == end_ || *p_ != '"') fail(ErrorCode::ParseError, "expected a quoted key, found " + describeHere());
      const std::string key = string();
      expect(':', "after a key");
      skipSpace();
      onMember(key, depth + 1);
      skipSpace();
      if (p_ != end_ && *p_ == ',') {
        ++p_;
        continue;
      }
      expect('}', "or ',' in an object");
      return;
    }
  }

  // An array at p_: calls onElement("path[i]", depth + 1) with p_ at each element.
  template <typename OnElement>
  void elements(int depth, const std::string& path, OnElement onElement) {
    enter(depth);
    expect('[', path.empty() ? "to open an array" : ("to open the array " + path).c_str());
    skipSpace();
    if (p_ != end_ && *p_ == ']') {
      ++p_;
      return;
    }
    for (std::size_t i = 0;; ++i) {
      skipSpace();
      onElement(path + "[" + std::to_string(i) + "]", depth + 1);
      skipSpace();
      if (p_ != end_ && *p_ == ',') {
        ++p_;
        continue;
      }
      expect(']', "or ',' in an array");
      return;
    }
  }

  void requireArray(const std::string& key) {
    skipSpace();
    if (p_ == end_ || *p_ != '[') fail(ErrorCode::MalformedInput, key + " must be an array");
  }

  double requireNumber(const std::string& path) {
    if (!startsNumber()) fail(ErrorCode::MalformedInput, path + " is not a number");
    std::string text;
    return number(path, text);
  }

  void numbers(const std::string& key, int depth, std::vector<double>& out) {
    requireArray(key);
    elements(depth, key, [&](const std::string& path, int) { out.push_back(requireNumber(path)); });
  }

  // An array of whole numbers that Int holds: point indices (uint32) and boundary markers (int32,
  // negative ones too). A fraction or a value below Int's range is "`notInteger`"; one above it is
  // "`tooLarge`" (IndexOutOfRange), or without that "`notInteger`" too.
  template <class Int>
  void integers(const std::string& key, int depth, std::vector<Int>& out, const char* notInteger,
                const char* tooLarge = nullptr) {
    requireArray(key);
    elements(depth, key, [&](const std::string& path, int) {
      if (!startsNumber()) fail(ErrorCode::MalformedInput, path + " is not a number");
      const char* start = p_;
      std::string text;
      const double v = number(path, text);
      if (v != std::floor(v) || v < static_cast<double>(std::numeric_limits<Int>::min()))
        failAt(start, ErrorCode::MalformedInput, path + " = " + text + " " + notInteger);
      if (v > static_cast<double>(std::numeric_limits<Int>::max())) {
        if (tooLarge) failAt(start, ErrorCode::IndexOutOfRange, path + " = " + text + " " + tooLarge);
        failAt(start, ErrorCode::MalformedInput, path + " = " + text + " " + notInteger);
      }
      out.push_back(static_cast<Int>(v));
    });
  }

  // "attributesPerPoint": a whole number of values per point.
  double count(const std::string& key) {
    const char* start = p_;
    const double v = requireNumber(key);
    if (v != std::floor(v) || v < 0 || v > 65535)
      failAt(start, ErrorCode::MalformedInput, key + " must be an integer in [0, 65535]");
    return v;
  }

  // Markers one per point / segment (or none); attributes attributesPerPoint per point (or, without
  // it, the length over the number of points, which must divide it).
  void checkPerItem(Plc& plc, double attributesPerPoint) const {
    const std::size_t n = plc.points.size() / 2, segments = plc.segments.size() / 2;
    if (!plc.pointMarkers.empty() && plc.pointMarkers.size() != n)
      failAt(begin_, ErrorCode::MalformedInput, "pointMarkers has " + std::to_string(plc.pointMarkers.size()) +
                                                    " entries for " + std::to_string(n) + " points");
    if (!plc.segmentMarkers.empty() && plc.segmentMarkers.size() != segments)
      failAt(begin_, ErrorCode::MalformedInput, "segmentMarkers has " + std::to_string(plc.segmentMarkers.size()) +
                                                    " entries for " + std::to_string(segments) + " segments");
    const std::size_t values = plc.pointAttributes.size();
    if (values == 0) return;
    const std::size_t k = attributesPerPoint >= 0 ? static_cast<std::size_t>(attributesPerPoint) : n > 0 ? values / n : 0;
    if (k == 0 || values != k * n)
      failAt(begin_, ErrorCode::MalformedInput, "pointAttributes has " + std::to_string(values) + " values for " +
                                                    std::to_string(n) + " points" +
                                                    (attributesPerPoint >= 0 ? " with attributesPerPoint = " + std::to_string(k) : ""));
    plc.attributesPerPoint = static_cast<std::uint32_t>(k);
  }

  // One whole number in [lo, hi]: a curve's point index or marker.
  double wholeNumber(const std::string& path, double lo, double hi) {
    const char* start = p_;
    const double v = requireNumber(path);
    if (v != std::floor(v) || v < lo || v > hi)
      failAt(start, v > hi && lo == 0 ? ErrorCode::IndexOutOfRange : ErrorCode::MalformedInput,
             path + " is not " + (lo == 0 ? "a point index" : "a 32-bit integer marker"));
    return v;
  }

  // "curves": [{"type": "arc", "from": i, "to": j, "center": [x, y], "marker": m},
  //            {"type": "bezier", "from": i, "to": j, "controls": [x1, y1, x2, y2]}]
  // (ruppert.h's Curve; the points a curve names are checked with the rest of the input).
  void curves(const std::string& key, int depth, std::vector<Curve>& out) {
    requireArray(key);
    elements(depth, key, [&](const std::string& path, int inner) {
      if (p_ == end_ || *p_ != '{') fail(ErrorCode::MalformedInput, path + " is not an object ({\"type\": \"arc\", ...})");
      const char* start = p_;
      Curve curve;
      std::string type;
      bool from = false, to = false;
      std::vector<double> center, controls;
      members(inner, [&](const std::string& field, int valueDepth) {
        const std::string fieldPath = path + "." + field;
        if (field == "type") {
          if (p_ == end_ || *p_ != '"') fail(ErrorCode::MalformedInput, fieldPath + " is not a string");
          type = string();
        } else if (field == "from" || field == "to") {
          (field == "from" ? from : to) = true;
          (field == "from" ? curve.from : curve.to) = static_cast<std::uint32_t>(wholeNumber(fieldPath, 0, 4294967295.0));
        } else if (field == "center" || field == "controls") {
          numbers(fieldPath, valueDepth, field == "center" ? center : controls);
        } else if (field == "marker") {
          curve.marker = static_cast<std::int32_t>(wholeNumber(fieldPath, -2147483648.0, 2147483647.0));
        } else {
          skipValue(valueDepth);
        }
      });
      const bool arc = type == "arc";
      if (!arc && type != "bezier") failAt(start, ErrorCode::MalformedInput, path + ".type must be \"arc\" or \"bezier\", not \"" + type + "\"");
      curve.type = arc ? CurveType::Arc : CurveType::Bezier;
      if (!from || !to) failAt(start, ErrorCode::MalformedInput, path + " has no \"" + (from ? "to" : "from") + "\"");
      std::vector<double>& values = arc ? center : controls;
      if (values.size() != (arc ? 2u : 4u))
        failAt(start, ErrorCode::MalformedInput, path + (arc ? " needs \"center\": [x, y]" : " needs \"controls\": [x1, y1, x2, y2]"));
      std::copy(values.begin(), values.end(), arc ? curve.center : curve.controls);
      out.push_back(curve);
    });
  }

  void regions(const std::string& key, int depth, std::vector<Region>& out) {
    requireArray(key);
    elements(depth, key, [&](const std::string& path, int inner) {
      if (p_ == end_ || *p_ != '{') fail(ErrorCode::MalformedInput, path + " is not an object ({\"x\":..,\"y\":..})");
      const char* start = p_;
      Region region;
      bool hasX = false, hasY = false;
      members(inner, [&](const std::string& field, int valueDepth) {
        const std::string fieldPath = path + "." + field;
        if (field == "x") {
          region.x = requireNumber(fieldPath);
          hasX = true;
        } else if (field == "y") {
          region.y = requireNumber(fieldPath);
          hasY = true;
        } else if (field == "attribute" || field == "maxArea") {
          // null means "not given" (our writer never emits it, but other tools print absent values so).
          if (literal("null")) return;
          (field == "attribute" ? region.attribute : region.maxArea) = requireNumber(fieldPath);
        } else {
          skipValue(valueDepth);
        }
      });
      if (!hasX) failAt(start, ErrorCode::MalformedInput, path + " has no \"x\"");
      if (!hasY) failAt(start, ErrorCode::MalformedInput, path + " has no \"y\"");
      out.push_back(region);
    });
  }

  const char* begin_;
  const char* p_;
  const char* end_;
  std::string name_;
};

}  // namespace

Plc parseJson(const std::string& text, const std::string& name) { return JsonReader(text, name).document(); }

Plc readJson(std::istream& in, const std::string& name) {
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(ErrorCode::IoError, name + ": read failed");
  return parseJson(text, name);
}

}  // namespace ruppert
RUPPERT_COLD_END
