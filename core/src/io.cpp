#include "holefill/io.h"

#include <tiny_obj_loader.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "holefill/errors.h"

namespace holefill {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void check_readable_file(const fs::path& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!fs::exists(status)) throw FileError(path, "no such file");
  if (fs::is_directory(status)) throw FileError(path, "is a directory, not a mesh file");
  if (!fs::is_regular_file(status)) throw FileError(path, "is not a regular file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw FileError(path, "cannot be opened for reading (permissions?)");
  if (probe.peek() == std::ifstream::traits_type::eof()) throw FileError(path, "is empty");
}

// Adds one triangle; a triangle that OpenMesh refuses (it would make an edge non-manifold or
// join two fans at a vertex) is kept, on its own copies of its corners, so no data is lost.
void add_triangle(Mesh& mesh, VertexHandle a, VertexHandle b, VertexHandle c, LoadReport& report) {
  if (a == b || b == c || c == a) {
    ++report.degenerate_faces_dropped;
    return;
  }
  if (mesh.add_face(a, b, c).is_valid()) return;
  ++report.faces_detached;
  const Point pa = mesh.point(a), pb = mesh.point(b), pc = mesh.point(c);
  mesh.add_face(mesh.add_vertex(pa), mesh.add_vertex(pb), mesh.add_vertex(pc));
}

// The OBJ file's vertex positions, parsed with strtod (correctly rounded, unlike
// tinyobjloader's own parser), so a coordinate written with 17 digits reads back bit for bit.
std::vector<Point> read_obj_positions(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<Point> positions;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 2, "v ") != 0) {
      if (start == std::string::npos || line.compare(start, 2, "v\t") != 0) continue;
    }
    const char* cursor = line.c_str() + start + 2;
    Point p;
    for (int axis = 0; axis < 3; ++axis) {
      char* end = nullptr;
      p[axis] = std::strtod(cursor, &end);
      if (end == cursor) {
        throw FileError(path, "line " + std::to_string(line_number) + ": vertex needs 3 numbers");
      }
      if (!std::isfinite(p[axis])) {
        throw InvalidMeshError(path, "line " + std::to_string(line_number) + ": vertex " +
                                         std::to_string(positions.size() + 1) +
                                         " has a non-finite (NaN or infinite) coordinate");
      }
      cursor = end;
    }
    positions.push_back(p);
  }
  return positions;
}

Mesh load_obj(const fs::path& path, LoadReport& report) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // we triangulate ourselves, to count and to keep vertex indices
  config.vertex_color = false;
  config.mtl_search_path = "";
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path.string(), config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw FileError(path, "not a readable OBJ file" + (why.empty() ? "" : " (" + why + ")"));
  }
  const std::vector<Point> positions = read_obj_positions(path);
  const std::size_t vertex_count = positions.size();
  if (vertex_count != reader.GetAttrib().vertices.size() / 3) {
    throw FileError(path, "vertex lines could not be read consistently");
  }
  Mesh mesh;
  mesh.reserve(vertex_count, vertex_count * 3, vertex_count * 2);
  for (const auto& p : positions) mesh.add_vertex(p);
  for (const auto& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (const auto corner_count : shape.mesh.num_face_vertices) {
      std::vector<VertexHandle> corners;
      for (std::size_t c = 0; c < corner_count; ++c) {
        const int index = shape.mesh.indices[offset + c].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= vertex_count) {
          throw FileError(path, "face refers to vertex " + std::to_string(index + 1) + " of " +
                                    std::to_string(vertex_count));
        }
        corners.emplace_back(index);
      }
      offset += corner_count;
      if (corners.size() < 3) {
        ++report.degenerate_faces_dropped;
        continue;
      }
      if (corners.size() > 3) ++report.polygons_triangulated;
      for (std::size_t c = 1; c + 1 < corners.size(); ++c) {
        add_triangle(mesh, corners[0], corners[c], corners[c + 1], report);
      }
    }
  }
  return mesh;
}

Mesh load_with_openmesh(const fs::path& path) {
  // OpenMesh reports problems on its own streams; ours go through FileError and LoadReport.
  omerr().disable();
  omlog().disable();
  Mesh mesh;
  OpenMesh::IO::Options options;
  bool ok = false;
  try {
    ok = OpenMesh::IO::read_mesh(mesh, path.string(), options);
  } catch (const std::exception& e) {
    throw FileError(path, std::string("could not be read (") + e.what() + ")");
  }
  if (!ok) throw FileError(path, "not a readable " + lower_extension(path).substr(1) + " file");
  return mesh;
}

