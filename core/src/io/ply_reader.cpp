#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "mesh_from_triangles.h"
#include "ply_header.h"
#include "readers.h"
#include "text_scan.h"
#include "two_parts.h"

namespace holefill::io {
namespace fs = std::filesystem;
namespace {

// The lines of an ASCII body that one reading reads: all of them, or a part (two_parts.h).
struct BodyPart {
  std::size_t begin = 0, end = std::string_view::npos;  // bytes of the body, at line starts
  std::size_t lines_before = 0;                         // the body's lines before `begin`
  bool last = true;                                     // the part ends the body
};

// Reads the values of a PLY body record by record, ASCII (one record a line) or binary, refusing
// to read past its end or, in ASCII, past a record's line.
class PlyBody {
 public:
  PlyBody(std::string_view bytes, const PlyHeader& header, const fs::path& path,
          const BodyPart& part = {})
      : bytes_(bytes),
        lines_(bytes.substr(part.begin, part.end - std::min(part.end, part.begin))),
        encoding_(header.encoding),
        path_(path),
        line_offset_(header.header_lines + part.lines_before),
        part_begin_(part.begin),
        last_part_(part.last) {}

  // Starts record `index` of the `count` records of `element`; false when a part that does not
  // end the body has no more lines.
  bool begin_record(const std::string& element, unsigned long long index,
                    unsigned long long count) {
    element_ = &element;
    index_ = index;
    count_ = count;
    record_line_ = 0;
    if (encoding_ != PlyEncoding::Ascii) return true;
    if (!lines_.next(record_)) {
      if (!last_part_) return false;
      fail(path_, "ends before " + where() + " (truncated?)");
    }
    record_line_ = line_number();
    return true;
  }

  // Ends the record: in ASCII, its line must hold no more values.
  void end_record() {
    if (encoding_ != PlyEncoding::Ascii) return;
    skip_blanks(record_);
    if (!record_.empty()) {
      fail(path_, where() + " has more values than the header's properties give it (" +
                      quoted(record_) + " left over)");
    }
  }

  // The current record, for messages (made only when one is needed: once per record was a
  // large part of reading a big binary file).
  std::string where() const {
    return (record_line_ ? at_line(record_line_) : std::string()) + "'" + *element_ + "' element " +
           std::to_string(index_) + " of " + std::to_string(count_);
  }

  double read(PlyType type) {
    return encoding_ == PlyEncoding::Ascii ? read_text(type) : read_binary(type);
  }

  // Bytes left (to the body's end, whatever part is read); for ASCII, an upper bound on the
  // values left.
  std::size_t remaining() const {
    return encoding_ == PlyEncoding::Ascii
               ? record_.size() + 1 + bytes_.size() - part_begin_ - lines_.offset()
               : bytes_.size() - position_;
  }

  // What follows the last record, for a warning: "N bytes" (binary), or the number of lines
  // (ASCII: of this part).
  std::string leftover_bytes() const {
    return remaining() ? std::to_string(remaining()) + " bytes" : std::string();
  }
  std::size_t lines_read() const { return lines_.number(); }
  std::size_t leftover_lines() {
    std::size_t count = 0;
    for (std::string_view line; lines_.next(line);) ++count;
    return count;
  }

 private:
  std::size_t line_number() const { return line_offset_ + lines_.number(); }

  template <class T>
  static double load(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof value);
    return static_cast<double>(value);
  }

  double read_binary(PlyType type) {
    const std::size_t size = size_of(type);
    if (bytes_.size() - position_ < size) {
      fail(path_, "ends in the middle of " + where() + " (truncated?)");
    }
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, size);
    position_ += size;
    const bool swap =
        (encoding_ == PlyEncoding::BinaryBigEndian) != (std::endian::native == std::endian::big);
    if (swap) std::reverse(raw, raw + size);
    switch (type) {
      case PlyType::Int8:
        return load<std::int8_t>(raw);
      case PlyType::UInt8:
        return load<std::uint8_t>(raw);
      case PlyType::Int16:
        return load<std::int16_t>(raw);
      case PlyType::UInt16:
        return load<std::uint16_t>(raw);
      case PlyType::Int32:
        return load<std::int32_t>(raw);
      case PlyType::UInt32:
        return load<std::uint32_t>(raw);
      case PlyType::Float32:
        return load<float>(raw);
      case PlyType::Float64:
        return load<double>(raw);
    }
    return 0.0;
  }

  // Numbers are read in place (take_double, take_integer); the token is cut out only for a
  // message.
  double read_text(PlyType type) {
    const std::string_view unread = record_;
    if (is_integer_type(type)) {
      long long value = 0;
      if (!take_integer(record_, value)) refuse_text_value(unread, "expected a whole number");
      if (!fits(value, type)) {
        fail(path_,
             where() + ": " + quoted(first_token(unread)) + " does not fit the property's type");
      }
      return static_cast<double>(value);
    }
    double value = 0.0;
    if (!take_double(record_, value)) refuse_text_value(unread, "expected a number");
    // What the header says the value is: a float property holds a float, as in a binary file.
    if (type != PlyType::Float32) return value;
    if (!(std::abs(value) <= std::numeric_limits<float>::max())) {
      return std::isnan(value) ? value : std::copysign(HUGE_VAL, value);  // as a float reads
    }
    return static_cast<double>(static_cast<float>(value));
  }

  static std::string_view first_token(std::string_view text) { return take_token(text); }

  [[noreturn]] void refuse_text_value(std::string_view unread, const char* expected) const {
    const std::string_view token = first_token(unread);
    if (token.empty()) {
      fail(path_, where() + " has fewer values than the header's properties give it");
    }
    fail(path_, where() + ": " + expected + ", got " + quoted(token));
  }

  std::string_view bytes_;
  ContentLines lines_;       // ASCII: the lines of the part read
  std::string_view record_;  // ASCII: what is left of the current record's line
  PlyEncoding encoding_;
  const fs::path& path_;
  std::size_t line_offset_;
  std::size_t part_begin_;
  bool last_part_;
  std::size_t position_ = 0;              // binary: the next byte
  const std::string* element_ = nullptr;  // the current record's element, index and line
  unsigned long long index_ = 0, count_ = 0;
  std::size_t record_line_ = 0;
};

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
  if (ascii && split < body_bytes.size()) {
    const std::size_t lines = read_ascii_in_two_parts(body_bytes, split, header, plan, soup, path);
    if (lines) leftover = std::to_string(lines) + " lines";
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
