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
// A big file's two halves are read on two threads, the second by a detached reading that is
// appended to the first (obj_reading.h says how that stays what one reading gives).
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <istream>

#include "obj_reading.h"
#include "readers.h"

namespace holefill::io {
namespace fs = std::filesystem;
namespace {

// Gives the files mtllib names (tinyobjloader splits the statement) to the reading without
// reading them.
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  MaterialLibraries(fs::path folder, ObjReading& reading)
      : folder_(std::move(folder)), reading_(reading) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>*,
                  std::map<std::string, int>*, std::string*, std::string*) override {
    if (name.empty()) return false;
    std::error_code error;
    fs::path file = fs::weakly_canonical(folder_ / name, error);
    if (error) file = (folder_ / name).lexically_normal();
    reading_.add_material_library(file);
    return false;  // nothing read: tinyobjloader goes on to the statement's next file
  }

 private:
  fs::path folder_;
  ObjReading& reading_;
};

// The first line boundary at or after `near` that does not cut a continued statement (a line
// ending in a backslash, which may continue); text.size() when there is none.
std::size_t split_point(std::string_view text, std::size_t near) {
  while (near < text.size()) {
    const void* found = std::memchr(text.data() + near, '\n', text.size() - near);
    if (!found) return text.size();
    std::size_t end = static_cast<std::size_t>(static_cast<const char*>(found) - text.data());
    near = end + 1;
    if (end > 0 && text[end - 1] == '\r') --end;
    if (end == 0 || text[end - 1] != '\\') return near;
  }
  return text.size();
}

}  // namespace

void ObjReading::read(std::string_view text) {
  ObjStatements statements(text, lines_);
  statements_ = &statements;
  statements.read_directly([this](DirectStatement kind) { read_statement(kind); });
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
  MaterialLibraries libraries(fs::absolute(path_, error).parent_path(), *this);
  std::istream stream(&statements);
  tinyobj::LoadObjWithCallback(stream, callbacks, this, &libraries);
  statements_ = nullptr;
  statements.rethrow_failure();
  lines_ += statements.lines_read();
  elements_ignored_ += statements.elements_ignored();
  empty_faces_ += statements.empty_faces();
  for (const auto& [keyword, count] : statements.not_kept()) not_kept_[keyword] += count;
}

void ObjReading::FaceNames::append(const FaceNames& later, std::size_t own, std::size_t count,
                                   std::size_t room) {
  std::vector<int> number_of(later.names.size() + 1, 0);  // later's numbers as this one's
  for (std::size_t k = 0; k < later.names.size(); ++k) number_of[k + 1] = number(later.names[k]);
  auto ours = [&](int value) { return value == kInherited ? current : number_of[value]; };
  // Later's faces before its first name (all of them when it kept none) have this one's current.
  const std::size_t inheriting = later.faces.empty() ? count : 0;
  const bool none = faces.empty() && (inheriting == 0 || current == 0) &&
                    std::all_of(later.faces.begin(), later.faces.end(),
                                [&](int value) { return ours(value) == 0; });
  if (!none) {
    if (faces.empty()) reserve_on_huge_pages(faces, std::max(room, own + count));
    faces.resize(own, 0);
    faces.resize(own + inheriting, current);
    for (const int value : later.faces) faces.push_back(ours(value));
  }
  current = ours(later.current);
}

