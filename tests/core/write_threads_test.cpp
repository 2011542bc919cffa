// Writing a big mesh on several threads (io.h: blocks of vertices and faces formatted apart and
// handed on in order) gives the bytes one thread gives, in every format, with the attributes
// each carries.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "holefill/io.h"
#include "holefill/obj_attributes.h"

namespace holefill {
namespace {

constexpr int kSide = 200;  // 40,401 vertices and 80,000 faces: several blocks of each

int vertex_at(int i, int j) { return j * (kSide + 1) + i; }

// A wavy grid as an OBJ with a colour per vertex, texture coordinates and normals per corner, and
// objects, groups, materials and smoothing groups changing along the faces (some runs of them
// across the blocks' borders).
std::string grid_obj() {
  std::string text = "mtllib grid.mtl\n";
  for (int j = 0; j <= kSide; ++j) {
    for (int i = 0; i <= kSide; ++i) {
      const double x = i / 64.0, y = j / 64.0;
      text += "v " + std::to_string(x) + ' ' + std::to_string(y) + ' ' +
              std::to_string(0.1 * x * y - 0.01 * (i % 3)) + ' ' + std::to_string((i % 5) / 4.0) +
              " 0.5 " + std::to_string((j % 3) / 2.0) + '\n';
      text += "vt " + std::to_string(x) + ' ' + std::to_string(y) + '\n';
    }
  }
  text += "vn 0 0 1\nvn 0 1 0\n";
  int face = 0;
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i, ++face) {
      if (face % 9000 == 0) text += "o part" + std::to_string(face / 9000 % 3) + '\n';
      if (face % 700 == 0) text += "g group" + std::to_string(face / 700 % 5) + '\n';
      if (face % 333 == 0) text += "usemtl m" + std::to_string(face % 4) + '\n';
      if (face % 5000 == 0) text += "s " + std::to_string(face / 5000 % 2) + '\n';
      const int a = vertex_at(i, j) + 1, b = vertex_at(i + 1, j) + 1,
                c = vertex_at(i + 1, j + 1) + 1, d = vertex_at(i, j + 1) + 1;
      const std::string n = std::to_string(face % 2 + 1);
      auto corner = [&](int v) {
        return ' ' + std::to_string(v) + '/' + std::to_string(v) + '/' + n;
      };
      text += 'f' + corner(a) + corner(b) + corner(c) + "\nf" + corner(a) + corner(c) + corner(d) +
              '\n';
    }
  }
  return text;
}

// The same grid as an ASCII PLY with a colour per vertex (uchar) and a value per face (float).
std::string grid_ply() {
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex " + std::to_string((kSide + 1) * (kSide + 1)) +
      "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
      "element face " +
      std::to_string(2 * kSide * kSide) +
      "\nproperty list uchar int vertex_indices\nproperty float quality\nend_header\n";
  for (int j = 0; j <= kSide; ++j) {
    for (int i = 0; i <= kSide; ++i) {
      text += std::to_string(i / 64.0) + ' ' + std::to_string(j / 64.0) + ' ' +
              std::to_string(0.001 * i * j) + ' ' + std::to_string((i * 7 + j) % 256) + '\n';
    }
  }
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      const std::string a = std::to_string(vertex_at(i, j)),
                        b = std::to_string(vertex_at(i + 1, j)),
                        c = std::to_string(vertex_at(i + 1, j + 1)),
                        d = std::to_string(vertex_at(i, j + 1));
      text += "3 " + a + ' ' + b + ' ' + c + ' ' + std::to_string(0.25 * i) + "\n3 " + a + ' ' + c +
              ' ' + d + ' ' + std::to_string(0.5 * j) + '\n';
    }
  }
  return text;
}

// How many faces have each (object, group, material, smoothing group), by name.
std::map<std::vector<std::string>, std::size_t> faces_per_state(const Mesh& mesh) {
  const ObjHandles obj = obj_handles(mesh);
  const ObjTables& tables = mesh.property(obj.tables);
  auto name = [&](OpenMesh::FPropHandleT<int> property, const std::vector<std::string>& names,
                  FaceHandle f) {
    const int number = obj_face_number(mesh, property, f);
    return number ? names[static_cast<std::size_t>(number - 1)] : std::string();
  };
  std::map<std::vector<std::string>, std::size_t> count;
  for (const auto f : mesh.faces()) {
    ++count[{name(obj.object, tables.objects, f), name(obj.group, tables.groups, f),
             name(obj.material, tables.materials, f),
             name(obj.smoothing, tables.smoothing_groups, f)}];
  }
  return count;
}

TEST(WriteThreads, EveryFormatIsTheOneThreadFileOnAnyNumberOfThreads) {
  const Mesh obj = load_mesh_from_memory(grid_obj(), "grid.obj", nullptr, 1);
  const Mesh ply = load_mesh_from_memory(grid_ply(), "grid.ply", nullptr, 1);
  ASSERT_EQ(obj.n_faces(), std::size_t{2 * kSide * kSide});
  ASSERT_EQ(ply.n_vertices(), std::size_t{(kSide + 1) * (kSide + 1)});
  // OBJ keeps its attributes; the PLY's mesh as PLY (its ASCII and types), OFF and STL, and the
  // OBJ's mesh as PLY (ASCII doubles with its colours) and OFF (COFF).
  const std::pair<const Mesh*, const char*> files[] = {
      {&obj, "a.obj"}, {&obj, "a.ply"}, {&obj, "a.off"}, {&ply, "b.ply"},
      {&ply, "b.off"}, {&ply, "b.stl"}, {&ply, "b.obj"}};
  for (const auto& [mesh, name] : files) {
    const std::string one = mesh_to_bytes(*mesh, name, 1);
    for (const unsigned threads : {2u, 3u, 8u}) {
      SCOPED_TRACE(std::string(name) + ", threads " + std::to_string(threads));
      EXPECT_TRUE(mesh_to_bytes(*mesh, name, threads) == one);
    }
    // What one thread wrote reads back to the mesh it was written from.
    const Mesh back = load_mesh_from_memory(one, name, nullptr, 1);
    EXPECT_EQ(back.n_faces(), mesh->n_faces());
  }
  // Read back, the OBJ written on three threads gives each face the object, group, material and
  // smoothing group it had (faces counted per four names): every block started from the state
  // of the face before it, and said each change.
  const Mesh back = load_mesh_from_memory(mesh_to_bytes(obj, "c.obj", 3), "c.obj", nullptr, 1);
  EXPECT_EQ(faces_per_state(back), faces_per_state(obj));
}

}  // namespace
}  // namespace holefill
