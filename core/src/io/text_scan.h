// Scanning the text of a mesh file: tokens, numbers (exact, locale-independent), lines, and the
// messages that quote what was found. Shared by every reader.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

namespace holefill::io {

// Throws FileError(path, reason).
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason);

// "line N: ", the prefix of a message about line N.
std::string at_line(std::size_t line);

// A short, printable excerpt of file text for a message (files may hold any bytes).
std::string quoted(std::string_view text);

inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Inline: called before every number (about a twentieth of reading an OBJ when it was not).
inline void skip_blanks(std::string_view& text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
}

// `text` is at its end or at a blank: a number read in place was a whole token.
inline bool at_token_end(std::string_view text) { return text.empty() || is_blank(text.front()); }

// The next blank-separated token of `text` (empty at its end), removed from `text`.
std::string_view take_token(std::string_view& text);

// The whole token is a number (from_chars: locale-independent and correctly rounded); overflow
// reads as infinity, underflow as a tiny number.
bool parse_double(std::string_view token, double& value);

// The whole token is a whole number that fits a long long.
bool parse_integer(std::string_view token, long long& value);

// Exactly `parse_double(take_token(text), value)`, but a number followed by a blank or the end
// is read in place, without finding the token's end first (from_chars finds it).
bool take_double(std::string_view& text, double& value);

// from_chars takes no leading '+': drops one. False when nothing (or a sign again) follows.
inline bool drop_plus_sign(std::string_view& token) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;
  }
  return !token.empty();
}

// The number of digits (0 to 8) that the `available` bytes at `p` start with (the first 8 of
// them), and their value: all eight tested and combined at once (SWAR, as fast_float and
// simdjson read eight digits), where from_chars takes some ten instructions a digit; face
// indices are most of an OBJ's numbers. Fewer than eight bytes (a line's last number) are read
// one at a time (a partial load went through a memcpy call).
inline int leading_digits(const char* p, std::size_t available, std::uint64_t& value) {
  if (available < 8) {
    std::uint64_t short_value = 0;
    int count = 0;
    for (; count < static_cast<int>(available); ++count) {
      const unsigned digit = static_cast<unsigned char>(p[count]) - unsigned{'0'};
      if (digit > 9) break;
      short_value = short_value * 10 + digit;
    }
    if (count) value = short_value;
    return count;
  }
  std::uint64_t bytes;
  std::memcpy(&bytes, p, sizeof bytes);  // one load
  if constexpr (std::endian::native != std::endian::little) bytes = __builtin_bswap64(bytes);
  // A byte's high bit is set in either sum unless it is '0' to '9'; what a non-digit borrows or
  // carries only reaches the bytes after it, which are not counted.
  const std::uint64_t not_digit =
      ((bytes - 0x3030303030303030) | (bytes + 0x4646464646464646)) & 0x8080808080808080;
  const int count = not_digit ? std::countr_zero(not_digit) / 8 : 8;
  if (count == 0) return 0;
  // The digits, first one highest, as "00..0ddd": then 8-digit arithmetic needs no cases.
  std::uint64_t digits = (bytes - 0x3030303030303030) << (8 * (8 - count));
  digits = digits * 10 + (digits >> 8);
  value = (((digits & 0x000000FF000000FF) * (100 + (1000000ull << 32))) +
           (((digits >> 16) & 0x000000FF000000FF) * (1 + (10000ull << 32)))) >>
          32;
  return count;
}

// take_integer_prefix for numbers of eight digits or more (from_chars).
bool take_long_integer_prefix(std::string_view& text, long long& value);

// Reads the whole number that `text` starts with (no blanks first; an optional '+' as
// parse_integer takes it) and removes it; false, with `text` unchanged, when there is none or it
// does not fit a long long. What follows is left for the caller to check. Inline, as
// take_integer: a call was a third of reading an index.
inline bool take_integer_prefix(std::string_view& text, long long& value) {
  std::string_view digits = text;
  if (!drop_plus_sign(digits)) return false;
  const std::size_t sign = digits.front() == '-' ? 1 : 0;
  std::uint64_t magnitude = 0;
  const int count = leading_digits(digits.data() + sign, digits.size() - sign, magnitude);
  if (count == 0) return false;
  if (count == 8) return take_long_integer_prefix(text, value);  // more may follow
  value = sign ? -static_cast<long long>(magnitude) : static_cast<long long>(magnitude);
  text.remove_prefix(static_cast<std::size_t>(digits.data() - text.data()) + sign +
                     static_cast<std::size_t>(count));
  return true;
}