void validate(const Mesh& mesh, const fs::path& path) {
  if (mesh.n_faces() == 0) throw InvalidMeshError(path, "contains no faces");
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      throw InvalidMeshError(path, "vertex " + std::to_string(v.idx() + 1) +
                                       " has a non-finite (NaN or infinite) coordinate");
    }
  }
}

// Writes vertices as "<prefix>x y z" and faces as "<face_prefix>a b c" with indices from `base`.
void write_lists(const Mesh& mesh, std::ostream& out, const char* vertex_prefix,
                 const char* face_prefix, int base) {
  char line[128];
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    std::snprintf(line, sizeof line, "%s%.17g %.17g %.17g\n", vertex_prefix, p[0], p[1], p[2]);
    out << line;
  }
  for (const auto f : mesh.faces()) {
    out << face_prefix;
    const char* separator = "";
    for (const auto v : mesh.fv_range(f)) {
      out << separator << v.idx() + base;
      separator = " ";
    }
    out << '\n';
  }
}

// OpenMesh's OFF and PLY writers store single precision; ours keep every bit of a double.
void write_mesh_text(const Mesh& mesh, const std::string& ext, std::ostream& out) {
  if (ext == ".obj") {
    out << "# written by holefill\n";
    write_lists(mesh, out, "v ", "f ", 1);
  } else if (ext == ".off") {
    out << "OFF\n" << mesh.n_vertices() << ' ' << mesh.n_faces() << " 0\n";
    write_lists(mesh, out, "", "3 ", 0);
  } else {
    out << "ply\nformat ascii 1.0\ncomment written by holefill\nelement vertex "
        << mesh.n_vertices()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
        << mesh.n_faces() << "\nproperty list uchar int vertex_indices\nend_header\n";
    write_lists(mesh, out, "", "3 ", 0);
  }
}

}  // namespace

const std::vector<std::string>& readable_extensions() {
  static const std::vector<std::string> extensions{".obj", ".off", ".ply", ".stl"};
  return extensions;
}

const std::vector<std::string>& writable_extensions() {
  static const std::vector<std::string> extensions{".obj", ".off", ".ply"};
  return extensions;
}

Mesh load_mesh(const fs::path& path, LoadReport* report) {
  LoadReport local;
  LoadReport& out = report ? *report : local;
  out = LoadReport{};
  check_readable_file(path);
  const std::string ext = lower_extension(path);
  const auto& readable = readable_extensions();
  if (std::find(readable.begin(), readable.end(), ext) == readable.end()) {
    throw FileError(path, "unsupported file type '" + ext + "' (use .obj, .off, .ply or .stl)");
  }
  Mesh mesh = ext == ".obj" ? load_obj(path, out) : load_with_openmesh(path);
  validate(mesh, path);
  if (out.polygons_triangulated) {
    out.warnings.push_back(std::to_string(out.polygons_triangulated) +
                           " polygons with more than 3 corners were triangulated");
  }
  if (out.degenerate_faces_dropped) {
    out.warnings.push_back(std::to_string(out.degenerate_faces_dropped) +
                           " degenerate faces (a vertex used twice) were dropped");
  }
  if (out.faces_detached) {
    out.warnings.push_back(std::to_string(out.faces_detached) +
                           " non-manifold faces were kept on their own copies of their vertices");
  }
  return mesh;
}

void save_mesh(const Mesh& mesh, const fs::path& path) {
  const std::string ext = lower_extension(path);
  const auto& writable = writable_extensions();
  if (std::find(writable.begin(), writable.end(), ext) == writable.end()) {
    throw FileError(path, "cannot write '" + ext + "' files (use .obj, .off or .ply)");
  }
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw FileError(path, "folder does not exist");
  std::random_device seed;
  const fs::path temp =
      dir / ("." + path.stem().string() + ".partial-" + std::to_string(seed()) + ext);
  bool written = false;
  {
    std::ofstream out(temp, std::ios::binary);
    if (out) {
      write_mesh_text(mesh, ext, out);
      out.flush();
      written = static_cast<bool>(out);
    }
  }
  if (!written) {
    fs::remove(temp, ec);
    throw FileError(path, "could not be written");
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw FileError(path, "could not be written (" + ec.message() + ")");
  }
}

}  // namespace holefill
