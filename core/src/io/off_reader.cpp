#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include "readers.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

bool parse_off_keyword(std::string_view keyword, bool& three_dimensional) {
  constexpr std::string_view kOff = "OFF";
  if (keyword.size() < kOff.size() || keyword.substr(keyword.size() - kOff.size()) != kOff) {
    return false;
  }
  std::string_view prefix = keyword.substr(0, keyword.size() - kOff.size());
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  for (const char letter : {'C', 'N', '4', 'n'}) {
    if (!prefix.empty() && prefix.front() == letter) prefix.remove_prefix(1);
  }
  three_dimensional = keyword.find_first_of("4n") == std::string_view::npos;
  return prefix.empty();
}

namespace {

// The next line with content, comments ('#' to the end of the line) removed.
bool next_content(Lines& lines, std::string_view& line) {
  while (lines.next(line)) {
    line = line.substr(0, line.find('#'));
    skip_blanks(line);
    if (!line.empty()) return true;
  }
  return false;
}

struct OffCounts {
  unsigned long long vertices = 0, faces = 0;
  bool normals = false, colours = false;  // NOFF, COFF (or both)
};

// Reads the keyword and counts from `lines`, checking them against the `file_size` bytes of the
// file (`lines` may hold only its first bytes).
OffCounts parse_off_header(Lines& lines, std::uint64_t file_size, const fs::path& path) {
  std::string_view line;
  if (!next_content(lines, line)) fail(path, "holds no OFF header, only blank or comment lines");
  std::string_view rest = line;
  const std::string_view keyword = take_token(rest);
  bool three_dimensional = true;
  if (!parse_off_keyword(keyword, three_dimensional)) {
    fail(path, "does not start with an OFF header (found " + quoted(keyword) + ")");
  }
  if (!three_dimensional) {
    fail(path, "only 3D OFF files are supported (header " + quoted(keyword) + ")");
  }
  skip_blanks(rest);
  if (rest.substr(0, 6) == "BINARY") {
    fail(path, "binary OFF is not supported; save it as ASCII OFF, PLY or OBJ");
  }
  if (rest.empty() && !next_content(lines, rest)) fail(path, "ends after its header keyword");
  const std::size_t counts_line = lines.number();
  long long counts[2] = {0, 0};
  for (auto& count : counts) {
    const std::string_view token = take_token(rest);
    if (!parse_integer(token, count) || count < 0) {
      fail(path, at_line(counts_line) + "the header needs vertex and face counts" +
                     (token.empty() ? std::string() : ", got " + quoted(token)));
    }
  }
  const auto vertex_count = static_cast<unsigned long long>(counts[0]);
  const auto face_count = static_cast<unsigned long long>(counts[1]);
  // A vertex takes at least 6 bytes ("0 0 0\n"), a face at least 2 ("0\n"): a header that
  // promises more than the file can hold is corrupt, and must not make us allocate for it.
  const std::uint64_t remaining = file_size - lines.offset();
  const unsigned long long room = remaining + 1;
  if (vertex_count > room / 6 || face_count > room / 2 ||
      vertex_count * 6 + face_count * 2 > room + 1) {
    fail(path, at_line(counts_line) + "the header promises " + std::to_string(vertex_count) +
                   " vertices and " + std::to_string(face_count) +
                   " faces, more than the remaining " + std::to_string(remaining) +
                   " bytes of the file can hold (corrupt header or truncated file)");
  }
  const std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  return {vertex_count, face_count, prefix.find('N') != std::string_view::npos,
          prefix.find('C') != std::string_view::npos};
}

}  // namespace

// The colour channels `numbers` hold (3: RGB, 4: RGBA; none when fewer), as 0-255 integers (uchar)
// or numbers in [0, 1] (double).
std::vector<ScalarAttribute> colour_channels(std::string_view numbers) {
  const bool fractions = numbers.find_first_of(".eE") != std::string_view::npos;
  int channels = 0;
  while (!take_token(numbers).empty()) ++channels;
  std::vector<ScalarAttribute> colour;
  if (channels < 3) return colour;
  for (const char* name : {"red", "green", "blue", "alpha"}) {
    if (colour.size() == 3 && channels < 4) break;
    colour.push_back({name, fractions ? ScalarType::Float64 : ScalarType::UInt8});
  }
  return colour;
}

// Colour channels typed uchar by their first line keep that type only if every value fits it
// (a whole number 0-255); otherwise they become doubles, which hold whatever the file has.
void settle_colour_types(std::vector<ScalarAttribute>& attributes,
                         const std::vector<std::vector<double>>& columns) {
  for (std::size_t a = 0; a < attributes.size(); ++a) {
    if (attributes[a].type != ScalarType::UInt8) continue;
    const bool fits = std::all_of(columns[a].begin(), columns[a].end(), [](double value) {
      return value >= 0.0 && value <= 255.0 && value == std::floor(value);
    });
    if (!fits) attributes[a].type = ScalarType::Float64;
  }
}

