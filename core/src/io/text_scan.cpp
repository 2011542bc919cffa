#include "text_scan.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "holefill/errors.h"

namespace holefill::io {
namespace fs = std::filesystem;

void fail(const fs::path& path, const std::string& reason) { throw FileError(path, reason); }

std::string at_line(std::size_t line) { return "line " + std::to_string(line) + ": "; }

std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxShown = 24;
  std::string shown = "'";
  for (std::size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    shown += (c >= 0x20 && c < 0x7F) ? static_cast<char>(c) : '?';
  }
  if (text.size() > kMaxShown) shown += "...";
  return shown + "'";
}

std::string_view take_token(std::string_view& text) {
  skip_blanks(text);
  std::size_t length = 0;
  while (length < text.size() && !is_blank(text[length])) ++length;
  const std::string_view token = text.substr(0, length);
  text.remove_prefix(length);
  return token;
}

namespace {

// from_chars takes no leading '+': drops one. False when nothing (or a sign again) follows.
bool drop_plus_sign(std::string_view& token) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;
  }
  return !token.empty();
}

}  // namespace

bool parse_double(std::string_view token, double& value) {
  if (!drop_plus_sign(token)) return false;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (stop != end) return false;
  if (error == std::errc::result_out_of_range) {
    // Overflow reads as infinity (refused later as non-finite), underflow as a tiny number.
    value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return error == std::errc();
}

bool parse_integer(std::string_view token, long long& value) {
  if (!drop_plus_sign(token)) return false;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  return stop == end && error == std::errc();
}

namespace {

// A whole number of at most 18 digits (no overflow possible), read by a plain loop: from_chars'
// overflow test per digit made it about a hundred instructions per face index. Returns where the
// number stops, or null when there is none or it has more digits (then from_chars decides).
const char* take_short_integer(const char* p, const char* end, long long& value) {
  const bool negative = p < end && *p == '-';
  if (negative) ++p;
  const char* const first = p;
  constexpr std::ptrdiff_t kMostDigits = 18;
  unsigned long long magnitude = 0;
  for (; p < end && *p >= '0' && *p <= '9' && p - first < kMostDigits; ++p) {
    magnitude = magnitude * 10 + static_cast<unsigned>(*p - '0');
  }
  if (p == first || (p < end && *p >= '0' && *p <= '9')) return nullptr;
  value = negative ? -static_cast<long long>(magnitude) : static_cast<long long>(magnitude);
  return p;
}

// A decimal number that is exactly a double of at most 53 bits times a power of ten up to 22
// (both exact): then one multiplication or division is correctly rounded and gives what
// from_chars gives (Clinger's fast path; from_chars' own first step). Coordinates written as
// shortest floats or with a few decimals all are. Returns where the number stops, or null when
// it is not one (from_chars decides then).
const char* take_short_decimal(const char* p, const char* end, double& value) {
  const bool negative = p < end && *p == '-';
  if (negative) ++p;
  constexpr int kMostDigits = 19;  // what a 64-bit integer holds
  std::uint64_t mantissa = 0;
  int digits = 0, fraction_digits = 0;
  for (; p < end && *p >= '0' && *p <= '9'; ++p, ++digits) {
    mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
  }
  if (p < end && *p == '.') {
    for (++p; p < end && *p >= '0' && *p <= '9'; ++p, ++digits, ++fraction_digits) {
      mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
    }
  }
  if (digits == 0 || digits > kMostDigits) return nullptr;
  int exponent = -fraction_digits;
  if (p < end && (*p == 'e' || *p == 'E')) {
    const char* q = p + 1;
    const bool negative_exponent = q < end && *q == '-';
    if (q < end && (*q == '-' || *q == '+')) ++q;
    int written = 0, exponent_digits = 0;
    for (; q < end && *q >= '0' && *q <= '9' && exponent_digits < 4; ++q, ++exponent_digits) {
      written = written * 10 + (*q - '0');
    }
    if (exponent_digits == 0 || (q < end && *q >= '0' && *q <= '9')) return nullptr;
    exponent += negative_exponent ? -written : written;
    p = q;
  }
  constexpr std::uint64_t kExactLimit = std::uint64_t{1} << 53;
  constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (mantissa > kExactLimit || exponent < -22 || exponent > 22) return nullptr;
  const double exact = static_cast<double>(mantissa);
  const double magnitude = exponent < 0 ? exact / kPowers[-exponent] : exact * kPowers[exponent];
  value = negative ? -magnitude : magnitude;
  return p;
}

}  // namespace

bool take_integer_prefix(std::string_view& text, long long& value) {
  std::string_view digits = text;
  if (!drop_plus_sign(digits)) return false;
  if (const char* stop = take_short_integer(digits.data(), digits.data() + digits.size(), value)) {
    text.remove_prefix(static_cast<std::size_t>(stop - text.data()));
    return true;
  }
  const auto [stop, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc()) return false;
  text.remove_prefix(static_cast<std::size_t>(stop - text.data()));
  return true;
}

bool take_double(std::string_view& text, double& value) {
  skip_blanks(text);
  std::string_view number = text;
  if (drop_plus_sign(number)) {
    const char* end = number.data() + number.size();
    const char* short_stop = take_short_decimal(number.data(), end, value);
    if (short_stop && at_token_end({short_stop, end})) {
      text.remove_prefix(static_cast<std::size_t>(short_stop - text.data()));
      return true;
    }
    const auto [stop, error] = std::from_chars(number.data(), end, value);
    // No number holds a blank, so one that stops at a blank (or the end) was the whole token.
    if (error == std::errc() && at_token_end({stop, end})) {
      text.remove_prefix(static_cast<std::size_t>(stop - text.data()));
      return true;
    }
  }
  // Not a whole token, out of range or no number: the token's own rules decide.
  return parse_double(take_token(text), value);
}

bool take_integer(std::string_view& text, long long& value) {
  skip_blanks(text);
  std::string_view rest = text;
  if (take_integer_prefix(rest, value) && at_token_end(rest)) {
    text = rest;
    return true;
  }
  return parse_integer(take_token(text), value);
}

// A line ends at LF, CR LF or a lone CR (classic Mac files).
bool Lines::next(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  // memchr is many times faster than a loop over the characters, but looks for one byte: the
  // line ends at the next LF or at a CR before it.
  if (next_newline_ <= position_) {
    const void* newline = std::memchr(text_.data() + position_, '\n', text_.size() - position_);
    next_newline_ = newline
                        ? static_cast<std::size_t>(static_cast<const char*>(newline) - text_.data())
                        : text_.size();
  }
  const void* return_ = std::memchr(text_.data() + position_, '\r', next_newline_ - position_);
  const std::size_t end =
      return_ ? static_cast<std::size_t>(static_cast<const char*>(return_) - text_.data())
              : next_newline_;
  line = text_.substr(position_, end - position_);
  position_ = end + 1;
  if (end + 1 < text_.size() && text_[end] == '\r' && text_[end + 1] == '\n') ++position_;
  ++number_;
  return true;
}

void require_text(std::string_view text, const fs::path& path, const char* format) {
  const std::size_t nul = text.find('\0');
  if (nul != std::string_view::npos) {
    fail(path, std::string("is not a text ") + format + " file: it holds binary data (byte " +
                   std::to_string(nul) + " is NUL)");
  }
}

std::string_view without_byte_order_mark(std::string_view bytes) {
  constexpr std::string_view kMark = "\xEF\xBB\xBF";
  return bytes.substr(0, kMark.size()) == kMark ? bytes.substr(kMark.size()) : bytes;
}

bool starts_with_word(std::string_view text, std::string_view word) {
  while (!text.empty() && (is_blank(text.front()) || text.front() == '\n')) text.remove_prefix(1);
  return text.substr(0, word.size()) == word &&
         (text.size() == word.size() || is_blank(text[word.size()]) || text[word.size()] == '\n');
}

}  // namespace holefill::io
