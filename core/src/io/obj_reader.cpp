// OBJ through tinyobjloader (Debian's libtinyobjloader, its double build): its callback API walks
// the statements and gives the names of materials (usemtl), groups (g) and objects (o) and the
// files of mtllib. Its numbers are not used: the statements made of numbers (v, vt, vn, f) are
// read here instead, exactly where tinyobjloader would have called back for them, and so are
// smoothing groups (s), which it does not report (ObjStatements serves one statement at a time,
// hands those over, and knows which one is read):
// - coordinates, colours, texture coordinates and normals with std::from_chars, because
//   tinyobjloader's parser is not correctly rounded (60-68 % of 17-digit coordinates come back
//   1-8 ulp off) and original vertices keep their values bit for bit;
// - face corners with a strict integer parse, because tinyobjloader's atoi reads letters as 0
//   and overflows silently; index 0, relative indices before the first element and indices past
//   the last are refused, naming the line, as are non-finite numbers and short statements.
// Continued lines and comments are resolved by ObjStatements (tinyobjloader knows neither). The
// .mtl files are not read: the mesh keeps their paths, and the output refers to them.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <istream>
#include <unordered_map>

#include "obj_statements.h"
#include "readers.h"

namespace holefill::io {
namespace fs = std::filesystem;
namespace {

std::string_view trimmed(std::string_view text) {
  skip_blanks(text);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

// The number (1-based) of `name` in `names`, added at the end when new.
int number_of(std::string_view name, std::vector<std::string>& names,
              std::unordered_map<std::string, int>& numbers) {
  const auto [found, added] = numbers.try_emplace(std::string(name), 0);
  if (added) {
    names.emplace_back(name);
    found->second = static_cast<int>(names.size());
  }
  return found->second;
}

// Sets values[index] (0 beyond the values set so far, which stay empty until one is not 0).
void set_sparse(std::vector<int>& values, std::size_t index, int value) {
  if (value == 0 && values.empty()) return;
  values.resize(index, 0);
  values.push_back(value);
}

// Records the files mtllib names (tinyobjloader splits the statement) without reading them.
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  explicit MaterialLibraries(fs::path folder) : folder_(std::move(folder)) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>*,
                  std::map<std::string, int>*, std::string*, std::string*) override {
    if (name.empty()) return false;
    std::error_code error;
    fs::path file = fs::weakly_canonical(folder_ / name, error);
    if (error) file = (folder_ / name).lexically_normal();
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
    return false;  // nothing read: tinyobjloader goes on to the statement's next file
  }
  std::vector<fs::path> files;

 private:
  fs::path folder_;
};

// One element's kind, for messages: "vertex", "texture coordinate", "normal".
struct IndexKind {
  const char* name;
  const char* plural;
  const char* syntax_error;  // what a corner is not when its number cannot be read
};
constexpr IndexKind kVertexIndex{"vertex", "vertices", "is not a vertex index"};
constexpr IndexKind kTexcoordIndex{"texture coordinate", "texture coordinates",
                                   "has no valid texture coordinate index"};
constexpr IndexKind kNormalIndex{"normal", "normals", "has no valid normal index"};

// How many of a face's corners have a texture coordinate, a normal.
struct CornerCounts {
  std::size_t texcoords = 0, normals = 0;
};

// A corner "v", "v/vt", "v//vn", "v/vt/vn" (or "v/", "v//", "v/vt/") at the start of `text`,
// up to a blank or the end.
struct PlainCorner {
  long long index[3] = {0, 0, 0};  // vertex, texture coordinate, normal
  bool given[3] = {true, false, false};
};

// Reads such a corner and removes it from `text`; false when `text` does not start with one.
// Split as read_face splits a corner: the vertex before the first slash, the texture coordinate
// up to the second.
bool take_plain_corner(std::string_view& text, PlainCorner& corner) {
  if (!take_integer_prefix(text, corner.index[0])) return false;
  for (int part = 1; part < 3 && !at_token_end(text); ++part) {
    if (text.front() != '/') return false;
    text.remove_prefix(1);
    if (at_token_end(text) || text.front() == '/') continue;  // this part is left out
    if (!take_integer_prefix(text, corner.index[part])) return false;
    corner.given[part] = true;
  }
  return at_token_end(text);
}

class ObjReading {
 public:
  ObjReading(const ObjStatements& statements, const fs::path& path)
      : statements_(statements), path_(path) {}

