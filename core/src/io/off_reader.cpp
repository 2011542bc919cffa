#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include "mesh_from_triangles.h"
#include "readers.h"
#include "text_scan.h"
#include "two_parts.h"

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

struct OffCounts {
  unsigned long long vertices = 0, faces = 0;
  bool normals = false, colours = false;  // NOFF, COFF (or both)
};

// Reads the keyword and counts from `lines`, checking them against the `file_size` bytes of the
// file (`lines` may hold only its first bytes).
OffCounts parse_off_header(ContentLines& lines, std::uint64_t file_size, const fs::path& path) {
  std::string_view line;
  if (!lines.next(line)) fail(path, "holds no OFF header, only blank or comment lines");
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
  if (rest.empty() && !lines.next(rest)) fail(path, "ends after its header keyword");
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

namespace {

// Reads an OFF body's records (its content lines: the counted vertices, then the counted faces,
// then lines that are ignored with a warning) into a soup: the whole body, or one part of it.
class OffBody {
 public:
  OffBody(const OffCounts& counts, const fs::path& path) : counts_(counts), path_(path) {}

  // Gives the soup room for the records from `first` on, which `bytes` bytes of the file hold:
  // the positions with the mesh's room when `first` is 0 (the mesh then takes them without a
  // copy), the faces as triangles (most files' faces; each corner takes a byte at least), so that
  // the arrays are not copied into twice their size as they grow, nor when a second part is
  // appended; on huge pages (huge_pages.h), where a fault per 4 KB page was a large part of
  // reading them.
  void reserve(unsigned long long first, std::size_t bytes);

  // Reads the records of `text`, which follows `lines_before` lines of the file and starts at
  // record `first`. A file that ends before the counted records is refused only when `last`
  // (else `text` is a first part, and the rest follows).
  void read(std::string_view text, std::size_t lines_before, unsigned long long first, bool last);

  // Appends `later`, read from where this part ends on; false, with nothing changed, when it
  // could not be read alone (its faces' colours depend on the first face, read here).
  bool append(OffBody& later);

  // The soup, with the warnings for what was not kept.
  Soup finish(LoadReport& report);

  // Where the text read last ends: records and lines before it.
  unsigned long long records() const { return record_; }
  std::size_t lines() const { return lines_; }

 private:
  void read_vertex(std::string_view line, unsigned long long v, std::size_t at);
  void read_face(std::string_view line, unsigned long long f, std::size_t at);

  const OffCounts& counts_;
  const fs::path& path_;
  Soup soup_;
  unsigned long long record_ = 0;  // the next record to read
  std::size_t lines_ = 0;
  std::size_t faces_with_colours_ = 0, extra_lines_ = 0;
};

void OffBody::reserve(unsigned long long first, std::size_t bytes) {
  const unsigned long long vertices = counts_.vertices - std::min(first, counts_.vertices);
  const unsigned long long faces_before = first - std::min(first, counts_.vertices);
  const unsigned long long faces = counts_.faces - std::min(faces_before, counts_.faces);
  reserve_positions(soup_.positions, static_cast<std::size_t>(vertices), first == 0);
  reserve_faces(soup_, static_cast<std::size_t>(faces), bytes);
}

void OffBody::read(std::string_view text, std::size_t lines_before, unsigned long long first,
                   bool last) {
  const unsigned long long vertex_count = counts_.vertices, face_count = counts_.faces;
  ContentLines lines(text, '#');
  std::string_view line;
  for (record_ = first; lines.next(line); ++record_) {
    const std::size_t at = lines_before + lines.number();
    if (record_ < vertex_count) {
      read_vertex(line, record_, at);
    } else if (record_ - vertex_count < face_count) {
      read_face(line, record_ - vertex_count, at);
    } else {
      ++extra_lines_;
    }
  }
  lines_ = lines_before + lines.number();
  if (!last) return;
  if (record_ < vertex_count) {
    fail(path_, "ends after " + std::to_string(record_) + " of its " +
                    std::to_string(vertex_count) + " vertices (truncated?)");
  }
  if (record_ - vertex_count < face_count) {
    fail(path_, "ends after " + std::to_string(record_ - vertex_count) + " of its " +
                    std::to_string(face_count) + " faces (truncated?)");
  }
}

void OffBody::read_vertex(std::string_view line, unsigned long long v, std::size_t at) {
  if (v == 0) plan_off_attributes(counts_, line, soup_);
  Point p;
  for (int axis = 0; axis < 3; ++axis) {
    std::string_view unread = line;
    if (!take_double(line, p[axis])) {
      const std::string_view token = take_token(unread);
      fail(path_, at_line(at) + "vertex needs 3 numbers" +
                      (token.empty() ? std::string() : ", got " + quoted(token)));
    }
  }
  require_finite(p, v, at, path_);
  soup_.positions.push_back(p);
  read_columns(line, soup_.vertex_values, at, path_);
}

void OffBody::read_face(std::string_view line, unsigned long long f, std::size_t at) {
  long long corner_count = 0;
  std::string_view unread = line;
  if (!take_integer(line, corner_count) || corner_count < 0) {
    fail(path_, at_line(at) + "a face must start with its number of corners, got " +
                    quoted(take_token(unread)));
  }
  for (long long c = 0; c < corner_count; ++c) {
    unread = line;
    long long index = 0;
    if (!take_integer(line, index)) {
      const std::string_view token = take_token(unread);
      fail(path_, at_line(at) + "face needs " + std::to_string(corner_count) + " vertex indices" +
                      (token.empty() ? std::string() : ", got " + quoted(token)));
    }
    if (index < 0 || static_cast<unsigned long long>(index) >= counts_.vertices) {
      fail(path_, at_line(at) + "face refers to vertex " + std::to_string(index) +
                      ", but the file has " + std::to_string(counts_.vertices) +
                      " vertices (numbered from 0)");
    }
    soup_.corners.push_back(static_cast<int>(index));
  }
  if (!read_off_face_colours(line, f == 0, soup_, at, path_)) ++faces_with_colours_;
  // No line kept per face: nothing after the reading names a face's line (8 bytes a face).
  soup_.end_face(soup_.corners.size(), 0);
}

bool OffBody::append(OffBody& later) {
  Soup& more = later.soup_;
  const bool first_face_here = record_ > counts_.vertices;
  if (first_face_here && !soup_.layout.face.empty() && more.face_count() != 0) return false;
  append_positions_and_faces(soup_, more);
  if (!first_face_here) {
    soup_.layout.face = more.layout.face;
    soup_.face_values = std::move(more.face_values);
  }
  faces_with_colours_ += later.faces_with_colours_;
  extra_lines_ += later.extra_lines_;
  record_ = later.record_;
  lines_ = later.lines_;
  return true;
}

Soup OffBody::finish(LoadReport& report) {
  settle_colour_types(soup_.layout.vertex, soup_.vertex_values);
  settle_colour_types(soup_.layout.face, soup_.face_values);
  if (faces_with_colours_) {
    report.warnings.push_back(
        std::to_string(faces_with_colours_) +
        " faces' colours (numbers after their vertex indices where the first face has none) "
        "were not kept");
  }
  if (extra_lines_) {
    report.warnings.push_back(std::to_string(extra_lines_) + " lines after the last of the " +
                              std::to_string(counts_.faces) +
                              " faces the header counts were ignored (the header's counts may be "
                              "too small)");
  }
  return std::move(soup_);
}

}  // namespace

Soup parse_off(std::string_view text, const fs::path& path, LoadReport& report,
               std::size_t split_near) {
  require_text(text, path, "OFF");
  ContentLines header(text, '#');
  const OffCounts counts = parse_off_header(header, text.size(), path);
  const std::size_t body = header.offset(), header_lines = header.number();
  OffBody reading(counts, path);
  reading.reserve(0, text.size() - body);
  const std::size_t split = line_start_after(text, std::max(split_near, body));
  // A vertex's attributes are planned from the first vertex line: read on one thread.
  if (split >= text.size() || counts.normals || counts.colours) {
    reading.read(text.substr(body), header_lines, 0, true);
    return reading.finish(report);
  }
  // The second part on a thread of its own, which first counts the lines and records before it.
  const std::string_view first = text.substr(body, split - body), second = text.substr(split);
  OffBody later(counts, path);
  const bool later_read =
      read_in_two_parts([&] { reading.read(first, header_lines, 0, false); },
                        [&] {
                          ContentLines lines(first, '#');
                          unsigned long long records = 0;
                          for (std::string_view line; lines.next(line);) ++records;
                          later.reserve(records, second.size());
                          later.read(second, header_lines + lines.number(), records, true);
                        });
  if (!later_read || !reading.append(later)) {
    reading.read(second, reading.lines(), reading.records(), true);
  }
  return reading.finish(report);
}

Soup parse_off(std::string_view text, const fs::path& path, LoadReport& report) {
  return parse_off(text, path, report,
                   text.size() >= kTwoPartsFrom ? text.size() / 2 : std::string_view::npos);
}

void check_off_start(std::string_view first_bytes, std::uint64_t file_size, const fs::path& path) {
  ContentLines lines(first_bytes, '#');
  parse_off_header(lines, file_size, path);
  require_text(first_bytes, path, "OFF");
}

}  // namespace holefill::io
