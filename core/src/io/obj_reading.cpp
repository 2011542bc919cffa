// The statements made of numbers (v, vt, vn, f) and smoothing groups (s), read into the soup
// (obj_reader.cpp says why here rather than by tinyobjloader), and the checks at the end.
#include "obj_reading.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "huge_pages.h"
#include "mesh_from_triangles.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

// One element's kind, for messages: "vertex", "texture coordinate", "normal".
struct ObjIndexKind {
  const char* name;
  const char* plural;
  const char* syntax_error;  // what a corner is not when its number cannot be read
};

// How many of a face's corners have a texture coordinate, a normal.
struct ObjReading::CornerCounts {
  std::size_t texcoords = 0, normals = 0;
};

namespace {

constexpr ObjIndexKind kVertexIndex{"vertex", "vertices", "is not a vertex index"};
constexpr ObjIndexKind kTexcoordIndex{"texture coordinate", "texture coordinates",
                                      "has no valid texture coordinate index"};
constexpr ObjIndexKind kNormalIndex{"normal", "normals", "has no valid normal index"};

std::string_view trimmed(std::string_view text) {
  skip_blanks(text);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

// A corner "v", "v/vt", "v//vn", "v/vt/vn" (or "v/", "v//", "v/vt/") at the start of `text`,
// up to a blank or the end: its indices as written, 0 where not given (0 is never valid).
struct PlainCorner {
  long long index[3] = {0, 0, 0};  // vertex, texture coordinate, normal
};

// Reads such a corner and removes it from `text`; false when `text` does not start with one.
// Split as read_corners splits a corner: the vertex before the first slash, the texture
// coordinate up to the second.
bool take_plain_corner(std::string_view& text, PlainCorner& corner) {
  if (!take_integer_prefix(text, corner.index[0]) || corner.index[0] == 0) return false;
  for (int part = 1; part < 3 && !at_token_end(text); ++part) {
    if (text.front() != '/') return false;
    text.remove_prefix(1);
    if (at_token_end(text) || text.front() == '/') continue;  // this part is left out
    if (!take_integer_prefix(text, corner.index[part]) || corner.index[part] == 0) return false;
  }
  return at_token_end(text);
}

}  // namespace

void CornerColumn::push_other(std::size_t corner, long long index, bool relative) {
  if (values_.size() < corner) values_.resize(corner, 0);
  if (relative) relative_.push_back(values_.size());
  const long long value = index + base_;
  if (value >= kBeyond && beyond_corner_ == kNone) {
    beyond_corner_ = values_.size();
    beyond_index_ = index;
  }
  values_.push_back(value < kBeyond ? static_cast<int>(value) : kBeyond);
}

bool CornerColumn::within(std::size_t defined) const {
  int most = 0;
  for (const int value : values_) most = std::max(most, value);
  return static_cast<long long>(most) - base_ < static_cast<long long>(defined);
}

void CornerColumn::clear_from(std::size_t corner) {
  if (values_.size() > corner) {
    std::fill(values_.begin() + static_cast<std::ptrdiff_t>(corner), values_.end(), 0);
  }
  forget_from(corner);
}

bool CornerColumn::relative_reach(std::size_t before) const {
  return std::all_of(relative_.begin(), relative_.end(), [&](std::size_t c) {
    return static_cast<long long>(values_[c]) - base_ + static_cast<long long>(before) >= 0;
  });
}

void CornerColumn::append(CornerColumn& later, std::size_t own, std::size_t corners,
                          std::size_t before) {
  if (values_.empty() && later.values_.empty()) return;
  values_.resize(own, 0);
  append_and_free(values_, later.values_);
  values_.resize(own + corners, 0);
  for (const std::size_t c : later.relative_) {
    values_[own + c] = static_cast<int>(values_[own + c] + static_cast<long long>(before));
  }
  if (beyond_corner_ == kNone && later.beyond_corner_ != kNone) {
    beyond_corner_ = own + later.beyond_corner_;
    beyond_index_ = later.beyond_index_;
  }
}

int ObjReading::FaceNames::number(std::string_view name) {
  const auto [found, added] = numbers.try_emplace(std::string(name), 0);
  if (added) {
    names.emplace_back(name);
    found->second = static_cast<int>(names.size());
  }
  return found->second;
}

ObjReading::ObjReading(const fs::path& path, bool detached) : path_(path), detached_(detached) {
  if (!detached) return;
  for (FaceNames* names : {&material_, &group_, &object_, &smoothing_}) {
    names->initial = names->current = kInherited;
  }
}

void ObjReading::reserve(const ObjCounts& counts) {
  reserve_positions(soup_.positions, counts.vertices, !detached_);
  reserve_on_huge_pages(soup_.obj.texcoords, counts.texcoords);
  reserve_on_huge_pages(soup_.obj.normals, counts.normals);
  reserve_on_huge_pages(soup_.corners, counts.corners);
  if (counts.slashed_corners) {
    reserve_on_huge_pages(soup_.corner_texcoord, counts.corners);
    reserve_on_huge_pages(soup_.corner_normal, counts.corners);
  }
  reserve_on_huge_pages(soup_.face_end, counts.faces);
}

void ObjReading::fail_here(const std::string& reason) const {
  fail(path_, at_line(statements_->line()) + reason);
}

void ObjReading::read_statement(DirectStatement kind) {
  switch (kind) {
    case DirectStatement::Vertex:
      return read_vertex();
    case DirectStatement::Texcoord:
      return read_texcoord();
    case DirectStatement::Normal:
      return read_normal();
    case DirectStatement::Face:
      return read_face();
    case DirectStatement::Smoothing:
      return read_smoothing_group();
  }
}

void ObjReading::use_material(std::string_view name) { material_.set(trimmed(name)); }

void ObjReading::set_group(std::string_view names) {
  group_.set(names.empty() ? "default" : names);
}

void ObjReading::set_object(std::string_view name) { object_.set(trimmed(name)); }

// "s 1", "s off", "s 0": kept as written (a number, any size, or off) for the faces that follow.
void ObjReading::read_smoothing_group() { smoothing_.set(trimmed(statements_->arguments())); }

void ObjReading::add_material_library(const fs::path& file) {
  auto& files = soup_.obj.material_libraries;
  if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
}

int ObjReading::read_numbers(double* values, int least, int most, const char* what) const {
  std::string_view rest = statements_->arguments();
  int count = 0;
  for (; count < most; ++count) {
    std::string_view unread = rest;
    if (take_double(rest, values[count])) continue;
    if (count >= least) break;
    const std::string_view token = take_token(unread);
    fail_here(std::string(what) + " needs " + std::to_string(least) + " numbers" +
              (token.empty() ? std::string() : ", got " + quoted(token)));
  }
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) fail_here(std::string(what) + " has a non-finite value");
  }
  return count;
}