  void read_vertex();
  void read_texcoord();
  void read_normal();
  void read_face();
  void use_material(std::string_view name) {
    material_ = number_of(trimmed(name), soup.obj.materials, material_numbers_);
  }
  void set_group(std::string_view names) {
    group_ = number_of(names.empty() ? "default" : names, soup.obj.groups, group_numbers_);
  }
  void set_object(std::string_view name) {
    object_ = number_of(trimmed(name), soup.obj.objects, object_numbers_);
  }
  // "s 1", "s off", "s 0": kept as written (a number, any size, or off) for the faces that follow.
  void read_smoothing_group() {
    smoothing_ =
        number_of(trimmed(statements_.arguments()), soup.obj.smoothing_groups, smoothing_numbers_);
  }
  // Checks the indices against what the file defines and moves them into the soup.
  void finish(LoadReport& report);

  Soup soup;

 private:
  [[noreturn]] void fail_here(const std::string& reason) const {
    fail(path_, at_line(statements_.line()) + reason);
  }
  // The statement's numbers after its keyword, at most `most`; refuses a missing or bad one
  // among the first `least`, and non-finite ones.
  int read_numbers(double* values, int least, int most, const char* what) const;
  long long read_index(std::string_view text, std::string_view corner, std::size_t defined,
                       const IndexKind& kind) const;
  // A read index's 0-based value; refuses 0 and relative indices before the first element.
  long long resolve_index(long long index, std::size_t defined, const IndexKind& kind) const;
  // A face's corners, pushed onto vertex_, texcoord_ and normal_.
  void read_corners(std::string_view rest, CornerCounts& given);
  // The same for the usual corners, read in place; false (some corners pushed) at the first
  // that is not one (then read_corners tells what is wrong with it).
  bool read_plain_corners(std::string_view rest, CornerCounts& given);
  void read_vertex_colour(std::string_view rest);
  void check_indices(const std::vector<long long>& indices, std::size_t defined,
                     const IndexKind& kind) const;

