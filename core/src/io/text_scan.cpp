#include "text_scan.h"

#include <charconv>
#include <cstdlib>

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

void skip_blanks(std::string_view& text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
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

// A line ends at LF, CR LF or a lone CR (classic Mac files).
bool Lines::next(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  // A plain loop: string_view::find_first_of calls memchr once per character.
  std::size_t end = position_;
  while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
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