void ObjReading::read_vertex() {
  double xyz[3];
  std::string_view rest = statements_->arguments();
  for (double& value : xyz) {
    std::string_view unread = rest;
    if (!take_double(rest, value)) {
      const std::string_view token = take_token(unread);
      fail_here("vertex needs 3 numbers" +
                (token.empty() ? std::string() : ", got " + quoted(token)));
    }
  }
  if (static_cast<long long>(soup_.positions.size()) >= kMaxVertices) {
    fail_here("more vertices than holefill supports");
  }
  const Point p(xyz[0], xyz[1], xyz[2]);
  require_finite(p, soup_.positions.size() + 1, statements_->line(), path_);
  soup_.positions.push_back(p);
  read_vertex_colour(rest);
}

// The common "v x y z r g b" extension: colours in [0, 1] as vertex attributes, from the first
// vertex that has them (vertices without get 0).
void ObjReading::read_vertex_colour(std::string_view rest) {
  double rgb[3];
  for (double& channel : rgb) {
    if (!take_double(rest, channel)) return;
  }
  if (soup_.layout.vertex.empty()) {
    for (const char* name : {"red", "green", "blue"}) soup_.layout.vertex.push_back({name});
    soup_.vertex_values.resize(3);
    for (auto& column : soup_.vertex_values) column.reserve(soup_.positions.capacity());
  }
  for (int c = 0; c < 3; ++c) {
    soup_.vertex_values[c].resize(soup_.positions.size() - 1, 0.0);
    soup_.vertex_values[c].push_back(rgb[c]);
  }
}

