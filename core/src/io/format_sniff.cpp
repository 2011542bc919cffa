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

Format sniff(std::string_view bytes) {
  Lines lines(bytes);
  std::string_view line;
  while (lines.next(line)) {
    std::string_view rest = line.substr(0, line.find('#'));
    const std::string_view keyword = take_token(rest);
    if (keyword.empty()) continue;
    bool three_dimensional = true;
    if (keyword == "ply" && rest.find_first_not_of(" \t\r") == std::string_view::npos) {
      return Format::Ply;
    }
    if (parse_off_keyword(keyword, three_dimensional)) return Format::Off;
    break;
  }
  std::uint32_t count = 0;
  if (binary_stl_size_matches(bytes, count)) return Format::Stl;
  constexpr std::size_t kWindow = 1 << 16;
  const std::string_view window = bytes.substr(0, kWindow);
  if (window.find('\0') != std::string_view::npos) return Format::Unknown;
  if (starts_with_word(bytes, "solid") && window.find("facet") != std::string_view::npos) {
    return Format::Stl;
  }
  Lines obj_lines(window);
  while (obj_lines.next(line)) {
    const std::string_view keyword = take_token(line);
    if (keyword == "v" || keyword == "f") return Format::Obj;
  }
  return Format::Unknown;
}

}  // namespace holefill::io
