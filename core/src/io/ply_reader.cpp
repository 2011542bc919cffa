#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "mesh_from_triangles.h"
#include "ply_body.h"
#include "ply_header.h"
#include "readers.h"
#include "text_scan.h"
#include "two_parts.h"

namespace holefill::io {
namespace fs = std::filesystem;
namespace {

// The index of the property named one of `names` (not a list unless `list`), or -1.
int find_property(const PlyElement& element, std::initializer_list<std::string_view> names,
                  bool list) {
  for (int i = 0; i < static_cast<int>(element.properties.size()); ++i) {
    const auto& property = element.properties[i];
    if (property.is_list != list) continue;
    if (std::find(names.begin(), names.end(), property.name) != names.end()) return i;
  }
  return -1;
}

// The face's list of vertex indices: the one named so, or else its first list.
int face_list_of(const PlyElement& face) {
  const int named = find_property(face, {"vertex_indices", "vertex_index"}, true);
  if (named >= 0) return named;
  for (int i = 0; i < static_cast<int>(face.properties.size()); ++i) {
    if (face.properties[i].is_list) return i;
  }
  return -1;
}

// Where an element's values go: per property, the attribute column (or -1: not kept).
struct ElementColumns {
  std::vector<int> column_of;
  std::vector<std::vector<double>>* columns = nullptr;
};

// Reads one element's records from record `first` on; positions and face corners go into `soup`
// (corners checked against the vertex count once all are read), other values into their
// columns. Returns the records read (fewer than asked where a part of the body ends).
unsigned long long read_element(PlyBody& body, const PlyElement& element,
                                const ElementColumns& kept, Soup& soup, unsigned long long first,
                                const fs::path& path) {
  const bool is_vertex = element.name == "vertex";
  const bool is_face = element.name == "face";
  const int axis_of[3] = {find_property(element, {"x"}, false),
                          find_property(element, {"y"}, false),
                          find_property(element, {"z"}, false)};
  const int face_list = is_face ? face_list_of(element) : -1;
  // The header's counts fit the file; the room is what the mesh takes the positions with.
  const unsigned long long count = element.count - first;
  // On huge pages (huge_pages.h), where a fault per 4 KB page was a large part of reading them.
  if (is_vertex) reserve_positions(soup.positions, static_cast<std::size_t>(count), first == 0);
  if (is_face) reserve_faces(soup, static_cast<std::size_t>(count), body.remaining());
  for (unsigned long long r = first; r < element.count; ++r) {
    if (!body.begin_record(element.name, r, element.count)) return r - first;
    Point p(0.0, 0.0, 0.0);
    for (int i = 0; i < static_cast<int>(element.properties.size()); ++i) {
      const auto& property = element.properties[i];
      if (!property.is_list) {
        const double value = body.read(property.type);
        for (int axis = 0; axis < 3; ++axis) {
          if (is_vertex && axis_of[axis] == i) p[axis] = value;
        }
        if (kept.columns && kept.column_of[i] >= 0) {
          (*kept.columns)[kept.column_of[i]].push_back(value);
        }
        continue;
      }
      const double count = body.read(property.count_type);
      const std::size_t smallest = std::min<std::size_t>(2, size_of(property.type));
      if (count < 0.0 || count > static_cast<double>(body.remaining() / smallest + 1)) {
        fail(path, body.where() + ": a list claims " +
                       std::to_string(static_cast<long long>(count)) +
                       " items, more than the rest of the file holds (truncated or corrupt)");
      }
      for (long long item = 0; item < static_cast<long long>(count); ++item) {
        const double value = body.read(property.type);
        if (i != face_list) continue;
        // A whole number in range (NaN is not): the int conversion is exact, where floor was a
        // call per corner.
        if (!(value >= 0.0 && value <= kMaxVertices) ||
            value != static_cast<double>(static_cast<int>(value))) {
          fail(path, "face " + std::to_string(r) + " has an invalid vertex index " +
                         std::to_string(value));
        }
        soup.corners.push_back(static_cast<int>(value));
      }
    }
    body.end_record();
    if (is_vertex) {
      require_finite(p, r, 0, path);
      soup.positions.push_back(p);
    }
    if (is_face) soup.end_face(soup.corners.size(), 0);
  }
  return count;
}

// Reads the records of `body` from record `first` (counted over all elements in order) on, as
// far as the part it reads goes; returns the number of the record after the last one read.
unsigned long long read_records(PlyBody& body, const PlyHeader& header,
                                const std::vector<ElementColumns>& plan, Soup& soup,
                                unsigned long long first, const fs::path& path) {
  unsigned long long before = 0;  // the records of the elements before e
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const unsigned long long count = header.elements[e].count;
    if (first < before + count) {
      const unsigned long long from = first - before;
      const unsigned long long read =
          read_element(body, header.elements[e], plan[e], soup, from, path);
      if (read < count - from) return before + from + read;
      first = before + count;
    }
    before += count;
  }
  return std::max(first, before);
}

// 0, 1, 2 for a position's property x, y, z; -1 for any other name.
int position_axis(std::string_view name) {
  return name.size() == 1 && name[0] >= 'x' && name[0] <= 'z' ? name[0] - 'x' : -1;
}

// Properties that repeat an earlier one's name in their element: the mesh keeps one attribute a
// name, so their values are read past, and one warning says how many and names the first.
struct RepeatedNames {
  std::size_t count = 0;
  std::string first;
  void note(const PlyProperty& property, const PlyElement& element) {
    if (count++ == 0) {
      first = "'" + property.name + "' of the '" + element.name + "' element at line " +
              std::to_string(property.repeats_line);
    }
  }
  void warn(LoadReport& report) const {
    if (count == 0) return;
    report.warnings.push_back(std::to_string(count) +
                              (count == 1 ? " property repeats" : " properties repeat") +
                              " an earlier property's name and " + (count == 1 ? "was" : "were") +
                              " not kept (the first of that name is): " + first);
  }
};

// The vertex and face properties the mesh keeps (every scalar one but x, y, z, and the first of
// each name), their columns in the soup, and a warning for each element, list or repeated name
// that cannot be kept.
std::vector<ElementColumns> plan_attributes(const PlyHeader& header, Soup& soup,
                                            LoadReport& report) {
  std::vector<ElementColumns> plan(header.elements.size());
  AttributeLayout& layout = soup.layout;
  layout.encoding = header.encoding;
  RepeatedNames repeated;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    if (!is_vertex && !is_face) {
      if (element.count) {
        report.warnings.push_back("the '" + element.name + "' element (" +
                                  std::to_string(element.count) + " records) was not kept");
      }
      continue;
    }
    auto& attributes = is_vertex ? layout.vertex : layout.face;
    plan[e].columns = is_vertex ? &soup.vertex_values : &soup.face_values;
    plan[e].column_of.assign(element.properties.size(), -1);
    const int face_list = is_face ? face_list_of(element) : -1;
    for (int i = 0; i < static_cast<int>(element.properties.size()); ++i) {
      const PlyProperty& property = element.properties[i];
      const int axis = is_vertex ? position_axis(property.name) : -1;
      if (property.repeats_line) {
        repeated.note(property, element);
      } else if (axis >= 0) {
        // Each written back in its own type (a double z beside float x and y stays double),
        // integers as doubles: new positions would not fit them.
        layout.position_types[axis] =
            is_integer_type(property.type) ? ScalarType::Float64 : property.type;
      } else if (i == face_list) {
        layout.face_count_type = property.count_type;
        layout.face_index_type = property.type;
      } else if (property.is_list) {
        report.warnings.push_back("the list property '" + property.name + "' of the '" +
                                  element.name + "' element was not kept");
      } else {
        plan[e].column_of[i] = static_cast<int>(attributes.size());
        attributes.push_back({property.name, property.type});
        plan[e].columns->emplace_back().reserve(element.count);
      }
    }
  }
  repeated.warn(report);
  return plan;
}

}  // namespace

