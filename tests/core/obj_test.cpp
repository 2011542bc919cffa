// OBJ attributes (texture coordinates, normals, materials, groups, smoothing groups and material
// libraries) kept bit for bit through load, fill and save, and given to patches where they can
// be. Reading statements: obj_read_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <tuple>

#include "holefill/errors.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/obj_attributes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

namespace fs = std::filesystem;

class ObjFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("holefill_obj_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const fs::path& name, const std::string& text) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  fs::path dir_;
};

std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// "<keyword> a b c\n" with the numbers at 17 digits.
std::string statement(const char* keyword, std::initializer_list<double> values) {
  std::string text = keyword;
  for (const double value : values) {
    text += ' ';
    text += number(value);
  }
  text += '\n';
  return text;
}

// " v/vt/vn".
std::string corner(int v, int vt, int vn) {
  std::string text = " ";
  text += std::to_string(v);
  for (const int index : {vt, vn}) {
    text += '/';
    text += std::to_string(index);
  }
  return text;
}

using Bits = std::array<std::uint64_t, 3>;

// What a face corner carries, as bits: its vertex, texture coordinate and normal (all ones
// where it has none).
using CornerValues = std::tuple<int, Bits, Bits>;
// A face: its corners from the smallest vertex on, its material, group, object and smoothing group.
using FaceValues =
    std::tuple<std::vector<CornerValues>, std::string, std::string, std::string, std::string>;

template <class Vector>
Bits bits_of(const Vector& value) {
  return {std::bit_cast<std::uint64_t>(double(value[0])),
          std::bit_cast<std::uint64_t>(double(value[1])),
          std::bit_cast<std::uint64_t>(double(value[2]))};
}

std::string name_in(const std::vector<std::string>& names, int number) {
  return number ? names[number - 1] : "(none)";
}

FaceValues face_values(const Mesh& mesh, FaceHandle f) {
  const ObjHandles obj = obj_handles(mesh);
  const ObjTables& tables = mesh.property(obj.tables);
  std::vector<CornerValues> corners;
  const Bits none{~0ull, ~0ull, ~0ull};
  for (const auto h : mesh.fh_range(f)) {
    const int t = mesh.property(obj.texcoord, h), n = mesh.property(obj.normal, h);
    corners.emplace_back(mesh.to_vertex_handle(h).idx(),
                         t ? bits_of(tables.texcoords[t - 1]) : none,
                         n ? bits_of(tables.normals[n - 1]) : none);
  }
  std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
  return {corners, name_in(tables.materials, obj_face_number(mesh, obj.material, f)),
          name_in(tables.groups, obj_face_number(mesh, obj.group, f)),
          name_in(tables.objects, obj_face_number(mesh, obj.object, f)),
          name_in(tables.smoothing_groups, obj_face_number(mesh, obj.smoothing, f))};
}

// Every face's values, in no particular order (the writer groups faces).
std::vector<FaceValues> all_face_values(const Mesh& mesh) {
  std::vector<FaceValues> faces;
  for (const auto f : mesh.faces()) faces.push_back(face_values(mesh, f));
  std::sort(faces.begin(), faces.end());
  return faces;
}

