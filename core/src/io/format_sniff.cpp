#include <algorithm>
#include <charconv>
#include <cstring>
#include <string>

#include "readers.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kWindow = 1 << 16;

enum class KeywordLine { Found, None, PastTheBytes };

// The longest OFF keyword, "STCN4nOFF": a longer token is neither it nor "ply".
constexpr std::size_t kLongestKeyword = 9;

// Whether a keyword line cut at the end of the bytes given (`keyword` and `rest` as far as they
// go) already answers what sniffing asks of it: is it an OFF keyword, or "ply" alone on its line.
KeywordLine cut_keyword_line(std::string_view line, std::string_view keyword,
                             std::string_view rest) {
  const bool comment = line.find('#') != std::string_view::npos;
  if (keyword.empty()) return KeywordLine::PastTheBytes;  // the keyword may be on a later line
  if (!comment && rest.empty()) {                         // the token may go on
    return keyword.size() > kLongestKeyword ? KeywordLine::Found : KeywordLine::PastTheBytes;
  }
  const bool blank_so_far = rest.find_first_not_of(" \t\r") == std::string_view::npos;
  if (keyword == "ply" && !comment && blank_so_far) return KeywordLine::PastTheBytes;
  return KeywordLine::Found;
}

// The first line of `bytes` (the first bytes of a file of `file_size` bytes) that holds a keyword:
// the keyword, and the rest of the line before any comment; None when no line has one,
// PastTheBytes when more of the file could change what sniff_start makes of it. Looked for in a
// window at the start of the text, widened until the line ends inside it (a file may start with
// any number of comment lines): Lines searches the text it is given for a CR once, so it was given
// the whole text, and sniffing a 100 MB file read all of it before the reader did (20-100 ms, one
// thread).
KeywordLine first_keyword(std::string_view bytes, std::uint64_t file_size,
                          std::string_view& keyword, std::string_view& rest) {
  for (std::size_t window = kWindow;; window *= 16) {
    const std::string_view start = bytes.substr(0, window);
    const bool whole = start.size() == file_size;
    const bool more_given = start.size() == window;  // else every byte given is in the window
    Lines lines(start);
    std::string_view line;
    while (lines.next(line)) {
      const bool cut = !whole && line.data() + line.size() == start.data() + start.size();
      if (cut && more_given) break;  // the line may go on: widen the window
      rest = line.substr(0, line.find('#'));
      keyword = take_token(rest);
      if (cut) return cut_keyword_line(line, keyword, rest);
      if (!keyword.empty()) return KeywordLine::Found;
    }
    if (whole) return KeywordLine::None;
    if (!more_given) return KeywordLine::PastTheBytes;
  }
}

}  // namespace

Sniffed sniff_start(std::string_view first_bytes, std::uint64_t file_size) {
  const std::string_view bytes = first_bytes;
  if (bytes.size() < std::min<std::uint64_t>(kWindow, file_size)) return {std::nullopt, false};
  std::string_view keyword, rest;
  const KeywordLine line = first_keyword(bytes, file_size, keyword, rest);
  if (line == KeywordLine::PastTheBytes) return {std::nullopt, false};
  if (line == KeywordLine::Found) {
    bool three_dimensional = true;
    if (keyword == "ply" && rest.find_first_not_of(" \t\r") == std::string_view::npos) {
      return {MeshFormat::Ply};
    }
    if (parse_off_keyword(keyword, three_dimensional)) return {MeshFormat::Off};
  }
  std::uint32_t count = 0;
  if (binary_stl_size_matches(bytes, file_size, count)) return {MeshFormat::Stl};
  const std::string_view window = bytes.substr(0, kWindow);
  if (window.find('\0') != std::string_view::npos) return {};
  if (starts_with_word(bytes, "solid") && window.find("facet") != std::string_view::npos) {
    return {MeshFormat::Stl};
  }
  Lines obj_lines(window);
  std::string_view obj_line;
  while (obj_lines.next(obj_line)) {
    const std::string_view first = take_token(obj_line);
    if (first == "v" || first == "f") return {MeshFormat::Obj};
  }
  return {};
}

std::optional<MeshFormat> sniff(std::string_view bytes) {
  return sniff_start(bytes, bytes.size()).format;
}

}  // namespace holefill::io