void ObjReading::read_texcoord() {
  std::array<double, 3> uvw{0.0, 0.0, 0.0};
  const int count = read_numbers(uvw.data(), 1, 3, "texture coordinate");
  soup_.obj.texcoord_size =
      soup_.obj.texcoords.empty() ? count : std::max(soup_.obj.texcoord_size, count);
  soup_.obj.texcoords.push_back(uvw);
}

void ObjReading::read_normal() {
  double xyz[3];
  read_numbers(xyz, 3, 3, "normal");
  soup_.obj.normals.emplace_back(xyz[0], xyz[1], xyz[2]);
}

long long ObjReading::read_index(std::string_view text, std::string_view corner,
                                 std::size_t defined, const ObjIndexKind& kind) const {
  long long index = 0;
  if (!parse_integer(text, index)) {
    fail_here("face corner " + quoted(corner) + " " + kind.syntax_error);
  }
  return resolve_index(index, defined, kind);
}

long long ObjReading::resolve_other_index(long long index, std::size_t defined,
                                          const ObjIndexKind& kind) const {
  if (index == 0) fail_here(std::string(kind.name) + " index 0 (OBJ counts from 1)");
  // Relative: -1 is the last element defined so far.
  if (index < -static_cast<long long>(defined) && !detached_) {
    fail_here(std::string("relative ") + kind.name + " index " + std::to_string(index) +
              " reaches before the first " + kind.name);
  }
  return index + static_cast<long long>(defined);
}

void ObjReading::push_corner(const long long* written, const long long* resolved) {
  const std::size_t corner = soup_.corners.size();
  vertex_.push(corner, resolved[0], detached_ && written[0] < 0);
  if (written[1]) {
    texcoord_.push(corner, resolved[1], detached_ && written[1] < 0);
  } else {
    texcoord_.push_none();
  }
  if (written[2]) {
    normal_.push(corner, resolved[2], detached_ && written[2] < 0);
  } else {
    normal_.push_none();
  }
}

bool ObjReading::read_plain_corners(std::string_view rest, CornerCounts& given) {
  for (skip_blanks(rest); !rest.empty(); skip_blanks(rest)) {
    PlainCorner corner;
    if (!take_plain_corner(rest, corner)) return false;
    const long long* index = corner.index;
    // Resolved in read_index's order, so that a bad index fails as there.
    const long long resolved[3] = {
        resolve_index(index[0], soup_.positions.size(), kVertexIndex),
        index[1] ? resolve_index(index[1], soup_.obj.texcoords.size(), kTexcoordIndex) : 0,
        index[2] ? resolve_index(index[2], soup_.obj.normals.size(), kNormalIndex) : 0};
    push_corner(index, resolved);
    given.texcoords += index[1] ? 1 : 0;
    given.normals += index[2] ? 1 : 0;
  }
  return true;
}

void ObjReading::read_corners(std::string_view rest, CornerCounts& given) {
  for (std::string_view corner = take_token(rest); !corner.empty(); corner = take_token(rest)) {
    // "v", "v/vt", "v//vn" or "v/vt/vn".
    const std::size_t slash = corner.find('/');
    const std::string_view after =
        slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
    const std::size_t second = after.find('/');
    const std::string_view parts[3] = {
        corner.substr(0, slash), after.substr(0, second),
        second == std::string_view::npos ? std::string_view() : after.substr(second + 1)};
    const std::size_t defined[3] = {soup_.positions.size(), soup_.obj.texcoords.size(),
                                    soup_.obj.normals.size()};
    const ObjIndexKind* kinds[3] = {&kVertexIndex, &kTexcoordIndex, &kNormalIndex};
    long long written[3] = {0, 0, 0}, resolved[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      if (k > 0 && parts[k].empty()) continue;
      resolved[k] = read_index(parts[k], corner, defined[k], *kinds[k]);
      parse_integer(parts[k], written[k]);
    }
    push_corner(written, resolved);
    given.texcoords += written[1] ? 1 : 0;
    given.normals += written[2] ? 1 : 0;
  }
}

