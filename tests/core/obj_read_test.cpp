// OBJ reading through tinyobjloader: numbers read exactly, every malformed statement refused with
// its line, statements holefill drops named in a warning, per-face numbers only where a face has
// one; and what saving in another format leaves out.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <tuple>

#include "holefill/errors.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/obj_attributes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

std::string reason_of(const std::string& text) {
  try {
    load_mesh_from_memory(text, "t.obj");
  } catch (const FileError& e) {
    return e.reason();
  }
  return "(loaded)";
}

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// kTriangle followed by `rest`. Appended, not `std::string + "..."`: GCC 12 at -O1 warns
// -Warray-bounds on that concatenation inlined here (a false positive of its string code).
std::string triangle_then(std::string_view rest) {
  std::string text(kTriangle);
  text.append(rest);
  return text;
}

TEST(ObjRead, CoordinatesAreReadCorrectlyRoundedWhereTinyobjloaderIsNot) {
  // Random doubles as 17 digits and as 6: strtod's values are the truth.
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> any(-1e3, 1e3);
  std::string text;
  std::vector<double> truth;
  for (int v = 0; v < 300; ++v) {
    text += 'v';
    for (int axis = 0; axis < 3; ++axis) {
      char number[40];
      std::snprintf(number, sizeof number, v % 2 ? " %.17g" : " %.6g", any(random));
      text += number;
      truth.push_back(std::strtod(number, nullptr));
    }
    text += '\n';
  }
  text += "f 1 2 3\n";
  const Mesh mesh = load_mesh_from_memory(text, "t.obj");
  ASSERT_EQ(mesh.n_vertices(), 300u);
  for (int v = 0; v < 300; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(mesh.point(VertexHandle(v))[axis]),
                std::bit_cast<std::uint64_t>(truth[3 * v + axis]))
          << "vertex " << v;
    }
  }
}

TEST(ObjRead, MalformedStatementsAreRefusedWithTheirLine) {
  EXPECT_EQ(reason_of(triangle_then("v 1 2\nf 1 2 3\n")), "line 4: vertex needs 3 numbers");
  EXPECT_EQ(reason_of(triangle_then("v\nf 1 2 3\n")), "line 4: vertex needs 3 numbers");
  EXPECT_EQ(reason_of(triangle_then("vt nan 0\nf 1/1 2/1 3/1\n")),
            "line 4: texture coordinate has a non-finite value");
  EXPECT_EQ(reason_of(triangle_then("vn 0 0\nf 1//1 2//1 3//1\n")),
            "line 4: normal needs 3 numbers");
  EXPECT_EQ(reason_of(triangle_then("vt 0 0\nf 1/1 2/2 3/1\n")),
            "line 5: face refers to texture coordinate 2, but the file has 1 texture coordinates");
  EXPECT_EQ(reason_of(triangle_then("vn 0 0 1\nf 1//1 2//1 3//-2\n")),
            "line 5: relative normal index -2 reaches before the first normal");
  EXPECT_EQ(reason_of(triangle_then("vt 0 0\nf 1/0 2/1 3/1\n")),
            "line 5: texture coordinate index 0 (OBJ counts from 1)");
  EXPECT_EQ(reason_of(triangle_then("vt 0 0\nf 1/x 2/1 3/1\n")),
            "line 5: face corner '1/x' has no valid texture coordinate index");
  EXPECT_EQ(reason_of(triangle_then("f 1 2 \\\n 9\n")),
            "line 4: face refers to vertex 9, but the file has 3 vertices");
}

TEST(ObjRead, OldFaceKeywordsBareGroupsAndEmptyFacesAreUnderstood) {
  LoadReport report;
  const Mesh mesh =
      load_mesh_from_memory(triangle_then("v 1 1 0\ng\nfo 1 2 3\nf\nf 2 4 3\n"), "t.obj", &report);
  EXPECT_EQ(mesh.n_faces(), 2u);
  EXPECT_EQ(report.degenerate_faces_dropped, 1u);
}

TEST(ObjRead, StatementsNotKeptAreNamedInAWarning) {
  LoadReport report;
  load_mesh_from_memory(triangle_then("s 1\nvp 0.5\ns off\nl 1 2\nf 1 2 3\n"), "t.obj", &report);
  EXPECT_EQ(report.elements_ignored, 1u);
  const auto named =
      std::find_if(report.warnings.begin(), report.warnings.end(),
                   [](const std::string& w) { return w.find("'vp' (1)") != std::string::npos; });
  ASSERT_NE(named, report.warnings.end());
  EXPECT_EQ(named->find("'s'"), std::string::npos) << *named;  // smoothing groups are kept
}

// A per-face number no face has is no property of the loaded mesh (4 MB a million faces), and
// without it the mesh is written as with every face's number 0.
TEST(ObjRead, PerFaceNumbersNoFaceHasAreNoProperties) {
  const std::string text =
      "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nf 1/1 2/1 3/1\n"
      "usemtl red\nf 2/1 4/1 3/1\n";
  const Mesh mesh = load_mesh_from_memory(text, "t.obj");
  const ObjHandles obj = obj_handles(mesh);
  ASSERT_TRUE(obj.valid());
  EXPECT_TRUE(obj.texcoord.is_valid());
  EXPECT_TRUE(obj.normal.is_valid());
  EXPECT_TRUE(obj.material.is_valid());
  EXPECT_FALSE(obj.group.is_valid());
  EXPECT_FALSE(obj.object.is_valid());
  EXPECT_FALSE(obj.smoothing.is_valid());
  EXPECT_EQ(obj_face_number(mesh, obj.material, FaceHandle(1)), 1);
  EXPECT_EQ(obj_face_number(mesh, obj.group, FaceHandle(1)), 0);
  // The same mesh with every per-face number: written alike.
  Mesh every = mesh;
  const ObjHandles all = add_obj_handles(every);
  ASSERT_TRUE(all.group.is_valid() && all.object.is_valid() && all.smoothing.is_valid());
  EXPECT_EQ(all.material, obj.material);
  EXPECT_EQ(mesh_to_bytes(mesh, "out.obj"), mesh_to_bytes(every, "out.obj"));
}

TEST(ObjSave, SmoothingGroupsSavedWhereOnlyObjHoldsThemAreNamed) {
  const Mesh mesh = load_mesh_from_memory(triangle_then("s 1\nf 1 2 3\n"), "t.obj");
  EXPECT_TRUE(attributes_not_written(mesh, "out.obj").empty());
  for (const char* name : {"out.ply", "out.off", "out.stl"}) {
    EXPECT_EQ(attributes_not_written(mesh, name),
              (std::vector<std::string>{"smoothing groups (only OBJ holds them)"}));
  }
}
}  // namespace
}  // namespace holefill
