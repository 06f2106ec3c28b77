// TextOut: what the writers and the CLI's reports print into, instead of std::ostream.
//
// Any use of iostreams links libc++'s locale machinery (every standard facet: number parsing and
// printing, character classes), which was a third of the WebAssembly module. TextOut appends to a
// string and, when given a sink, hands the text over in pieces of about 64 KiB, so a native writer
// streaming a mesh of 10^7 triangles to a file never holds the whole text.
//
// Only text and integers are printed directly; a double must go through an explicit format (the
// writers' %.17g, the reports' fixed decimals), so no default precision can slip into a file.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdio>
#include <iosfwd>
#include <string>
#include <type_traits>
#include <utility>

#include "ruppert/ruppert.h"

namespace ruppert::detail {

class TextOut {
 public:
  using Sink = void (*)(void* context, const char* data, std::size_t size);

  // Collects everything; take it with str().
  TextOut() = default;
  // Hands the text to `sink` whenever 64 KiB have gathered, and at flush().
  TextOut(Sink sink, void* context) : sink_(sink), context_(context) {}
  TextOut(const TextOut&) = delete;
  TextOut& operator=(const TextOut&) = delete;

  TextOut& operator<<(const char* s) { return append(s); }
  TextOut& operator<<(const std::string& s) { return append(s); }
  TextOut& operator<<(char c) {
    text_ += c;
    return spill();
  }
  template <class T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, char> && !std::is_same_v<T, bool>, int> = 0>
  TextOut& operator<<(T v) {
    char buf[24];
    const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
    text_.append(buf, r.ptr);
    return spill();
  }
  TextOut& operator<<(double) = delete;
  TextOut& operator<<(float) = delete;
  TextOut& operator<<(bool) = delete;

  // Passes what has gathered to the sink (nothing without one).
  void flush() {
    if (sink_ && !text_.empty()) {
      sink_(context_, text_.data(), text_.size());
      text_.clear();
    }
  }
  const std::string& str() const { return text_; }
  std::string take() { return std::move(text_); }

 private:
  static constexpr std::size_t kPiece = 64 * 1024;
  template <class S>
  TextOut& append(const S& s) {
    text_ += s;
    return spill();
  }
  TextOut& spill() {
    if (sink_ && text_.size() >= kPiece) flush();
    return *this;
  }

  std::string text_;
  Sink sink_ = nullptr;
  void* context_ = nullptr;
};

// A finite double as %.17g prints it: 17 significant digits read back bit-exact. Where the standard
// library has floating-point to_chars (libstdc++ 11 and later), it gives the same characters (the
// standard defines it as printf's %.*g in the C locale) about twenty times faster: glibc's printf
// was half of a native run that writes 10^5 triangles. Emscripten's libc++ lacks it and keeps printf.
inline std::string realText(double v) {
  char buf[32];
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
#else
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
#endif
}

// TextOut's sink for a std::ostream given as the context. A template, so that only code that uses it
// (the native writers and CLI, which include <ostream>) instantiates any stream code.
template <class Stream>
void writeToStream(void* stream, const char* data, std::size_t size) {
  static_cast<Stream*>(stream)->write(data, static_cast<std::streamsize>(size));
}

// Prints into `out` (a std::ostream) in pieces as `print` makes the text; throws IoError naming
// `what` if the stream fails. The stream type is a parameter for the reason writeToStream's is.
template <class Stream, class Print>
void toStream(Stream& out, const char* what, Print&& print) {
  TextOut text(writeToStream<Stream>, &out);
  print(text);
  text.flush();
  out.flush();
  if (!out) throw Error(ErrorCode::IoError, std::string("writing the ") + what + " output failed");
}

// What `print` makes, as one string.
template <class Print>
std::string toText(Print&& print) {
  TextOut text;
  print(text);
  return text.take();
}

}  // namespace ruppert::detail
