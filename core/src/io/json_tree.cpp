// Recursive-descent JSON parser building a JsonValue tree (see json_tree.h).
#include "io/json_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "ruppert/ruppert.h"

#include "cold_code.h"
#include "decimal_text.h"

RUPPERT_COLD_BEGIN
namespace ruppert::detail {
namespace {

class TreeParser {
 public:
  TreeParser(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  JsonValue document() {
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) p_ = 3;
    skipSpace();
    if (p_ == text_.size()) fail("the input is empty; expected JSON");
    JsonValue root = value(1);
    skipSpace();
    if (p_ != text_.size()) fail("unexpected text after the top-level value");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(ErrorCode::ParseError, name_ + ":" + jsonPosition(text_, p_) + ": " + message);
  }

  std::string here() const {
    if (p_ >= text_.size()) return "end of input";
    const char c = text_[p_];
    if (c >= 0x20 && c < 0x7f) return std::string("'") + c + "'";
    return "byte " + std::to_string(static_cast<unsigned char>(c));
  }

  void skipSpace() {
    while (p_ < text_.size() && (text_[p_] == ' ' || text_[p_] == '\t' || text_[p_] == '\n' || text_[p_] == '\r')) ++p_;
  }

  bool literal(const char* word) {
    const std::string w(word);
    if (text_.compare(p_, w.size(), w) != 0) return false;
    p_ += w.size();
    return true;
  }

  JsonValue value(int depth) {
    if (depth > kMaxJsonDepth) fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    skipSpace();
    JsonValue v;
    v.offset = p_;
    if (p_ >= text_.size()) fail("expected a value, found end of input");
    const char c = text_[p_];
    if (c == '{') {
      object(v, depth);
    } else if (c == '[') {
      array(v, depth);
    } else if (c == '"') {
      v.kind = JsonValue::Kind::String;
      v.text = string();
    } else if (literal("true") || literal("false")) {
      v.kind = JsonValue::Kind::Boolean;
      v.boolean = c == 't';
    } else if (literal("null")) {
      v.kind = JsonValue::Kind::Null;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      v.kind = JsonValue::Kind::Number;
      v.number = number();
    } else {
      fail("expected a value, found " + here());
    }
    return v;
  }

  void object(JsonValue& v, int depth) {
    v.kind = JsonValue::Kind::Object;
    ++p_;
    skipSpace();
    if (p_ < text_.size() && text_[p_] == '}') {
      ++p_;
      return;
    }
    for (;;) {
      skipSpace();
      if (p_ >= text_.size() || text_[p_] != '"') fail("expected a key string, found " + here());
      std::string key = string();
      skipSpace();
      if (p_ >= text_.size() || text_[p_] != ':') fail("expected ':' after key \"" + key + "\", found " + here());
      ++p_;
      v.members.emplace_back(std::move(key), value(depth + 1));
      skipSpace();
      if (p_ < text_.size() && text_[p_] == ',') {
        ++p_;
      } else if (p_ < text_.size() && text_[p_] == '}') {
        ++p_;
        requireUniqueKeys(v);
        return;
      } else {
        fail("expected ',' or '}' in an object, found " + here());
      }
    }
  }

  void array(JsonValue& v, int depth) {
    v.kind = JsonValue::Kind::Array;
    v.numeric = true;
    ++p_;
    skipSpace();
    if (p_ < text_.size() && text_[p_] == ']') {
      ++p_;
      return;
    }
    for (;;) {
      JsonValue item = value(depth + 1);
      if (v.numeric && item.kind == JsonValue::Kind::Number) {
        v.numbers.push_back(item.number);
      } else {
        if (v.numeric) unpack(v);
        v.items.push_back(std::move(item));
      }
      skipSpace();
      if (p_ < text_.size() && text_[p_] == ',') {
        ++p_;
      } else if (p_ < text_.size() && text_[p_] == ']') {
        ++p_;
        return;
      } else {
        fail("expected ',' or ']' in an array, found " + here());
      }
    }
  }