  const ObjStatements& statements_;
  const fs::path& path_;
  // 0-based indices by corner, checked against the counts at the end (a face may refer ahead);
  // -1: the corner has no texture coordinate or normal.
  std::vector<long long> vertex_, texcoord_, normal_;
  bool any_texcoord_ = false, any_normal_ = false;
  std::size_t partial_texcoords_ = 0, partial_normals_ = 0;  // faces with some corners only
  int material_ = 0, group_ = 0, object_ = 0, smoothing_ = 0;
  std::unordered_map<std::string, int> material_numbers_, group_numbers_, object_numbers_,
      smoothing_numbers_;
};

int ObjReading::read_numbers(double* values, int least, int most, const char* what) const {
  std::string_view rest = statements_.arguments();
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
  std::string_view rest = statements_.arguments();
  for (double& value : xyz) {
    std::string_view unread = rest;
    if (!take_double(rest, value)) {
      const std::string_view token = take_token(unread);
      fail_here("vertex needs 3 numbers" +
                (token.empty() ? std::string() : ", got " + quoted(token)));
    }
  }
  if (static_cast<long long>(soup.positions.size()) >= kMaxVertices) {
    fail_here("more vertices than holefill supports");
  }
  const Point p(xyz[0], xyz[1], xyz[2]);
  require_finite(p, soup.positions.size() + 1, statements_.line(), path_);
  soup.positions.push_back(p);
  read_vertex_colour(rest);
}

// The common "v x y z r g b" extension: colours in [0, 1] as vertex attributes, from the first
// vertex that has them (vertices without get 0).
void ObjReading::read_vertex_colour(std::string_view rest) {
  double rgb[3];
  for (double& channel : rgb) {
    if (!take_double(rest, channel)) return;
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

void ObjReading::read_texcoord() {
  std::array<double, 3> uvw{0.0, 0.0, 0.0};
  const int count = read_numbers(uvw.data(), 1, 3, "texture coordinate");
  soup.obj.texcoord_size =
      soup.obj.texcoords.empty() ? count : std::max(soup.obj.texcoord_size, count);
  soup.obj.texcoords.push_back(uvw);
}

void ObjReading::read_normal() {
  double xyz[3];
  read_numbers(xyz, 3, 3, "normal");
  soup.obj.normals.emplace_back(xyz[0], xyz[1], xyz[2]);
}

long long ObjReading::read_index(std::string_view text, std::string_view corner,
                                 std::size_t defined, const IndexKind& kind) const {
  long long index = 0;
  if (!parse_integer(text, index)) {
    fail_here("face corner " + quoted(corner) + " " + kind.syntax_error);
  }
  return resolve_index(index, defined, kind);
}

long long ObjReading::resolve_index(long long index, std::size_t defined,
                                    const IndexKind& kind) const {
  if (index == 0) fail_here(std::string(kind.name) + " index 0 (OBJ counts from 1)");
  if (index > 0) return index - 1;
  // Relative: -1 is the last element defined so far.
  if (index < -static_cast<long long>(defined)) {
    fail_here(std::string("relative ") + kind.name + " index " + std::to_string(index) +
              " reaches before the first " + kind.name);
  }
  return index + static_cast<long long>(defined);
}

bool ObjReading::read_plain_corners(std::string_view rest, CornerCounts& given) {
  for (skip_blanks(rest); !rest.empty(); skip_blanks(rest)) {
    PlainCorner corner;
    if (!take_plain_corner(rest, corner)) return false;
    // Resolved in read_index's order, so that a bad index fails as there.
    vertex_.push_back(resolve_index(corner.index[0], soup.positions.size(), kVertexIndex));
    texcoord_.push_back(
        corner.given[1] ? resolve_index(corner.index[1], soup.obj.texcoords.size(), kTexcoordIndex)
                        : -1);
    normal_.push_back(corner.given[2]
                          ? resolve_index(corner.index[2], soup.obj.normals.size(), kNormalIndex)
                          : -1);
    given.texcoords += corner.given[1] ? 1 : 0;
    given.normals += corner.given[2] ? 1 : 0;
  }
  return true;
}

void ObjReading::read_corners(std::string_view rest, CornerCounts& given) {
  for (std::string_view corner = take_token(rest); !corner.empty(); corner = take_token(rest)) {
    // "v", "v/vt", "v//vn" or "v/vt/vn".
    const std::size_t slash = corner.find('/');
    vertex_.push_back(
        read_index(corner.substr(0, slash), corner, soup.positions.size(), kVertexIndex));
    const std::string_view after =
        slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
    const std::size_t second = after.find('/');
    const std::string_view vt = after.substr(0, second);
    const std::string_view vn =
        second == std::string_view::npos ? std::string_view() : after.substr(second + 1);
    texcoord_.push_back(
        vt.empty() ? -1 : read_index(vt, corner, soup.obj.texcoords.size(), kTexcoordIndex));
    normal_.push_back(vn.empty() ? -1
                                 : read_index(vn, corner, soup.obj.normals.size(), kNormalIndex));
    given.texcoords += vt.empty() ? 0 : 1;
    given.normals += vn.empty() ? 0 : 1;
  }
}

void ObjReading::read_face() {
  const std::size_t first = vertex_.size();
  CornerCounts given;
  if (!read_plain_corners(statements_.arguments(), given)) {
    // Read again from the first corner, the way that names what is wrong.
    for (auto* indices : {&vertex_, &texcoord_, &normal_}) indices->resize(first);
    given = CornerCounts();
    read_corners(statements_.arguments(), given);
  }
  const std::size_t texcoords = given.texcoords, normals = given.normals;
  const std::size_t corners = vertex_.size() - first;
  // A face gives every corner a texture coordinate (a normal), or none.
  auto all_or_none = [&](std::vector<long long>& values, std::size_t given, std::size_t& partial) {
    if (given == 0 || given == corners) return given != 0;
    std::fill(values.begin() + static_cast<std::ptrdiff_t>(first), values.end(), -1);
    ++partial;
    return false;
  };
  any_texcoord_ = all_or_none(texcoord_, texcoords, partial_texcoords_) || any_texcoord_;
  any_normal_ = all_or_none(normal_, normals, partial_normals_) || any_normal_;
  const std::size_t face = soup.face_count();
  soup.end_face(vertex_.size(), statements_.line());
  set_sparse(soup.face_material, face, material_);
  set_sparse(soup.face_group, face, group_);
  set_sparse(soup.face_object, face, object_);
  set_sparse(soup.face_smoothing, face, smoothing_);
}

void ObjReading::check_indices(const std::vector<long long>& indices, std::size_t defined,
                               const IndexKind& kind) const {
  for (std::size_t f = 0, c = 0; f < soup.face_count(); ++f) {
    for (; c < soup.face_end[f]; ++c) {
      if (indices[c] < static_cast<long long>(defined)) continue;
      fail(path_, at_line(soup.face_line[f]) + "face refers to " + kind.name + " " +
                      std::to_string(indices[c] + 1) + ", but the file has " +
                      std::to_string(defined) + " " + kind.plural);
    }
  }
}

void ObjReading::finish(LoadReport& report) {
  const std::size_t faces = soup.face_count();
  for (auto* values :
       {&soup.face_material, &soup.face_group, &soup.face_object, &soup.face_smoothing}) {
    if (!values->empty()) values->resize(faces, 0);
  }
  check_indices(vertex_, soup.positions.size(), kVertexIndex);
  soup.corners.assign(vertex_.size(), 0);
  std::transform(vertex_.begin(), vertex_.end(), soup.corners.begin(),
                 [](long long index) { return static_cast<int>(index); });
  // Texture coordinate and normal numbers count from 1, 0 for none.
  auto keep = [&](const std::vector<long long>& indices, std::size_t defined, const IndexKind& kind,
                  std::vector<int>& numbers) {
    check_indices(indices, defined, kind);
    numbers.assign(indices.size(), 0);
    std::transform(indices.begin(), indices.end(), numbers.begin(),
                   [](long long index) { return static_cast<int>(index + 1); });
  };
  if (any_texcoord_)
    keep(texcoord_, soup.obj.texcoords.size(), kTexcoordIndex, soup.corner_texcoord);
  if (any_normal_) keep(normal_, soup.obj.normals.size(), kNormalIndex, soup.corner_normal);
  soup.obj.file_texcoords = soup.obj.texcoords.size();
  soup.obj.file_normals = soup.obj.normals.size();
  for (auto& column : soup.vertex_values) column.resize(soup.positions.size(), 0.0);
  auto warn = [&](std::size_t count, const char* what) {
    if (count)
      report.warnings.push_back(std::to_string(count) + " faces gave " + what +
                                " to some of their corners only; those were dropped");
  };
  warn(partial_texcoords_, "texture coordinates");
  warn(partial_normals_, "normals");
}

}  // namespace

Soup parse_obj(std::string_view text, const fs::path& path, LoadReport& report) {
  require_text(text, path, "OBJ");
  ObjStatements statements(text);
  ObjReading reading(statements, path);
  statements.read_directly([&reading](std::string_view keyword) {
    if (keyword == "v") {
      reading.read_vertex();
    } else if (keyword == "vt") {
      reading.read_texcoord();
    } else if (keyword == "vn") {
      reading.read_normal();
    } else if (keyword == "s") {
      reading.read_smoothing_group();
    } else {
      reading.read_face();
    }
  });
  tinyobj::callback_t callbacks;
  callbacks.usemtl_cb = [](void* r, const char* name, int) {
    static_cast<ObjReading*>(r)->use_material(name);
  };
  callbacks.group_cb = [](void* r, const char** names, int count) {
    std::string joined;
    for (int i = 0; i < count; ++i) {
      if (i) joined += ' ';
      joined += names[i];
    }
    static_cast<ObjReading*>(r)->set_group(joined);
  };
  callbacks.object_cb = [](void* r, const char* name) {
    static_cast<ObjReading*>(r)->set_object(name);
  };
  std::error_code error;
  fs::path folder = fs::absolute(path, error).parent_path();
  MaterialLibraries libraries(folder);
  std::istream stream(&statements);
  tinyobj::LoadObjWithCallback(stream, callbacks, &reading, &libraries);
  statements.rethrow_failure();
  reading.soup.obj.material_libraries = libraries.files;
  report.elements_ignored += statements.elements_ignored();
  report.degenerate_faces_dropped += statements.empty_faces();
  if (!statements.not_kept().empty()) {
    std::string kinds;
    for (const auto& [keyword, count] : statements.not_kept()) {
      kinds +=
          (kinds.empty() ? "" : ", ") + io::quoted(keyword) + " (" + std::to_string(count) + ")";
    }
    report.warnings.push_back("statements holefill does not keep were dropped: " + kinds);
  }
  reading.finish(report);
  return std::move(reading.soup);
}

}  // namespace holefill::io