// NOFF's normals and COFF's colours become vertex attributes, typed as the first vertex line
// has them.
void plan_off_attributes(const OffCounts& counts, std::string_view first_vertex_line, Soup& soup) {
  if (counts.normals) {
    for (const char* name : {"nx", "ny", "nz"}) soup.layout.vertex.push_back({name});
  }
  if (counts.colours) {
    std::string_view rest = first_vertex_line;
    for (int skip = 0; skip < (counts.normals ? 6 : 3); ++skip) take_token(rest);
    for (auto& channel : colour_channels(rest)) soup.layout.vertex.push_back(channel);
  }
  soup.vertex_values.resize(soup.layout.vertex.size());
}

// The numbers left on a line, one per attribute column (0 where the line has none).
void read_columns(std::string_view rest, std::vector<std::vector<double>>& columns,
                  std::size_t line, const fs::path& path) {
  for (auto& column : columns) {
    std::string_view unread = rest;
    double value = 0.0;
    if (!take_double(rest, value)) {
      const std::string_view token = take_token(unread);
      if (!token.empty()) fail(path, at_line(line) + "expected a number, got " + quoted(token));
      value = 0.0;
    }
    column.push_back(value);
  }
}

// Colours after a face's indices become face attributes, typed by the first face line; returns
// false when a face has colours the first face did not announce (they are not kept).
bool read_off_face_colours(std::string_view rest, bool first_face, Soup& soup, std::size_t line,
                           const fs::path& path) {
  if (first_face) {
    soup.layout.face = colour_channels(rest);
    soup.face_values.resize(soup.layout.face.size());
  }
  if (soup.face_values.empty()) return take_token(rest).empty();
  read_columns(rest, soup.face_values, line, path);
  return true;
}

Soup parse_off(std::string_view text, const fs::path& path, LoadReport& report) {
  require_text(text, path, "OFF");
  Lines lines(text);
  const OffCounts counts = parse_off_header(lines, text.size(), path);
  const unsigned long long vertex_count = counts.vertices, face_count = counts.faces;
  std::string_view line;
  Soup soup;
  soup.positions.reserve(vertex_count);
  for (unsigned long long v = 0; v < vertex_count; ++v) {
    if (!next_content(lines, line)) {
      fail(path, "ends after " + std::to_string(v) + " of its " + std::to_string(vertex_count) +
                     " vertices (truncated?)");
    }
    if (v == 0) plan_off_attributes(counts, line, soup);
    Point p;
    for (int axis = 0; axis < 3; ++axis) {
      std::string_view unread = line;
      if (!take_double(line, p[axis])) {
        const std::string_view token = take_token(unread);
        fail(path, at_line(lines.number()) + "vertex needs 3 numbers" +
                       (token.empty() ? std::string() : ", got " + quoted(token)));
      }
    }
    require_finite(p, v, lines.number(), path);
    soup.positions.push_back(p);
    read_columns(line, soup.vertex_values, lines.number(), path);
  }
  std::size_t faces_with_colours = 0;
  for (unsigned long long f = 0; f < face_count; ++f) {
    if (!next_content(lines, line)) {
      fail(path, "ends after " + std::to_string(f) + " of its " + std::to_string(face_count) +
                     " faces (truncated?)");
    }
    long long corner_count = 0;
    std::string_view unread = line;
    if (!take_integer(line, corner_count) || corner_count < 0) {
      fail(path, at_line(lines.number()) + "a face must start with its number of corners, got " +
                     quoted(take_token(unread)));
    }
    for (long long c = 0; c < corner_count; ++c) {
      unread = line;
      long long index = 0;
      if (!take_integer(line, index)) {
        const std::string_view token = take_token(unread);
        fail(path, at_line(lines.number()) + "face needs " + std::to_string(corner_count) +
                       " vertex indices" +
                       (token.empty() ? std::string() : ", got " + quoted(token)));
      }
      if (index < 0 || static_cast<unsigned long long>(index) >= vertex_count) {
        fail(path, at_line(lines.number()) + "face refers to vertex " + std::to_string(index) +
                       ", but the file has " + std::to_string(vertex_count) +
                       " vertices (numbered from 0)");
      }
      soup.corners.push_back(static_cast<int>(index));
    }
    if (!read_off_face_colours(line, f == 0, soup, lines.number(), path)) ++faces_with_colours;
    soup.end_face(soup.corners.size(), lines.number());
  }
  settle_colour_types(soup.layout.vertex, soup.vertex_values);
  settle_colour_types(soup.layout.face, soup.face_values);
  if (faces_with_colours) {
    report.warnings.push_back(
        std::to_string(faces_with_colours) +
        " faces' colours (numbers after their vertex indices where the first face has none) "
        "were not kept");
  }
  std::size_t extra_lines = 0;
  while (next_content(lines, line)) ++extra_lines;
  if (extra_lines) {
    report.warnings.push_back(std::to_string(extra_lines) + " lines after the last of the " +
                              std::to_string(face_count) +
                              " faces the header counts were ignored (the header's counts may be "
                              "too small)");
  }
  return soup;
}

void check_off_start(std::string_view first_bytes, std::uint64_t file_size, const fs::path& path) {
  Lines lines(first_bytes);
  parse_off_header(lines, file_size, path);
  require_text(first_bytes, path, "OFF");
}

}  // namespace holefill::io
