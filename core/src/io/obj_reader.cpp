#include <algorithm>
#include <charconv>
#include <cstring>
#include <set>
#include <string>

#include "readers.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;
namespace {

// A backslash at the end of a line continues it on the next, unless it ends a comment.
bool continues(std::string_view line) {
  return !line.empty() && line.back() == '\\' && line.find('#') == std::string_view::npos;
}

// The common "v x y z r g b" extension: colours in [0, 1] as vertex attributes, from the first
// vertex that has them (vertices without get 0).
void read_vertex_colour(std::string_view rest, Soup& soup) {
  double rgb[3];
  for (double& channel : rgb) {
    if (!parse_double(take_token(rest), channel)) return;
  }
  if (soup.layout.vertex.empty()) {
    for (const char* name : {"red", "green", "blue"}) soup.layout.vertex.push_back({name});
    soup.vertex_values.resize(3);
  }
  for (int c = 0; c < 3; ++c) {
    soup.vertex_values[c].resize(soup.positions.size() - 1, 0.0);
    soup.vertex_values[c].push_back(rgb[c]);
  }
}

}  // namespace

Soup parse_obj(std::string_view text, const fs::path& path, LoadReport& report) {
  require_text(text, path, "OBJ");
  Soup soup;
  std::vector<long long> corners;  // 0-based, checked against the vertex count at the end
  Lines lines(text);
  std::string_view line;
  std::string joined;
  std::set<std::string> not_kept;
  while (lines.next(line)) {
    const std::size_t line_number = lines.number();
    if (continues(line)) {
      joined.assign(line.substr(0, line.size() - 1));
      std::string_view more;
      bool continued = true;
      while (continued && lines.next(more)) {
        continued = continues(more);
        joined += ' ';
        joined += more.substr(0, more.size() - (continued ? 1 : 0));
      }
      line = joined;
    }
    std::string_view rest = line.substr(0, line.find('#'));  // comments run to the line's end
    const std::string_view keyword = take_token(rest);
    if (keyword.empty()) continue;
    if (keyword == "v") {
      Point p;
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view token = take_token(rest);
        if (!parse_double(token, p[axis])) {
          fail(path, at_line(line_number) + "vertex needs 3 numbers" +
                         (token.empty() ? std::string() : ", got " + quoted(token)));
        }
      }
      if (static_cast<long long>(soup.positions.size()) >= kMaxVertices) {
        fail(path, at_line(line_number) + "more vertices than holefill supports");
      }
      require_finite(p, soup.positions.size() + 1, line_number, path);
      soup.positions.push_back(p);
      read_vertex_colour(rest, soup);
    } else if (keyword == "f" || keyword == "fo") {
      const std::size_t first = corners.size();
      for (std::string_view corner = take_token(rest); !corner.empty(); corner = take_token(rest)) {
        // "v", "v/vt", "v//vn" or "v/vt/vn": only the position index matters here.
        const std::string_view index_text = corner.substr(0, corner.find('/'));
        long long index = 0;
        if (!parse_integer(index_text, index)) {
          fail(path,
               at_line(line_number) + "face corner " + quoted(corner) + " is not a vertex index");
        }
        if (index == 0) fail(path, at_line(line_number) + "vertex index 0 (OBJ counts from 1)");
        const long long defined = static_cast<long long>(soup.positions.size());
        if (index < 0) {
          // Relative: -1 is the last vertex defined so far.
          if (index < -defined) {
            fail(path, at_line(line_number) + "relative vertex index " + std::to_string(index) +
                           " reaches before the first vertex");
          }
          index += defined;
        } else {
          index -= 1;
        }
        corners.push_back(index);
      }
      if (corners.size() == first) {
        ++report.degenerate_faces_dropped;
        continue;
      }
      soup.end_face(corners.size(), line_number);
    } else if (keyword == "vt" || keyword == "vn" || keyword == "usemtl" || keyword == "mtllib") {
      not_kept.insert(std::string(keyword));
    } else if (keyword == "l" || keyword == "p" || keyword == "curv" || keyword == "curv2" ||
               keyword == "surf") {
      ++report.elements_ignored;
    }
  }
  if (!not_kept.empty()) {
    std::string kinds;
    for (const auto& kind : not_kept) kinds += (kinds.empty() ? "" : ", ") + kind;
    report.warnings.push_back("the file's " + kinds +
                              " lines (texture coordinates, normals, materials) were not kept");
  }
  const long long vertex_count = static_cast<long long>(soup.positions.size());
  soup.corners.reserve(corners.size());
  for (std::size_t f = 0, c = 0; f < soup.face_count(); ++f) {
    for (; c < soup.face_end[f]; ++c) {
      if (corners[c] >= vertex_count) {
        fail(path, at_line(soup.face_line[f]) + "face refers to vertex " +
                       std::to_string(corners[c] + 1) + ", but the file has " +
                       std::to_string(vertex_count) + " vertices");
      }
      soup.corners.push_back(static_cast<int>(corners[c]));
    }
  }
  for (auto& column : soup.vertex_values) column.resize(soup.positions.size(), 0.0);
  return soup;
}

}  // namespace holefill::io