void check_ply_start(std::string_view first_bytes, std::uint64_t file_size, const fs::path& path) {
  if (first_bytes.find("end_header") == std::string_view::npos) return;
  const PlyHeader header = parse_ply_header(first_bytes, file_size, path);
  if (header.encoding == PlyEncoding::Ascii) {
    require_text(first_bytes.substr(header.body_offset), path, "ASCII PLY");
  }
}

namespace {

// Appends the soup `later` read of a body's second part to `soup` (their columns alike).
void append_part(Soup& soup, Soup& later) {
  append_positions_and_faces(soup, later);
  for (std::size_t c = 0; c < later.vertex_values.size(); ++c) {
    append_and_free(soup.vertex_values[c], later.vertex_values[c]);
  }
  for (std::size_t c = 0; c < later.face_values.size(); ++c) {
    append_and_free(soup.face_values[c], later.face_values[c]);
  }
}

// Reads an ASCII body in two parts, the second on a thread of its own, from `split` (a line
// start) on; returns the lines after the last record.
std::size_t read_ascii_in_two_parts(std::string_view body_bytes, std::size_t split,
                                    const PlyHeader& header,
                                    const std::vector<ElementColumns>& plan, Soup& soup,
                                    const fs::path& path) {
  PlyBody first(body_bytes, header, path, {0, split, 0, false});
  const std::string_view first_text = body_bytes.substr(0, split);
  unsigned long long records = 0;
  std::size_t leftover = 0;
  Soup later;
  LoadReport ignored;  // the warnings are the first reading's
  const std::vector<ElementColumns> later_plan = plan_attributes(header, later, ignored);
  std::size_t later_leftover = 0;
  const bool later_read = read_in_two_parts(
      [&] {
        records = read_records(first, header, plan, soup, 0, path);
        leftover = first.leftover_lines();
      },
      [&] {
        ContentLines lines(first_text);
        unsigned long long before = 0;
        for (std::string_view line; lines.next(line);) ++before;
        PlyBody second(body_bytes, header, path, {split, std::string_view::npos, lines.number()});
        read_records(second, header, later_plan, later, before, path);
        later_leftover = second.leftover_lines();
      });
  if (later_read) {
    append_part(soup, later);
    return leftover + later_leftover;
  }
  PlyBody second(body_bytes, header, path, {split, std::string_view::npos, first.lines_read()});
  read_records(second, header, plan, soup, records, path);
  return leftover + second.leftover_lines();
}

// Where a binary body's face element begins, when the records before it have one size each (no
// lists) and no vertex element follows it, so that the faces can be read apart from the vertices
// (into the other arrays of the soup): the element's index and its byte in the body, or nothing.
struct FaceStart {
  std::size_t element = 0, offset = 0;
};
std::optional<FaceStart> binary_face_start(const PlyHeader& header, std::size_t body_size) {
  FaceStart start;
  for (; start.element < header.elements.size(); ++start.element) {
    const PlyElement& element = header.elements[start.element];
    if (element.name == "face") break;
    std::size_t record = 0;
    for (const auto& property : element.properties) {
      if (property.is_list) return std::nullopt;
      record += size_of(property.type);
    }
    if (record && element.count > (body_size - start.offset) / record) return std::nullopt;
    start.offset += static_cast<std::size_t>(element.count) * record;
  }
  if (start.element == 0 || start.element == header.elements.size()) return std::nullopt;
  for (std::size_t e = start.element; e < header.elements.size(); ++e) {
    if (header.elements[e].name == "vertex") return std::nullopt;
  }
  return start;
}

// Reads a binary body's elements before the face element here and the rest on a second thread,
// each into arrays of the soup the other does not touch (positions and vertex values, corners and
// face values); the first part's error, where both fail, is the one a reading in order meets
// first. Returns the bytes left over after the last record.
std::string read_binary_in_two_parts(std::string_view body_bytes, const FaceStart& start,
                                     const PlyHeader& header,
                                     const std::vector<ElementColumns>& plan, Soup& soup,
                                     const fs::path& path) {
  PlyBody first(body_bytes.substr(0, start.offset), header, path);
  PlyBody second(body_bytes.substr(start.offset), header, path);
  unsigned long long records_before = 0;
  for (std::size_t e = 0; e < start.element; ++e) records_before += header.elements[e].count;
  run_both(
      true,
      [&] {
        for (std::size_t e = 0; e < start.element; ++e) {
          read_element(first, header.elements[e], plan[e], soup, 0, path);
        }
      },
      [&] { read_records(second, header, plan, soup, records_before, path); });
  return second.leftover_bytes();
}

}  // namespace