bool ObjReading::append(ObjReading& second) {
  Soup& later = second.soup_;
  const std::size_t vertices = soup_.positions.size(), texcoords = soup_.obj.texcoords.size(),
                    normals = soup_.obj.normals.size();
  if (static_cast<long long>(vertices + later.positions.size()) > kMaxVertices ||
      !second.vertex_.relative_reach(vertices) || !second.texcoord_.relative_reach(texcoords) ||
      !second.normal_.relative_reach(normals)) {
    return false;
  }
  if (!later.layout.vertex.empty() && soup_.layout.vertex.empty()) {
    soup_.layout.vertex = later.layout.vertex;
    soup_.vertex_values.resize(later.vertex_values.size());
  }
  for (std::size_t c = 0; c < later.vertex_values.size(); ++c) {
    soup_.vertex_values[c].resize(vertices, 0.0);
    append_and_free(soup_.vertex_values[c], later.vertex_values[c]);
  }
  append_and_free(soup_.positions, later.positions);
  const std::size_t corners = soup_.corners.size(), faces = soup_.face_count(),
                    later_corners = later.corners.size();
  vertex_.append(second.vertex_, corners, later_corners, vertices);
  texcoord_.append(second.texcoord_, corners, later_corners, texcoords);
  normal_.append(second.normal_, corners, later_corners, normals);
  soup_.face_end.reserve(faces + later.face_count());
  for (std::size_t f = 0; f < later.face_count(); ++f) {
    soup_.face_end.push_back(corners + later.face_end[f]);
  }
  soup_.face_line.append(later.face_line, faces, later.face_count(), lines_);
  FaceNames ObjReading::*const per_face[] = {&ObjReading::material_, &ObjReading::group_,
                                             &ObjReading::object_, &ObjReading::smoothing_};
  for (const auto names : per_face) {
    (this->*names).append(second.*names, faces, later.face_count(), soup_.face_end.capacity());
  }
  ObjTables& tables = soup_.obj;
  if (!later.obj.texcoords.empty()) {
    tables.texcoord_size = tables.texcoords.empty()
                               ? later.obj.texcoord_size
                               : std::max(tables.texcoord_size, later.obj.texcoord_size);
  }
  append_and_free(tables.texcoords, later.obj.texcoords);
  append_and_free(tables.normals, later.obj.normals);
  for (const fs::path& file : later.obj.material_libraries) add_material_library(file);
  any_texcoord_ = any_texcoord_ || second.any_texcoord_;
  any_normal_ = any_normal_ || second.any_normal_;
  partial_texcoords_ += second.partial_texcoords_;
  partial_normals_ += second.partial_normals_;
  elements_ignored_ += second.elements_ignored_;
  empty_faces_ += second.empty_faces_;
  for (const auto& [keyword, count] : second.not_kept_) not_kept_[keyword] += count;
  lines_ += second.lines_;
  return true;
}

Soup parse_obj(std::string_view text, const fs::path& path, LoadReport& report,
               std::size_t split_near) {
  ObjReading reading(path, false);
  const std::size_t split = split_point(text, split_near);
  if (split >= text.size()) {
    require_text(text, path, "OBJ");
    reading.reserve(estimate_obj_counts(text));
    reading.read(text);
    return reading.finish(report);
  }
  // The second half on a thread of its own, the first here; then the second is appended, or
  // read again after the first where it could not be read alone. Each thread first looks for a
  // NUL in its half (a whole text's search, on one thread before the reading started, was the
  // first to touch a big file's pages), and a NUL anywhere is refused before what the first half's
  // reading threw, as one reading refuses it before reading.
  ObjReading second(path, true);
  std::size_t first_nul = std::string_view::npos, second_nul = std::string_view::npos;
  std::exception_ptr first_failure;
  // The first reading's arrays have the room of the whole text, where the second is appended.
  const bool second_read = read_in_two_parts(
      [&] {
        first_nul = text.substr(0, split).find('\0');
        if (first_nul != std::string_view::npos) return;
        try {
          reading.reserve(estimate_obj_counts(text));
          reading.read(text.substr(0, split));
        } catch (...) {
          first_failure = std::current_exception();
        }
      },
      [&] {
        second_nul = text.substr(split).find('\0');
        if (second_nul != std::string_view::npos) return;
        second.reserve(estimate_obj_counts(text.substr(split)));
        second.read(text.substr(split));
      });
  if (first_nul != std::string_view::npos) refuse_nul(first_nul, path, "OBJ");
  if (second_nul != std::string_view::npos) refuse_nul(split + second_nul, path, "OBJ");
  if (first_failure) std::rethrow_exception(first_failure);
  if (!second_read || !reading.append(second)) reading.read(text.substr(split));
  return reading.finish(report);
}

Soup parse_obj(std::string_view text, const fs::path& path, LoadReport& report) {
  return parse_obj(text, path, report,
                   text.size() >= kTwoPartsFrom ? text.size() / 2 : std::string_view::npos);
}

}  // namespace holefill::io
