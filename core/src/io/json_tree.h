// A JSON document as a tree (RFC 8259), for readers of nested formats (GeoJSON) where filling a Plc
// while parsing, as read_json.cpp does, would tangle the format's rules with the syntax.
//
// An array whose items are all numbers keeps them as plain doubles (`numbers`): a GeoJSON position
// [x, y] costs one value and two doubles, not three values. Nesting is limited to kMaxJsonDepth so
// input like [[[[... cannot exhaust the stack. Syntax errors are ParseError with line and column.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ruppert::detail {

inline constexpr int kMaxJsonDepth = 256;

struct JsonValue {
  enum class Kind : std::uint8_t { Null, Boolean, Number, String, Array, Object };
  Kind kind = Kind::Null;
  bool boolean = false;
  bool numeric = false;        // Array: every item is a number, held in `numbers` (items is empty)
  double number = 0;           // Number
  std::size_t offset = 0;      // where the value starts in the text (for error positions)
  std::string text;            // String
  std::vector<double> numbers; // Array with numeric = true
  std::vector<JsonValue> items;  // Array with numeric = false
  std::vector<std::pair<std::string, JsonValue>> members;  // Object, in the text's order

  std::size_t size() const { return numeric ? numbers.size() : items.size(); }
  // The first member named `key`, or nullptr.
  const JsonValue* find(const std::string& key) const;
};

// "array", "object", "string", ... for messages ("expected an array, found a string").
const char* jsonKindName(JsonValue::Kind kind);

// Parses the whole text (a UTF-8 byte order mark is skipped). Throws ruppert::Error ParseError
// "name:line:column: message".
JsonValue parseJsonTree(const std::string& text, const std::string& name);

// "line:column" (both 1-based) of a byte offset.
std::string jsonPosition(const std::string& text, std::size_t offset);

}  // namespace ruppert::detail