void ObjReading::read_face() {
  const std::size_t first = soup_.corners.size();
  CornerCounts given;
  if (!read_plain_corners(statements_->arguments(), given)) {
    // Read again from the first corner, the way that names what is wrong.
    for (auto* column : {&vertex_, &texcoord_, &normal_}) column->truncate(first);
    given = CornerCounts();
    read_corners(statements_->arguments(), given);
  }
  const std::size_t corners = soup_.corners.size() - first;
  // A face gives every corner a texture coordinate (a normal), or none.
  auto all_or_none = [&](CornerColumn& column, std::size_t given, std::size_t& partial) {
    if (given == 0 || given == corners) return given != 0;
    column.clear_from(first);
    ++partial;
    return false;
  };
  any_texcoord_ = all_or_none(texcoord_, given.texcoords, partial_texcoords_) || any_texcoord_;
  any_normal_ = all_or_none(normal_, given.normals, partial_normals_) || any_normal_;
  const std::size_t face = soup_.face_count();
  soup_.end_face(soup_.corners.size(), statements_->line());
  const std::size_t room = soup_.face_end.capacity();
  material_.give(face, room);
  group_.give(face, room);
  object_.give(face, room);
  smoothing_.give(face, room);
}

void ObjReading::check_indices(const CornerColumn& column, std::size_t defined,
                               const ObjIndexKind& kind) const {
  if (column.within(defined)) return;
  for (std::size_t f = 0, c = 0; f < soup_.face_count(); ++f) {
    for (; c < soup_.face_end[f]; ++c) {
      if (!column.beyond(c, defined)) continue;
      fail(path_, at_line(soup_.face_line.line(f)) + "face refers to " + kind.name + " " +
                      std::to_string(column.index(c) + 1) + ", but the file has " +
                      std::to_string(defined) + " " + kind.plural);
    }
  }
}

Soup ObjReading::finish(LoadReport& report) {
  const std::size_t faces = soup_.face_count();
  for (FaceNames* names : {&material_, &group_, &object_, &smoothing_}) {
    if (!names->faces.empty()) names->faces.resize(faces, 0);
  }
  check_indices(vertex_, soup_.positions.size(), kVertexIndex);
  // A column no face gave to all its corners is dropped.
  auto keep = [&](CornerColumn& column, bool any, std::size_t defined, const ObjIndexKind& kind) {
    if (!any) {
      std::vector<int>().swap(column.values());
      return;
    }
    column.values().resize(soup_.corners.size(), 0);
    check_indices(column, defined, kind);
  };
  keep(texcoord_, any_texcoord_, soup_.obj.texcoords.size(), kTexcoordIndex);
  keep(normal_, any_normal_, soup_.obj.normals.size(), kNormalIndex);
  soup_.obj.file_texcoords = soup_.obj.texcoords.size();
  soup_.obj.file_normals = soup_.obj.normals.size();
  for (auto& column : soup_.vertex_values) column.resize(soup_.positions.size(), 0.0);
  report.elements_ignored += elements_ignored_;
  report.degenerate_faces_dropped += empty_faces_;
  if (!not_kept_.empty()) {
    std::string kinds;
    for (const auto& [keyword, count] : not_kept_) {
      kinds +=
          (kinds.empty() ? "" : ", ") + io::quoted(keyword) + " (" + std::to_string(count) + ")";
    }
    report.warnings.push_back("statements holefill does not keep were dropped: " + kinds);
  }
  auto warn = [&](std::size_t count, const char* what) {
    if (count)
      report.warnings.push_back(std::to_string(count) + " faces gave " + what +
                                " to some of their corners only; those were dropped");
  };
  warn(partial_texcoords_, "texture coordinates");
  warn(partial_normals_, "normals");
  return std::move(soup_);
}

}  // namespace holefill::io