  // RFC 8259 leaves duplicate names to the reader; two "type"s or "coordinates" are refused, as the
  // .json reader refuses them, instead of silently taking one.
  void requireUniqueKeys(const JsonValue& v) const {
    // Keys sorted by a hash (FNV-1a), then compared within runs of equal hashes: the sort is one
    // the core instantiates anyway, where one ordering strings would be a copy of its own.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
    for (std::size_t k = 0; k < v.members.size(); ++k) {
      std::uint64_t hash = 14695981039346656037ull;
      for (unsigned char c : v.members[k].first) hash = (hash ^ c) * 1099511628211ull;
      keys.emplace_back(hash, static_cast<std::uint32_t>(k));
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size(); ++i)
      for (std::size_t j = i + 1; j < keys.size() && keys[j].first == keys[i].first; ++j) {
        const std::string& key = v.members[keys[j].second].first;
        if (key == v.members[keys[i].second].first)
          throw Error(ErrorCode::MalformedInput,
                      name_ + ":" + jsonPosition(text_, v.offset) + ": duplicate key \"" + key + "\" in an object");
      }
  }

  // A numeric array that met a non-number: its numbers become values (their offsets are lost; the
  // array's own offset stands for them in messages).
  static void unpack(JsonValue& v) {
    v.numeric = false;
    for (double d : v.numbers) {
      JsonValue n;
      n.kind = JsonValue::Kind::Number;
      n.number = d;
      n.offset = v.offset;
      v.items.push_back(std::move(n));
    }
    v.numbers.clear();
  }

  double number() {
    const std::size_t start = p_;
    if (text_[p_] == '-') ++p_;
    auto digits = [&] {
      const std::size_t from = p_;
      while (p_ < text_.size() && text_[p_] >= '0' && text_[p_] <= '9') ++p_;
      return p_ > from;
    };
    if (!digits()) fail("a number needs digits");
    if (p_ < text_.size() && text_[p_] == '.') {
      ++p_;
      if (!digits()) fail("a number needs digits after '.'");
    }
    if (p_ < text_.size() && (text_[p_] == 'e' || text_[p_] == 'E')) {
      ++p_;
      if (p_ < text_.size() && (text_[p_] == '+' || text_[p_] == '-')) ++p_;
      if (!digits()) fail("a number needs digits in its exponent");
    }
    const std::string_view token(text_.data() + start, p_ - start);
    const double d = parseDecimal(token);
    if (!std::isfinite(d)) {
      p_ = start;
      fail("the number " + std::string(token) + " is too large for a double");
    }
    return d;
  }

  std::string string() {
    ++p_;  // the opening quote
    std::string out;
    while (p_ < text_.size() && text_[p_] != '"') {
      const char c = text_[p_++];
      if (static_cast<unsigned char>(c) < 0x20) fail("a control character inside a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (p_ >= text_.size()) break;
      const char e = text_[p_++];
      switch (e) {
        case '"': case '\\': case '/': out += e; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': out += unicodeEscape(); break;
        default: --p_; fail(std::string("unknown escape '\\") + e + "' in a string");
      }
    }
    if (p_ >= text_.size()) fail("a string is not closed");
    ++p_;
    return out;
  }

  // \uXXXX as UTF-8 (a lone surrogate becomes U+FFFD: names only appear in messages).
  std::string unicodeEscape() {
    if (p_ + 4 > text_.size()) fail("\\u needs four hex digits");
    unsigned code = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = text_[p_++];
      code <<= 4;
      if (h >= '0' && h <= '9') code |= static_cast<unsigned>(h - '0');
      else if (h >= 'a' && h <= 'f') code |= static_cast<unsigned>(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F') code |= static_cast<unsigned>(h - 'A' + 10);
      else fail("\\u needs four hex digits");
    }
    if (code >= 0xD800 && code <= 0xDFFF) code = 0xFFFD;
    std::string out;
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
    return out;
  }

  const std::string& text_;
  const std::string& name_;
  std::size_t p_ = 0;
};

}  // namespace

const JsonValue* JsonValue::find(const std::string& key) const {
  for (const auto& [k, v] : members) {
    if (k == key) return &v;
  }
  return nullptr;
}

const char* jsonKindName(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::Null: return "null";
    case JsonValue::Kind::Boolean: return "a boolean";
    case JsonValue::Kind::Number: return "a number";
    case JsonValue::Kind::String: return "a string";
    case JsonValue::Kind::Array: return "an array";
    case JsonValue::Kind::Object: return "an object";
  }
  return "a value";
}

std::string jsonPosition(const std::string& text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

JsonValue parseJsonTree(const std::string& text, const std::string& name) { return TreeParser(text, name).document(); }

}  // namespace ruppert::detail
RUPPERT_COLD_END
