#include <algorithm>
#include <charconv>
#include <cstring>
#include <string>

#include "readers.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

const char* name_of(Format format) {
  switch (format) {
    case Format::Obj:
      return "obj";
    case Format::Off:
      return "off";
    case Format::Ply:
      return "ply";
    case Format::Stl:
      return "stl";
    case Format::Unknown:
      break;
  }
  return "unknown";
}

Format format_of_extension(const std::string& ext) {
  if (ext == ".obj") return Format::Obj;
  if (ext == ".off") return Format::Off;
  if (ext == ".ply") return Format::Ply;
  if (ext == ".stl") return Format::Stl;
  return Format::Unknown;
}

namespace {

constexpr std::size_t kWindow = 1 << 16;

// The first line of `bytes` that holds a keyword: the keyword, and the rest of the line before
// any comment; false when no line has one. Looked for in a window at the start of the text,
// widened until the line ends inside it (a file may start with any number of comment lines):
// Lines searches the text it is given for a CR once, so it was given the whole text, and
// sniffing a 100 MB file read all of it before the reader did (20-100 ms, one thread).
bool first_keyword(std::string_view bytes, std::string_view& keyword, std::string_view& rest) {
  for (std::size_t window = kWindow;; window *= 16) {
    const std::string_view start = bytes.substr(0, window);
    const bool whole = start.size() == bytes.size();
    Lines lines(start);
    std::string_view line;
    while (lines.next(line)) {
      if (!whole && line.data() + line.size() == start.data() + start.size()) break;  // may go on
      rest = line.substr(0, line.find('#'));
      keyword = take_token(rest);
      if (!keyword.empty()) return true;
    }
    if (whole) return false;
  }
}

}  // namespace

Format sniff(std::string_view bytes) {
  std::string_view keyword, rest;
  if (first_keyword(bytes, keyword, rest)) {
    bool three_dimensional = true;
    if (keyword == "ply" && rest.find_first_not_of(" \t\r") == std::string_view::npos) {
      return Format::Ply;
    }
    if (parse_off_keyword(keyword, three_dimensional)) return Format::Off;
  }
  std::uint32_t count = 0;
  if (binary_stl_size_matches(bytes, count)) return Format::Stl;
  const std::string_view window = bytes.substr(0, kWindow);
  if (window.find('\0') != std::string_view::npos) return Format::Unknown;
  if (starts_with_word(bytes, "solid") && window.find("facet") != std::string_view::npos) {
    return Format::Stl;
  }
  Lines obj_lines(window);
  std::string_view line;
  while (obj_lines.next(line)) {
    const std::string_view keyword = take_token(line);
    if (keyword == "v" || keyword == "f") return Format::Obj;
  }
  return Format::Unknown;
}

}  // namespace holefill::io
