#include "text_scan.h"

#include <algorithm>
#include <bit>
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

bool take_long_integer_prefix(std::string_view& text, long long& value) {
  std::string_view digits = text;
  if (!drop_plus_sign(digits)) return false;
  const auto [stop, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc()) return false;
  text.remove_prefix(static_cast<std::size_t>(stop - text.data()));
  return true;
}

namespace {

// The powers of ten that a double holds exactly.
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kMaxExactPower = 22;
constexpr std::uint64_t kMaxExactMantissa = std::uint64_t{1} << 53;
constexpr std::uint64_t kPowersOfTenToEight[] = {1,      10,      100,      1000,     10000,
                                                 100000, 1000000, 10000000, 100000000};

// Appends the digits at `p` (up to `end`) to `mantissa` and returns how many there were.
[[gnu::always_inline]] inline int append_digits(const char*& p, const char* end,
                                                std::uint64_t& mantissa) {
  const char* q = p;
  std::uint64_t value = mantissa;  // locals: no store per digit
  for (;;) {
    std::uint64_t some = 0;
    const int count = leading_digits(q, static_cast<std::size_t>(end - q), some);
    value = value * kPowersOfTenToEight[count] + some;  // wraps past 19 digits, refused
    q += count;
    if (count < 8) break;
  }
  const auto count = static_cast<int>(q - p);
  p = q;
  mantissa = value;
  return count;
}

// The usual decimal spellings ("-0.1234", "5e-3"; at most 19 digits, the mantissa at most 2^53,
// the power of ten at most 22 either way) by Clinger's fast path: both the mantissa and the
// power are exact doubles, so one product or quotient is the correctly rounded value that
// from_chars gives (it takes this path itself, after a costlier scan). True, with the number
// removed from `number`, only when it is followed by a blank or the end; anything else is left to
// from_chars.
bool take_short_decimal(std::string_view& number, double& value) {
  const char* p = number.data();
  const char* const end = p + number.size();
  const bool negative = *p == '-';
  p += negative;
  std::uint64_t mantissa = 0;
  const int whole = append_digits(p, end, mantissa);
  int fraction = 0;
  if (p != end && *p == '.') {
    ++p;
    fraction = append_digits(p, end, mantissa);
  }
  if (whole + fraction == 0 || whole + fraction > 19) return false;
  int exponent = -fraction;
  if (p != end && (*p == 'e' || *p == 'E')) {
    ++p;
    const bool negative_exponent = p != end && *p == '-';
    if (p != end && (*p == '-' || *p == '+')) ++p;
    std::uint64_t written = 0;
    const int digits = append_digits(p, end, written);
    if (digits == 0 || digits > 3) return false;
    exponent += negative_exponent ? -static_cast<int>(written) : static_cast<int>(written);
  }
  if (!at_token_end({p, static_cast<std::size_t>(end - p)}) || mantissa > kMaxExactMantissa ||
      exponent < -kMaxExactPower || exponent > kMaxExactPower) {
    return false;
  }
  const auto exact = static_cast<double>(mantissa);
  value = exponent < 0 ? exact / kExactPowersOfTen[-exponent] : exact * kExactPowersOfTen[exponent];
  if (negative) value = -value;
  number.remove_prefix(static_cast<std::size_t>(p - number.data()));
  return true;
}

}  // namespace

bool take_double(std::string_view& text, double& value) {
  skip_blanks(text);
  std::string_view number = text;
  if (drop_plus_sign(number)) {
    if (take_short_decimal(number, value)) {
      text = number;
      return true;
    }
    const char* end = number.data() + number.size();
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

// The first `c` at or after `from` in `text` (text.size() when none).
std::size_t find_from(std::string_view text, std::size_t from, char c) {
  const void* found = std::memchr(text.data() + from, c, text.size() - from);
  return found ? static_cast<std::size_t>(static_cast<const char*>(found) - text.data())
               : text.size();
}

// A line ends at LF, CR LF or a lone CR (classic Mac files).
bool Lines::next(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  // memchr is many times faster than a loop over the characters, but looks for one byte: the
  // line ends at the next LF or at a CR before it. Each is searched for from where the last one
  // was found, once it is behind (a file without CRs is searched for them once).
  if (next_newline_ <= position_) next_newline_ = find_from(text_, position_, '\n');
  if (next_return_ <= position_) next_return_ = find_from(text_, position_, '\r');
  const std::size_t end = std::min(next_newline_, next_return_);
  line = text_.substr(position_, end - position_);
  position_ = end + 1;
  if (end + 1 < text_.size() && text_[end] == '\r' && text_[end + 1] == '\n') ++position_;
  ++number_;
  return true;
}

void require_text(std::string_view text, const fs::path& path, const char* format) {
  const std::size_t nul = text.find('\0');
  if (nul != std::string_view::npos) refuse_nul(nul, path, format);
}

void refuse_nul(std::size_t nul, const fs::path& path, const char* format) {
  fail(path, std::string("is not a text ") + format + " file: it holds binary data (byte " +
                 std::to_string(nul) + " is NUL)");
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
