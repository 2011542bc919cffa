// The token rules of the OBJ and OFF readers, which read numbers in place and serve the usual
// face corners on a fast path: a number is a whole blank-separated token (one followed by
// anything else is refused, quoted as before), '+' signs are taken but not "+-", every corner
// spelling reads as the slow path splits it, and lines end at LF, CR LF or a lone CR in any mix.
// The expected messages are those of the readers before the fast paths.
#include <string>

#include "robust_test_util.h"

namespace holefill::testing {
namespace {

constexpr const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
constexpr const char* kTriangleOff = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";

TEST(TextTokens, EveryObjCornerSpellingReadsAsOneFace) {
  const std::string t = kTriangleObj;
  for (const std::string faces :
       {"f 1/ 2// 3\n", "f +1 +2 +3\n", "f -3 -2 -1\n", "f 1\t2\v3\f\n", " \tfo 1 2 3 # c\n",
        "f 1 2\\\n 3\n", "vt 0 0\nf 1/1/ 2/1 3/-1\n", "vn 0 0 1\nf 1//1 2//+1 3//-1\n"}) {
    LoadReport report;
    const Mesh mesh = load_mesh_from_memory(t + faces, "t.obj", &report);
    EXPECT_EQ(mesh.n_faces(), 1u) << faces;
    EXPECT_TRUE(report.warnings.empty()) << faces << report.warnings.front();
  }
  LoadReport report;
  load_mesh_from_memory(t + "vt 0 0\nf 1/1 2/1 3/\n", "t.obj", &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            "1 faces gave texture coordinates to some of their corners only; those were dropped");
}

TEST(TextTokens, ObjNumbersFollowedByOtherCharactersAreRefusedAsBefore) {
  const std::string t = kTriangleObj;
  EXPECT_EQ(refusal(t + "v 0 0 0x\n", "t.obj"), "line 4: vertex needs 3 numbers, got '0x'");
  EXPECT_EQ(refusal(t + "v +-1 0 0\n", "t.obj"), "line 4: vertex needs 3 numbers, got '+-1'");
  EXPECT_EQ(refusal(t + "v 1e999 0 0\n", "t.obj"),
            "line 4: vertex 4 has a non-finite (NaN or infinite) coordinate");
  EXPECT_EQ(refusal(t + "f 1 2 3x\n", "t.obj"), "line 4: face corner '3x' is not a vertex index");
  EXPECT_EQ(refusal(t + "f 1 2 +-3\n", "t.obj"), "line 4: face corner '+-3' is not a vertex index");
  EXPECT_EQ(refusal(t + "f 1 2 99999999999999999999\n", "t.obj"),
            "line 4: face corner '99999999999999999999' is not a vertex index");
  EXPECT_EQ(refusal(t + "vt 0 0\nf 1/1/ 2/1 3/1//\n", "t.obj"),
            "line 5: face corner '3/1//' has no valid normal index");
  EXPECT_EQ(refusal(t + "vn 0 0 1\nf 1//1 2//1 3//1/\n", "t.obj"),
            "line 5: face corner '3//1/' has no valid normal index");
  // A bad index before a syntax error is named first, as the corners come.
  EXPECT_EQ(refusal(t + "f 0 2 3x\n", "t.obj"), "line 4: vertex index 0 (OBJ counts from 1)");
  // Underflow reads as a tiny number; colours that are not numbers are not colours.
  EXPECT_EQ(refusal(t + "v 1e-400 0 0 1 1 1x\nf 1 2 4\n", "t.obj"), "");
}

TEST(TextTokens, OffNumbersFollowedByOtherCharactersAreRefusedAsBefore) {
  const std::string t = kTriangleOff;
  EXPECT_EQ(refusal(t + "+3 +0 +1 +2\n", "t.off"), "");
  EXPECT_EQ(refusal(t + "3\t0\v1\f2\n", "t.off"), "");
  EXPECT_EQ(refusal(t + "3 0 1 2x\n", "t.off"), "line 6: face needs 3 vertex indices, got '2x'");
  EXPECT_EQ(refusal(t + "3 0 1 +-2\n", "t.off"), "line 6: face needs 3 vertex indices, got '+-2'");
  EXPECT_EQ(refusal(t + "3x 0 1 2\n", "t.off"),
            "line 6: a face must start with its number of corners, got '3x'");
  EXPECT_EQ(refusal(t + "-1 0 1 2\n", "t.off"),
            "line 6: a face must start with its number of corners, got '-1'");
  EXPECT_EQ(refusal(t + "3 0 1\n", "t.off"), "line 6: face needs 3 vertex indices");
  EXPECT_EQ(refusal(t + "3 0 1 2 0.5 0.5 0.5x\n", "t.off"),
            "line 6: expected a number, got '0.5x'");
  EXPECT_EQ(refusal("OFF\n3 1 0\n0 0 0x\n1 0 0\n0 1 0\n3 0 1 2\n", "t.off"),
            "line 3: vertex needs 3 numbers, got '0x'");
  EXPECT_EQ(refusal("COFF\n3 1 0\n0 0 0 1 2 3\n1 0 0 1 2 3x\n0 1 0\n3 0 1 2\n", "t.off"),
            "line 4: expected a number, got '3x'");
}

TEST(TextTokens, MixedLineEndsCountLinesAsBefore) {
  // CR LF, a lone CR, LF; then "\r\r\n\n" is three empty lines.
  EXPECT_EQ(refusal("v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\r\r\n\nv 1 x 0\n", "t.obj"),
            "line 7: vertex needs 3 numbers, got 'x'");
  EXPECT_EQ(refusal("OFF\r3 1 0\n\r0 0 0\r\n1 0 0\r0 1 0\n\n3 0 1 7\n", "t.off"),
            "line 8: face refers to vertex 7, but the file has 3 vertices (numbered from 0)");
}

}  // namespace
}  // namespace holefill::testing