Soup parse_ply(std::string_view bytes, const fs::path& path, LoadReport& report,
               std::size_t split_near) {
  const PlyHeader header = parse_ply_header(bytes, bytes.size(), path);
  const std::string_view body_bytes = bytes.substr(header.body_offset);
  const bool ascii = header.encoding == PlyEncoding::Ascii;
  if (ascii) require_text(body_bytes, path, "ASCII PLY");
  Soup soup;
  const std::vector<ElementColumns> plan = plan_attributes(header, soup, report);
  std::string leftover;
  const std::size_t split = split_near > header.body_offset
                                ? line_start_after(body_bytes, split_near - header.body_offset)
                                : body_bytes.size();
  const auto face_start = ascii || split_near >= bytes.size()
                              ? std::nullopt
                              : binary_face_start(header, body_bytes.size());
  if (ascii && split < body_bytes.size()) {
    const std::size_t lines = read_ascii_in_two_parts(body_bytes, split, header, plan, soup, path);
    if (lines) leftover = std::to_string(lines) + " lines";
  } else if (face_start) {
    leftover = read_binary_in_two_parts(body_bytes, *face_start, header, plan, soup, path);
  } else {
    PlyBody body(body_bytes, header, path);
    read_records(body, header, plan, soup, 0, path);
    if (!ascii) {
      leftover = body.leftover_bytes();
    } else if (const std::size_t lines = body.leftover_lines()) {
      leftover = std::to_string(lines) + " lines";
    }
  }
  if (!header.unknown_lines.empty()) {
    report.warnings.push_back(std::to_string(header.unknown_lines.size()) +
                              " header lines with no PLY keyword were skipped as comments (the "
                              "first is line " +
                              std::to_string(header.unknown_lines.front()) + ")");
  }
  if (!leftover.empty()) {
    report.warnings.push_back(leftover + " after the last record the header counts were ignored " +
                              "(the header's counts may be too small)");
  }
  const long long vertex_count = static_cast<long long>(soup.positions.size());
  for (std::size_t f = 0, c = 0; f < soup.face_count(); ++f) {
    for (; c < soup.face_end[f]; ++c) {
      if (soup.corners[c] >= vertex_count) {
        fail(path, "face " + std::to_string(f) + " refers to vertex " +
                       std::to_string(soup.corners[c]) + ", but the file has " +
                       std::to_string(vertex_count) + " vertices (numbered from 0)");
      }
    }
  }
  return soup;
}

Soup parse_ply(std::string_view bytes, const fs::path& path, LoadReport& report) {
  return parse_ply(bytes, path, report,
                   bytes.size() >= kTwoPartsFrom ? bytes.size() / 2 : std::string_view::npos);
}

}  // namespace holefill::io