// A closed box of quads with per-face normals, UVs at 17 digits (seams on every edge), two
// materials, two groups in one object, and a material library in a sub-folder.
std::string textured_box() {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> any(0.0, 1.0);
  std::string text = "# box\nmtllib mats/box.mtl\no box\n";
  for (int v = 0; v < 8; ++v) {
    text += statement("v", {(v & 1) + 0.1 * any(random), (v >> 1 & 1) + 0.1, (v >> 2 & 1) - 0.3});
  }
  for (int t = 0; t < 24; ++t) text += statement("vt", {any(random), any(random)});
  const int normals[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (const auto& n : normals) {
    text += statement("vn", {n[0] + 1e-3 * any(random), double(n[1]), double(n[2])});
  }
  const int quads[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                           {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
  for (int q = 0; q < 6; ++q) {
    if (q == 0) text += "g lid top\nusemtl wood\n";
    if (q == 2) text += "g sides\nusemtl metal\n";
    if (q == 4) text += "usemtl wood\n";
    text += "f";
    for (int c = 0; c < 4; ++c) {
      text += corner(quads[q][c], 4 * q + c + 1, q + 1);
    }
    text += "\n";
  }
  return text;
}

TEST_F(ObjFiles, TexturedObjRoundTripsBitForBit) {
  const fs::path in = write("in/box.obj", textured_box());
  write("in/mats/box.mtl", "newmtl wood\nnewmtl metal\n");
  LoadReport report;
  const Mesh mesh = load_mesh(in, &report);
  EXPECT_TRUE(report.warnings.empty() ||
              report.warnings.front().find("triangulated") != std::string::npos);
  ASSERT_EQ(mesh.n_faces(), 12u);
  const ObjHandles obj = obj_handles(mesh);
  ASSERT_TRUE(obj.valid());
  const ObjTables& tables = mesh.property(obj.tables);
  EXPECT_EQ(tables.texcoords.size(), 24u);
  EXPECT_EQ(tables.normals.size(), 6u);
  EXPECT_EQ(tables.materials, (std::vector<std::string>{"wood", "metal"}));
  EXPECT_EQ(tables.groups, (std::vector<std::string>{"lid top", "sides"}));
  // Each triangle's corners carry their quad's numbers: the lid (quad 0) uses vt 1-4 and vn 1.
  for (const auto h : mesh.fh_range(FaceHandle(0))) {
    EXPECT_LE(mesh.property(obj.texcoord, h), 4);
    EXPECT_EQ(mesh.property(obj.normal, h), 1);
  }
  fs::create_directories(dir_ / "out");
  save_mesh(mesh, dir_ / "out" / "box.obj");
  const Mesh again = load_mesh(dir_ / "out" / "box.obj");
  EXPECT_EQ(all_face_values(again), all_face_values(mesh));
  EXPECT_TRUE(testing::original_part_unchanged(mesh, again));
  const std::string written = read(dir_ / "out" / "box.obj");
  EXPECT_NE(written.find("mtllib ../in/mats/box.mtl\n"), std::string::npos) << written;
  EXPECT_NE(written.find("o box\ng lid top\nusemtl wood\nf 1/"), std::string::npos) << written;
  // Written again, the file is the same.
  save_mesh(again, dir_ / "out" / "box2.obj");
  EXPECT_EQ(read(dir_ / "out" / "box2.obj"), written);
}

TEST_F(ObjFiles, AMaterialLibraryWhosePathHoldsASpaceIsNotWrittenButNamed) {
  // From "in dir/" to "out/" the library's path is "../in dir/box.mtl": written unquoted, OBJ
  // readers (ours too) read two libraries, "../in" and "dir/box.mtl".
  const fs::path in = write("in dir/box.obj", "mtllib box.mtl other.mtl\n" + textured_box());
  write("in dir/box.mtl", "newmtl wood\nnewmtl metal\n");
  const Mesh mesh = load_mesh(in);
  const ObjTables& tables = mesh.property(obj_handles(mesh).tables);
  ASSERT_EQ(tables.material_libraries.size(), 3u);
  fs::create_directories(dir_ / "out");
  const fs::path out = dir_ / "out" / "box.obj";
  const auto lost = attributes_not_written(mesh, out);
  ASSERT_EQ(lost.size(), 1u);
  const std::string folder = fs::weakly_canonical(dir_ / "in dir").generic_string();
  EXPECT_EQ(lost[0], "the material libraries '" + folder + "/box.mtl', '" + folder +
                         "/other.mtl', '" + folder +
                         "/mats/box.mtl' (the path from the output's folder holds a space, which "
                         "OBJ readers take as the gap between two libraries)");
  save_mesh(mesh, out);
  const std::string written = read(out);
  EXPECT_EQ(written.find("mtllib"), std::string::npos) << written.substr(0, 200);
  const Mesh again = load_mesh(out);
  EXPECT_TRUE(again.property(obj_handles(again).tables).material_libraries.empty());

  // Beside the input the names hold no space: all written, nothing named.
  const fs::path beside = dir_ / "in dir" / "filled.obj";
  EXPECT_TRUE(attributes_not_written(mesh, beside).empty());
  save_mesh(mesh, beside);
  EXPECT_NE(read(beside).find("mtllib box.mtl other.mtl mats/box.mtl\n"), std::string::npos);
  const Mesh there = load_mesh(beside);
  EXPECT_EQ(there.property(obj_handles(there).tables).material_libraries,
            tables.material_libraries);
}

TEST_F(ObjFiles, SmoothingGroupsRoundTripBitForBit) {
  // As holefill writes it: "s" only where the group changes (it lasts across "g"), spelt as read.
  const std::string text =
      "# written by holefill\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 0 0\nv 2 1 0\nv 3 0 0\n"
      "f 1 2 3\ns 2\nf 2 4 3\ng rim\nf 2 5 4\ns off\nf 5 6 4\ns 0\nf 5 7 6\n";
  const Mesh mesh = load_mesh(write("in.obj", text));
  EXPECT_EQ(mesh.property(obj_handles(mesh).tables).smoothing_groups,
            (std::vector<std::string>{"2", "off", "0"}));
  save_mesh(mesh, dir_ / "out.obj");
  EXPECT_EQ(read(dir_ / "out.obj"), text);
}

TEST_F(ObjFiles, MaterialLibrariesResolveFromTheOutputsFolder) {
  const fs::path in = write("models/a/box.obj", textured_box());
  const fs::path library = write("models/a/mats/box.mtl", "newmtl wood\n");
  const Mesh mesh = load_mesh(in);
  for (const fs::path& out :
       {dir_ / "models" / "a" / "same.obj", dir_ / "x" / "y" / "deep.obj", dir_ / "up.obj"}) {
    fs::create_directories(out.parent_path());
    save_mesh(mesh, out);
    const std::string text = read(out);
    const std::size_t at = text.find("mtllib ");
    ASSERT_NE(at, std::string::npos);
    const std::string named = text.substr(at + 7, text.find('\n', at) - at - 7);
    EXPECT_TRUE(fs::path(named).is_relative()) << named;
    EXPECT_TRUE(fs::equivalent(out.parent_path() / named, library)) << named;
  }
}

// An icosphere with a hole at its top, textured by a planar projection (one chart) or by two
// charts meeting at x = 0 (a seam across the hole), with per-vertex normals and a material
// per side; with smoothing group 4 where x > -0.25 (most of the hole's rim), off elsewhere.
std::string textured_sphere(bool seam, bool smoothing = false) {
  const Mesh mesh =
      testing::without_faces(testing::make_icosphere(3), [](const Point& c) { return c[2] > 0.8; });
  std::string text = "mtllib s.mtl\n";
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    text += statement("v", {p[0], p[1], p[2]});
  }
  for (int chart = 0; chart < (seam ? 2 : 1); ++chart) {
    for (const auto v : mesh.vertices()) {
      const Point& p = mesh.point(v);
      text += statement("vt", {0.25 + 0.25 * p[0] + 0.5 * chart, 0.5 + 0.25 * p[1]});
    }
  }
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    text += statement("vn", {p[0], p[1], p[2]});
  }
  const int n = static_cast<int>(mesh.n_vertices());
  std::string last, last_smoothing;
  for (const auto f : mesh.faces()) {
    const Point centre = mesh.calc_face_centroid(f);
    const std::string material = centre[0] > 0 ? "usemtl east\n" : "usemtl west\n";
    if (material != last) text += material;
    last = material;
    const std::string group = centre[0] > -0.25 ? "s 4\n" : "s off\n";
    if (smoothing && group != last_smoothing) text += group;
    last_smoothing = group;
    const int chart = seam && centre[0] < 0 ? 1 : 0;
    text += "f";
    for (const auto v : mesh.fv_range(f)) {
      const int i = v.idx() + 1;
      text += corner(i, i + chart * n, i);
    }
    text += "\n";
  }
  return text;
}

TEST_F(ObjFiles, AFillKeepsTheOriginalsAndGivesThePatchUvsInRange) {
  Mesh mesh = load_mesh(write("s.obj", textured_sphere(false)));
  const Mesh before = mesh;
  const auto fills = fill_holes(mesh, find_holes(mesh), FillOptions{});
  ASSERT_EQ(fills.size(), 1u);
  ASSERT_FALSE(fills[0].failed());
  EXPECT_TRUE(fills[0].attributes_note.empty()) << fills[0].attributes_note;
  ASSERT_FALSE(fills[0].patch.new_vertices.empty());
  for (const auto f : before.faces()) EXPECT_EQ(face_values(mesh, f), face_values(before, f));
  const ObjHandles obj = obj_handles(mesh);
  const ObjTables& tables = mesh.property(obj.tables);
  // The boundary's UVs bound the patch's (harmonic: maximum principle).
  std::array<double, 2> low{1e9, 1e9}, high{-1e9, -1e9};
  for (const auto v : fills[0].patch.boundary) {
    const Point& p = mesh.point(v);
    const double uv[2] = {0.25 + 0.25 * p[0], 0.5 + 0.25 * p[1]};
    for (int i = 0; i < 2; ++i)
      low[i] = std::min(low[i], uv[i]), high[i] = std::max(high[i], uv[i]);
  }
  const std::size_t materials_before = tables.materials.size();
  for (const auto f : fills[0].patch.faces) {
    EXPECT_GE(mesh.property(obj.material, f), 1);
    for (const auto h : mesh.fh_range(f)) {
      const int t = mesh.property(obj.texcoord, h), n = mesh.property(obj.normal, h);
      ASSERT_GT(t, 0);
      ASSERT_GT(n, 0);
      for (int i = 0; i < 2; ++i) {
        EXPECT_GE(tables.texcoords[t - 1][i], low[i] - 1e-12);
        EXPECT_LE(tables.texcoords[t - 1][i], high[i] + 1e-12);
      }
      EXPECT_NEAR(tables.normals[n - 1].norm(), 1.0, 1e-9);
      EXPECT_GT(tables.normals[n - 1][2], 0.5);  // the cap faces up
    }
  }
  EXPECT_EQ(tables.materials.size(), materials_before);
  // Written and read again: the same, the patch's UVs included.
  save_mesh(mesh, dir_ / "filled.obj");
  const Mesh again = load_mesh(dir_ / "filled.obj");
  EXPECT_EQ(all_face_values(again), all_face_values(mesh));
  EXPECT_TRUE(find_holes(again).empty());
}

TEST_F(ObjFiles, APatchTakesTheSmoothingGroupMostFacesAlongTheHoleHave) {
  Mesh mesh = load_mesh(write("s.obj", textured_sphere(false, true)));
  const Mesh before = mesh;
  const auto fills = fill_holes(mesh, find_holes(mesh), FillOptions{});
  ASSERT_EQ(fills.size(), 1u);
  ASSERT_FALSE(fills[0].failed());
  for (const auto f : before.faces()) EXPECT_EQ(face_values(mesh, f), face_values(before, f));
  // The truth: the groups of the original faces that share an edge with the patch.
  std::map<std::string, int> votes;
  for (const auto f : fills[0].patch.faces) {
    for (const auto g : mesh.ff_range(f)) {
      if (g.idx() < static_cast<int>(before.n_faces())) ++votes[std::get<4>(face_values(mesh, g))];
    }
  }
  ASSERT_GT(votes["4"], votes["off"]);
  for (const auto f : fills[0].patch.faces) EXPECT_EQ(std::get<4>(face_values(mesh, f)), "4");
  save_mesh(mesh, dir_ / "filled.obj");
  EXPECT_EQ(all_face_values(load_mesh(dir_ / "filled.obj")), all_face_values(mesh));
}

TEST_F(ObjFiles, AUvSeamAcrossTheHoleLeavesThePatchWithoutUvsAndSaysSo) {
  Mesh mesh = load_mesh(write("s.obj", textured_sphere(true)));
  const Mesh before = mesh;
  const auto fills = fill_holes(mesh, find_holes(mesh), FillOptions{});
  ASSERT_EQ(fills.size(), 1u);
  ASSERT_FALSE(fills[0].failed());
  EXPECT_NE(fills[0].attributes_note.find("not in one UV chart"), std::string::npos)
      << fills[0].attributes_note;
  for (const auto f : before.faces()) EXPECT_EQ(face_values(mesh, f), face_values(before, f));
  const ObjHandles obj = obj_handles(mesh);
  for (const auto f : fills[0].patch.faces) {
    for (const auto h : mesh.fh_range(f)) {
      EXPECT_EQ(mesh.property(obj.texcoord, h), 0);
      EXPECT_GT(mesh.property(obj.normal, h), 0);
    }
  }
  // Written with the patch's faces as "v//vn".
  save_mesh(mesh, dir_ / "filled.obj");
  const Mesh again = load_mesh(dir_ / "filled.obj");
  EXPECT_EQ(all_face_values(again), all_face_values(mesh));
}

TEST_F(ObjFiles, SavingInAFormatThatCannotHoldTheAttributesSaysWhatIsLeftOut) {
  const Mesh textured = load_mesh(write("box.obj", textured_box()));
  EXPECT_TRUE(attributes_not_written(textured, "out.obj").empty());
  for (const char* name : {"out.ply", "out.off", "out.STL"}) {
    const auto lost = attributes_not_written(textured, name);
    ASSERT_EQ(lost.size(), 1u) << name;
    EXPECT_NE(lost[0].find("texture coordinates"), std::string::npos) << name;
  }
  const Mesh scan = load_mesh(
      write("scan.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
            "property float quality\nelement face 1\nproperty list uchar int vertex_indices\n"
            "property uchar flags\nend_header\n0 0 0 1 2 3 0.5\n1 0 0 1 2 3 0.5\n0 1 0 1 2 3 0.5\n"
            "3 0 1 2 7\n"));
  EXPECT_TRUE(attributes_not_written(scan, "out.ply").empty());
  EXPECT_EQ(attributes_not_written(scan, "out.obj"),
            (std::vector<std::string>{"vertex properties quality", "face properties flags"}));
  EXPECT_EQ(attributes_not_written(scan, "out.off"),
            (std::vector<std::string>{"vertex properties quality", "face properties flags"}));
}

// Real exporters' files (assimp's test models, BSD-3-clause; two are copied into tests/data, the
// rest are read where the assimp-testmodels package is installed).
TEST_F(ObjFiles, ExportersFilesLoadAndRoundTrip) {
  std::vector<fs::path> files = {fs::path(HOLEFILL_TEST_DATA_DIR) / "spider.obj",
                                 fs::path(HOLEFILL_TEST_DATA_DIR) / "cube_usemtl.obj"};
  const fs::path installed = "/usr/share/assimp/models/OBJ";
  if (fs::is_directory(installed)) {
    for (const auto& entry : fs::directory_iterator(installed)) {
      if (entry.path().extension() == ".obj") files.push_back(entry.path());
    }
  }
  int loaded = 0;
  for (const auto& file : files) {
    Mesh mesh;
    try {
      mesh = load_mesh(file);
    } catch (const FileError&) {
      continue;  // point clouds, UTF-16: refused, which the bad-input suite covers
    }
    ++loaded;
    save_mesh(mesh, dir_ / file.filename());
    const Mesh again = load_mesh(dir_ / file.filename());
    EXPECT_TRUE(testing::original_part_unchanged(mesh, again)) << file;
    if (obj_handles(mesh).valid()) {
      EXPECT_EQ(all_face_values(again), all_face_values(mesh)) << file;
    }
  }
  EXPECT_GE(loaded, 2);
  // The spider: textured (vt), normals, materials and groups, named by MilkShape.
  const Mesh spider = load_mesh(files[0]);
  const ObjTables& tables = spider.property(obj_handles(spider).tables);
  EXPECT_FALSE(tables.texcoords.empty());
  EXPECT_FALSE(tables.normals.empty());
  EXPECT_GE(tables.materials.size(), 2u);
  EXPECT_GE(tables.groups.size(), 2u);
  ASSERT_EQ(tables.material_libraries.size(), 1u);
  EXPECT_EQ(tables.material_libraries[0].filename(), "spider.mtl");
}

}  // namespace
}  // namespace holefill
