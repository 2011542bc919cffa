// OBJ through tinyobjloader (issue 12): numbers read exactly, every malformed statement refused
// with its line, statements holefill drops named in a warning.
#include <gtest/gtest.h>

#include <bit>
#include <cstdio>
#include <random>
#include <string>

#include "holefill/errors.h"
#include "holefill/io.h"

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
  const std::string t = kTriangle;
  EXPECT_EQ(reason_of(t + "v 1 2\nf 1 2 3\n"), "line 4: vertex needs 3 numbers");
  EXPECT_EQ(reason_of(t + "v\nf 1 2 3\n"), "line 4: vertex needs 3 numbers");
  EXPECT_EQ(reason_of(t + "vt nan 0\nf 1/1 2/1 3/1\n"),
            "line 4: texture coordinate has a non-finite value");
  EXPECT_EQ(reason_of(t + "vn 0 0\nf 1//1 2//1 3//1\n"), "line 4: normal needs 3 numbers");
  EXPECT_EQ(reason_of(t + "vt 0 0\nf 1/1 2/2 3/1\n"),
            "line 5: face refers to texture coordinate 2, but the file has 1 texture coordinates");
  EXPECT_EQ(reason_of(t + "vn 0 0 1\nf 1//1 2//1 3//-2\n"),
            "line 5: relative normal index -2 reaches before the first normal");
  EXPECT_EQ(reason_of(t + "vt 0 0\nf 1/0 2/1 3/1\n"),
            "line 5: texture coordinate index 0 (OBJ counts from 1)");
  EXPECT_EQ(reason_of(t + "vt 0 0\nf 1/x 2/1 3/1\n"),
            "line 5: face corner '1/x' has no valid texture coordinate index");
  EXPECT_EQ(reason_of(t + "f 1 2 \\\n 9\n"),
            "line 4: face refers to vertex 9, but the file has 3 vertices");
}

TEST(ObjRead, OldFaceKeywordsBareGroupsAndEmptyFacesAreUnderstood) {
  LoadReport report;
  const Mesh mesh = load_mesh_from_memory(
      std::string(kTriangle) + "v 1 1 0\ng\nfo 1 2 3\nf\n" + "f 2 4 3\n", "t.obj", &report);
  EXPECT_EQ(mesh.n_faces(), 2u);
  EXPECT_EQ(report.degenerate_faces_dropped, 1u);
}

TEST(ObjRead, StatementsNotKeptAreNamedInAWarning) {
  LoadReport report;
  load_mesh_from_memory(std::string(kTriangle) + "s 1\nvp 0.5\ns off\nl 1 2\nf 1 2 3\n", "t.obj",
                        &report);
  EXPECT_EQ(report.elements_ignored, 1u);
  const auto named = std::find_if(
      report.warnings.begin(), report.warnings.end(),
      [](const std::string& w) { return w.find("'s' (2), 'vp' (1)") != std::string::npos; });
  EXPECT_NE(named, report.warnings.end());
}

}  // namespace
}  // namespace holefill
