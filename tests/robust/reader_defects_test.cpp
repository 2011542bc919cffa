// Reader defects: each test reproduces a file that was misread (silently, or
// with a misleading message) before its fix.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "format_text.h"
#include "holefill/holes.h"
#include "robust_test_util.h"

namespace holefill::testing {
namespace {
namespace fs = std::filesystem;

// The tetrahedron reads as itself: its 4 vertices at their positions, 4 faces, closed.
void expect_tetrahedron(const Mesh& mesh, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(mesh.n_vertices(), 4u);
  EXPECT_EQ(mesh.n_faces(), 4u);
  EXPECT_TRUE(find_holes(mesh).empty());
  for (const auto v : mesh.vertices()) {
    EXPECT_NE(std::find(kTetraPoints.begin(), kTetraPoints.end(), mesh.point(v)),
              kTetraPoints.end());
  }
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    text.replace(at, from.size(), to);
    at += to.size();
  }
  return text;
}

const std::vector<std::pair<std::string, std::string>>& text_files() {
  static const std::vector<std::pair<std::string, std::string>> files{
      {"t.obj", obj_text(kTetraPoints, kTetraFaces)},
      {"t.off", off_text(kTetraPoints, kTetraFaces)},
      {"t.ply", ascii_ply(kTetraPoints, kTetraFaces)},
      {"t.stl", ascii_stl(kTetraPoints, kTetraFaces)},
  };
  return files;
}

TEST(ReaderDefects, AUtf8ByteOrderMarkIsSkippedInEveryTextFormat) {
  for (const auto& [name, text] : text_files()) {
    LoadReport report;
    expect_tetrahedron(load_mesh_from_memory("\xEF\xBB\xBF" + text, name, &report), name);
    EXPECT_TRUE(report.warnings.empty()) << name << ": " << report.warnings.front();
  }
  // The PLY header's magic line behind a BOM, with a binary body.
  expect_tetrahedron(
      load_mesh_from_memory("\xEF\xBB\xBF" + binary_ply(kTetraPoints, kTetraFaces, false), "b.ply"),
      "binary ply");
  // Read by its contents whatever its name says.
  LoadReport report;
  expect_tetrahedron(load_mesh_from_memory("\xEF\xBB\xBF" + ascii_ply(kTetraPoints, kTetraFaces),
                                           "t.obj", &report),
                     "named .obj");
  EXPECT_TRUE(has_warning(report, "read as PLY"));
}

TEST(ReaderDefects, CarriageReturnOnlyLineEndingsRead) {
  for (const auto& [name, text] : text_files()) {
    expect_tetrahedron(load_mesh_from_memory(replace_all(text, "\n", "\r"), name), name + " CR");
    expect_tetrahedron(load_mesh_from_memory(replace_all(text, "\n", "\r\n"), name),
                       name + " CRLF");
  }
}

TEST(ReaderDefects, AnObjCommentEndingInABackslashDoesNotSwallowTheNextLine) {
  std::string text = obj_text(kTetraPoints, kTetraFaces);
  text.insert(text.find("f "), "# a path C:\\models\\\n");
  expect_tetrahedron(load_mesh_from_memory(text, "t.obj"), "comment with backslash");
  // A real continuation still joins its lines.
  const std::string continued =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 \\\n4\n"
      "f 1 4 3\nf 2 3 4\n";
  expect_tetrahedron(load_mesh_from_memory(continued, "t.obj"), "continuation");
}

TEST(ReaderDefects, AsciiPlyIsReadByLinesAndAWrongCountIsRefusedNamingTheLine) {
  const std::string text = ascii_ply(kTetraPoints, kTetraFaces);
  // Line 10 is the first vertex ("0 0 0"), line 14 the first face.
  const std::string extra_value = replace_all(text, "\n0 0 0\n", "\n0 0 0 7\n");
  EXPECT_NE(refusal(extra_value, "t.ply").find("line 10"), std::string::npos)
      << refusal(extra_value, "t.ply");
  const std::string missing_value = replace_all(text, "\n0 0 0\n", "\n0 0\n");
  EXPECT_NE(refusal(missing_value, "t.ply").find("line 10"), std::string::npos)
      << refusal(missing_value, "t.ply");
  std::string long_face = text;
  long_face.replace(long_face.find("3 0 2 1"), 7, "3 0 2 1 3");
  EXPECT_NE(refusal(long_face, "t.ply").find("line 14"), std::string::npos)
      << refusal(long_face, "t.ply");
  // Records split over lines the same way still read; blank lines between records are fine.
  expect_tetrahedron(load_mesh_from_memory(replace_all(text, "\n3 ", "\n\n3 "), "t.ply"), "blank");
}

TEST(ReaderDefects, OffAndPlyWithMoreDataThanTheHeaderCountsWarn) {
  const std::string more_faces = "3 0 1 2\n3 1 2 3\n";
  struct Case {
    std::string name, bytes;
  };
  const std::vector<Case> cases{
      {"t.off", off_text(kTetraPoints, kTetraFaces) + more_faces},
      {"t.ply", ascii_ply(kTetraPoints, kTetraFaces) + more_faces},
      {"b.ply", binary_ply(kTetraPoints, kTetraFaces, false) + std::string(13, '\x01')},
  };
  for (const auto& c : cases) {
    LoadReport report;
    expect_tetrahedron(load_mesh_from_memory(c.bytes, c.name, &report), c.name);
    EXPECT_TRUE(has_warning(report, "after the last")) << c.name;
  }
  // Trailing blank lines and comments are no data.
  LoadReport report;
  load_mesh_from_memory(off_text(kTetraPoints, kTetraFaces) + "\n\n# end\n", "t.off", &report);
  EXPECT_TRUE(report.warnings.empty());
}

TEST(ReaderDefects, ABinaryStlWithTrailingBytesIsReadWithAWarning) {
  std::string bytes = binary_stl(kTetraPoints, kTetraFaces, 4);
  bytes.replace(0, 11, "solid mesh ");  // as many exporters write the binary header
  LoadReport report;
  expect_tetrahedron(load_mesh_from_memory(bytes + "trailing junk", "t.stl", &report), "trailing");
  EXPECT_TRUE(has_warning(report, "13 bytes after the 4 triangles")) << report.warnings.size();
  // Too few bytes for the count: truncated, said in triangles that make sense.
  const std::string reason = refusal(bytes.substr(0, bytes.size() - 10), "t.stl");
  EXPECT_NE(reason.find("truncated"), std::string::npos) << reason;
  EXPECT_NE(reason.find("4 triangles"), std::string::npos) << reason;
}

// Old Blender exporters wrote a bare line of text into the PLY header; such files are read.
TEST(ReaderDefects, ABareTextLineInAPlyHeaderIsSkippedWithAWarning) {
  std::string text = ascii_ply(kTetraPoints, kTetraFaces);
  text.insert(text.find("element"), "Created by Blender3D 247 - www.blender.org\n");
  LoadReport report;
  expect_tetrahedron(load_mesh_from_memory(text, "t.ply", &report), "bare header line");
  EXPECT_TRUE(has_warning(report, "the first is line 3")) << report.warnings.size();
}

// A 2 GiB file (sparse: it takes no disk) must be refused from its first bytes, in a child
// process whose address space (256 MiB) could never hold the file.
TEST(ReaderDefects, AHugeFileIsRefusedFromItsFirstBytesWithoutReadingItWhole) {
  // The child process may address 256 MB, far less than the file: reading it whole would fail.
  // Under the sanitizers (which reserve terabytes of address space at start) only the refusal
  // and its reason are checked.
#if defined(HOLEFILL_SANITIZED_LIBRARY)
  constexpr bool kLimitMemory = false;
#else
  constexpr bool kLimitMemory = true;
#endif
  const fs::path dir = fs::temp_directory_path() / ("holefill_huge_" + std::to_string(getpid()));
  fs::create_directories(dir);
  struct Case {
    std::string name, head, reason;
  };
  const std::vector<Case> cases{
      {"zeros.obj", std::string(16, '\0'), "binary data"},
      {"bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n",
       "lacks an x, y or z"},
      {"big.off", "OFF\n4000000000 1 0\n", "more than the remaining"},
  };
  for (const auto& c : cases) {
    const fs::path file = dir / c.name;
    std::ofstream(file, std::ios::binary) << c.head;
    fs::resize_file(file, std::uintmax_t{2} << 30);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const rlimit limit{256u << 20, 256u << 20};
      if (kLimitMemory) setrlimit(RLIMIT_AS, &limit);
      try {
        load_mesh(file);
      } catch (const FileError& e) {
        _exit(e.reason().find(c.reason) != std::string::npos ? 0 : 1);
      } catch (...) {
        _exit(2);
      }
      _exit(3);
    }
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << c.name << ": child ended with " << status;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace holefill::testing