// Exactly `parse_integer(take_token(text), value)`, reading in place as take_double does.
inline bool take_integer(std::string_view& text, long long& value) {
  skip_blanks(text);
  std::string_view rest = text;
  if (take_integer_prefix(rest, value) && at_token_end(rest)) {
    text = rest;
    return true;
  }
  return parse_integer(take_token(text), value);
}

// The first `c` at or after `from` in `text` (text.size() when none); from <= text.size().
std::size_t find_from(std::string_view text, std::size_t from, char c);

// The first `c` at or after a position of `text`, for positions that only move forward: searched
// for again only once the one found is behind (a text without `c` is searched once), where
// searching each line for it was a memchr call per line.
class NextOccurrence {
 public:
  NextOccurrence(std::string_view text, char c) : text_(text), c_(c) {}
  // text.size() when there is none; from <= text.size().
  std::size_t at_or_after(std::size_t from) {
    if (!known_ || found_ < from) {
      found_ = find_from(text_, from, c_);
      known_ = true;
    }
    return found_;
  }

 private:
  std::string_view text_;
  char c_;
  std::size_t found_ = 0;
  bool known_ = false;
};

// Lines of a text, without their end-of-line characters, counted from 1.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line);
  std::size_t number() const { return number_; }
  // Bytes after the current line.
  std::size_t remaining() const { return position_ >= text_.size() ? 0 : text_.size() - position_; }
  std::size_t offset() const { return position_ < text_.size() ? position_ : text_.size(); }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t number_ = 0;
  // The first '\n' at or after position_ (text_.size() when none): found once per LF, so a
  // file of lone CRs is not searched to its end at every line.
  std::size_t next_newline_ = 0;
  std::size_t next_return_ = 0;  // the same for '\r'
};

// The lines of a text that hold more than blanks, each without the blanks it starts with and, in
// a format with comments, without its comment (from `comment` to the line's end).
class ContentLines {
 public:
  static constexpr char kNoComments = '\0';  // text formats hold no NUL (require_text)
  explicit ContentLines(std::string_view text, char comment = kNoComments)
      : text_(text),
        lines_(text),
        next_comment_(text, comment),
        comments_(comment != kNoComments) {}

  bool next(std::string_view& line) {
    while (lines_.next(line)) {
      if (comments_) {
        const auto start = static_cast<std::size_t>(line.data() - text_.data());
        const std::size_t comment = next_comment_.at_or_after(start);
        if (comment - start < line.size()) line = line.substr(0, comment - start);
      }
      skip_blanks(line);
      if (!line.empty()) return true;
    }
    return false;
  }
  // The lines read so far, content or not; the bytes read so far.
  std::size_t number() const { return lines_.number(); }
  std::size_t offset() const { return lines_.offset(); }

 private:
  std::string_view text_;
  Lines lines_;
  NextOccurrence next_comment_;
  bool comments_;
};

// Text formats must not hold NUL bytes: a binary file with a text format's extension is refused,
// naming `format`.
void require_text(std::string_view text, const std::filesystem::path& path, const char* format);
// Refuses a text as require_text does, its byte `nul` (the first) being NUL.
[[noreturn]] void refuse_nul(std::size_t nul, const std::filesystem::path& path,
                             const char* format);

// `bytes` without the UTF-8 byte-order mark some editors put first (the bytes as they are without
// one).
std::string_view without_byte_order_mark(std::string_view bytes);

// `text` starts, after blank lines and blanks, with the whole word `word`.
bool starts_with_word(std::string_view text, std::string_view word);

}  // namespace holefill::io
