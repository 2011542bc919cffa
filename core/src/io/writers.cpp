#include "writers.h"

#include <charconv>

namespace holefill::io {
namespace {

void append_number(std::string& out, double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  out.append(text, end);
}

void append_number(std::string& out, long long value) {
  char text[24];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  out.append(text, end);
}

// Writes vertices as "<prefix>x y z" and faces as "<face_prefix>a b c" with indices from `base`.
void append_lists(const Mesh& mesh, std::string& out, const char* vertex_prefix,
                  const char* face_prefix, int base) {
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    out += vertex_prefix;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis) out += ' ';
      append_number(out, p[axis]);
    }
    out += '\n';
  }
  for (const auto f : mesh.faces()) {
    out += face_prefix;
    const char* separator = "";
    for (const auto v : mesh.fv_range(f)) {
      out += separator;
      append_number(out, static_cast<long long>(v.idx()) + base);
      separator = " ";
    }
    out += '\n';
  }
}

}  // namespace

std::string mesh_file_bytes(const Mesh& mesh, const std::string& ext) {
  std::string out;
  out.reserve(mesh.n_vertices() * 64 + mesh.n_faces() * 24 + 256);
  if (ext == ".obj") {
    out += "# written by holefill\n";
    append_lists(mesh, out, "v ", "f ", 1);
  } else if (ext == ".off") {
    out +=
        "OFF\n" + std::to_string(mesh.n_vertices()) + ' ' + std::to_string(mesh.n_faces()) + " 0\n";
    append_lists(mesh, out, "", "3 ", 0);
  } else {
    out += "ply\nformat ascii 1.0\ncomment written by holefill\nelement vertex " +
           std::to_string(mesh.n_vertices()) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
           std::to_string(mesh.n_faces()) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
    append_lists(mesh, out, "", "3 ", 0);
  }
  return out;
}

}  // namespace holefill::io
