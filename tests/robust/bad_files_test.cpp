// Every kind of bad input file: each is refused with a FileError that names the file
// and the problem (and the CLI exits with kBadInput, writing nothing), or read with a repair that
// the LoadReport counts and states (and the CLI goes on).
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <chrono>
#include <cstring>
#include <random>

#include "format_text.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "robust_test_util.h"

namespace holefill::testing {
namespace {
namespace fs = std::filesystem;

const fs::path kData = HOLEFILL_TEST_DATA_DIR;

class BadFiles : public ScratchTest {
 protected:
  // load_mesh refuses the file naming it and the reason; the CLI's info and fill exit with
  // kBadInput, say the same, and write nothing.
  void expect_refused(const fs::path& file, const std::string& reason_part) const {
    SCOPED_TRACE(file.string());
    try {
      load_mesh(file);
      ADD_FAILURE() << "no error for " << file;
    } catch (const FileError& e) {
      EXPECT_EQ(e.path(), file);
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      EXPECT_NE(e.reason().find(reason_part), std::string::npos) << e.reason();
    }
    const std::string out = path("out.obj");
    for (const auto& args : {std::vector<std::string>{"info", file.string()},
                             std::vector<std::string>{"fill", file.string(), "-o", out}}) {
      const CliRun run = run_cli(args);
      EXPECT_EQ(run.code, cli::kBadInput) << run.err;
      EXPECT_NE(run.err.find(file.string()), std::string::npos) << run.err;
      EXPECT_NE(run.err.find(reason_part), std::string::npos) << run.err;
      EXPECT_FALSE(fs::exists(out));
    }
  }
  // The file loads; returns the mesh and its report.
  Mesh expect_loads(const fs::path& file, LoadReport& report) const {
    SCOPED_TRACE(file.string());
    try {
      return load_mesh(file, &report);
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
      return Mesh{};
    }
  }
  // The CLI's fill exits with `code` and, for codes that write, writes the output.
  CliRun expect_fill_exit(const fs::path& file, int code,
                          const std::vector<std::string>& options = {}) const {
    const std::string out = path("filled.obj");
    fs::remove(out);
    std::vector<std::string> args{"fill", file.string(), "-o", out};
    args.insert(args.end(), options.begin(), options.end());
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.code, code) << run.err;
    EXPECT_EQ(fs::exists(out), code == cli::kOk || code == cli::kSomeHolesNotFilled ||
                                   code == cli::kPatchesIntersect);
    return run;
  }
};

TEST_F(BadFiles, EveryFormatAndEncodingReadsTheSameClosedTetrahedron) {
  const std::vector<fs::path> files{
      write("t.obj", obj_text(kTetraPoints, kTetraFaces)),
      write("t.off", off_text(kTetraPoints, kTetraFaces)),
      write("t.ply", ascii_ply(kTetraPoints, kTetraFaces)),
      write("le.ply", binary_ply(kTetraPoints, kTetraFaces, false)),
      write("be.ply", binary_ply(kTetraPoints, kTetraFaces, true)),
      write("a.stl", ascii_stl(kTetraPoints, kTetraFaces)),
      write("b.stl", binary_stl(kTetraPoints, kTetraFaces, 4)),
  };
  for (const auto& file : files) {
    LoadReport report;
    const Mesh mesh = expect_loads(file, report);
    EXPECT_EQ(mesh.n_vertices(), 4u) << file;
    EXPECT_EQ(mesh.n_faces(), 4u) << file;
    EXPECT_TRUE(find_holes(mesh).empty()) << file;
    EXPECT_TRUE(report.warnings.empty()) << file << ": " << report.warnings.front();
    // STL has no vertex list: its vertices come in the order they are first met.
    for (const auto& p : kTetraPoints) {
      const auto vertices = mesh.vertices();
      EXPECT_TRUE(std::any_of(vertices.begin(), vertices.end(), [&](VertexHandle v) {
        return mesh.point(v) == p;
      })) << file;
    }
    expect_fill_exit(file, cli::kOk);
  }
}

TEST_F(BadFiles, EmptyFilesAreRefused) {
  for (const char* name : {"empty.obj", "empty.off", "empty.ply", "empty.stl"}) {
    expect_refused(write(name, ""), "is empty");
  }
  expect_refused(write("blank.obj", "\n  \n# only a comment\n"), "contains no faces");
  expect_refused(write("blank.off", "# nothing\n\n"), "no OFF header");
}

TEST_F(BadFiles, TruncatedFilesAreRefused) {
  const std::string off = off_text(kTetraPoints, kTetraFaces);
  const std::string cut = off.substr(0, off.find("0 1 0"));
  expect_refused(write("cut.off", cut), "more than the remaining 12 bytes of the file can hold");
  expect_refused(write("vertices.off", cut + "# " + std::string(200, '-') + "\n"),
                 "ends after 2 of its 4 vertices");
  expect_refused(write("faces.off", off.substr(0, off.rfind("3 0 3 2"))), "of its 4 faces");
  const std::string obj = obj_text(kTetraPoints, kTetraFaces);
  expect_refused(write("cut.obj", obj.substr(0, obj.find("v 0 0 1") + 5)),
                 "vertex needs 3 numbers");
  for (const bool big_endian : {false, true}) {
    const std::string ply = binary_ply(kTetraPoints, kTetraFaces, big_endian);
    expect_refused(write("cut.ply", ply.substr(0, ply.size() - 7)), "ends in the middle of");
  }
  const std::string ply = ascii_ply(kTetraPoints, kTetraFaces);
  expect_refused(write("cut_ascii.ply", ply.substr(0, ply.size() - 4)),
                 "line 17: 'face' element 3 of 4 has fewer values than the header's properties");
  expect_refused(write("cut_ascii2.ply", ply.substr(0, ply.size() - 2)),
                 "line 17: 'face' element 3 of 4 has fewer values than the header's properties");
  expect_refused(write("header.ply", ply.substr(0, ply.find("end_header"))), "end_header");
  const std::string stl = binary_stl(kTetraPoints, kTetraFaces, 4);
  expect_refused(write("cut.stl", stl.substr(0, stl.size() - 1)), "truncated");
  const std::string text_stl = ascii_stl(kTetraPoints, kTetraFaces);
  expect_refused(write("cut_ascii.stl", text_stl.substr(0, text_stl.rfind("endloop"))),
                 "ends inside a facet");
}

TEST_F(BadFiles, BinaryGarbageIsRefusedWhateverItsExtension) {
  std::mt19937 rng(5);
  std::string garbage(4000, '\0');
  for (auto& c : garbage) c = static_cast<char>(rng());
  garbage[10] = '\0';
  expect_refused(write("garbage.obj", garbage), "not a text OBJ file");
  expect_refused(write("garbage.off", garbage), "not a text OFF file");
  expect_refused(write("garbage.ply", garbage), "does not start with the line 'ply'");
  expect_refused(write("garbage.stl", garbage), "is not an ASCII STL");
  expect_refused(write("garbage.bin", garbage), "unsupported file type '.bin'");
}

TEST_F(BadFiles, WrongExtensionIsReadByTheContentsWithAWarning) {
  const std::vector<std::pair<fs::path, std::string>> files{
      {write("is_off.obj", off_text(kTetraPoints, kTetraFaces)), "contents are OFF"},
      {write("is_ply.off", binary_ply(kTetraPoints, kTetraFaces, false)), "contents are PLY"},
      {write("is_stl.ply", binary_stl(kTetraPoints, kTetraFaces, 4)), "contents are STL"},
      {write("is_obj.stl", obj_text(kTetraPoints, kTetraFaces)), "contents are OBJ"},
      {write("mesh.txt", off_text(kTetraPoints, kTetraFaces)), "extension '.txt'"},
      {write("no_extension", ascii_stl(kTetraPoints, kTetraFaces)), "contents are STL"},
  };
  for (const auto& [file, warning] : files) {
    LoadReport report;
    const Mesh mesh = expect_loads(file, report);
    EXPECT_EQ(mesh.n_faces(), 4u) << file;
    EXPECT_TRUE(has_warning(report, warning)) << file;
    const CliRun run = expect_fill_exit(file, cli::kOk);
    EXPECT_NE(run.err.find(warning), std::string::npos) << run.err;
  }
  expect_refused(write("points.xyz", "1 2 3\n4 5 6\n"), "unsupported file type '.xyz'");
}

TEST_F(BadFiles, ADirectoryIsRefused) {
  fs::create_directories(dir_ / "folder.obj");
  expect_refused(dir_ / "folder.obj", "is a directory");
}

TEST_F(BadFiles, AMissingPathIsRefused) {
  expect_refused(dir_ / "missing.obj", "no such file");
  expect_refused(dir_ / "no" / "such" / "folder" / "mesh.ply", "no such file");
}

// A symbolic link loop was reported as "no such file"; the system's reason is named instead.
TEST_F(BadFiles, ASymbolicLinkLoopIsRefusedWithTheSystemsReason) {
  fs::create_symlink("b.obj", dir_ / "a.obj");
  fs::create_symlink("a.obj", dir_ / "b.obj");
  expect_refused(dir_ / "a.obj", "cannot be read (Too many levels of symbolic links)");
}

// What load_mesh says of `file` when run as user `uid` in a child process (root reads any file,
// so it must give that up first): the error's path and reason, or "loaded".
std::string load_as_user(const fs::path& file, uid_t uid) {
  int channel[2];
  if (pipe(channel) != 0) return "no pipe";
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    std::string said = "could not give up root";
    if (setgid(uid) == 0 && setuid(uid) == 0) {
      try {
        load_mesh(file);
        said = "loaded";
      } catch (const FileError& e) {
        said = e.path().string() + ": " + e.reason();
      }
    }
    const bool written =
        write(channel[1], said.data(), said.size()) == static_cast<ssize_t>(said.size());
    _exit(written ? 0 : 1);
  }
  close(channel[1]);
  std::string said;
  char buffer[512];
  for (ssize_t n; (n = read(channel[0], buffer, sizeof buffer)) > 0;) said.append(buffer, n);
  close(channel[0]);
  int status = 0;
  waitpid(child, &status, 0);
  return said;
}

TEST_F(BadFiles, AnUnreadableFileIsRefused) {
  const fs::path file = write("locked.obj", obj_text(kTetraPoints, kTetraFaces));
  fs::permissions(file, fs::perms::none);
  const std::string reason = "cannot be opened for reading (Permission denied)";
  if (geteuid() != 0) {
    expect_refused(file, reason);
    return;
  }
  constexpr uid_t kNobody = 65534;
  EXPECT_EQ(load_as_user(file, kNobody), file.string() + ": " + reason);
}

TEST_F(BadFiles, HugeHeaderCountsAreRefusedWithoutAllocatingForThem) {
  const auto start = std::chrono::steady_clock::now();
  expect_refused(write("huge.off", "OFF\n99999999999 1 0\n0 0 0\n3 0 0 0\n"),
                 "the header promises 99999999999 vertices");
  expect_refused(write("huge_faces.off", "OFF\n3 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                 "the header promises 3 vertices and 4000000000 faces");
  expect_refused(write("huge.ply",
                       "ply\nformat binary_little_endian 1.0\nelement vertex 4294967295\n"
                       "property float x\nproperty float y\nproperty float z\nend_header\n" +
                           std::string(24, '\0')),
                 "the header promises 4294967295 'vertex' elements");
  // Found by fuzzing: four billion empty faces took minutes and gigabytes.
  expect_refused(write("empty_records.ply",
                       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                       "property float y\nproperty float z\nelement face 4294967295\n"
                       "end_header\n0 0 0\n1 0 0\n0 1 0\n"),
                 "the header gives the 'face' element 4294967295 records but no properties");
  expect_refused(write("count_garbage.ply",
                       "ply\nformat ascii 1.0\nelement vertex 3 list uchar int x\nend_header\n"),
                 "unexpected text after the element count");
  std::string list = binary_ply(kTetraPoints, {{0, 1, 2}}, false);
  list[list.size() - 4 * 3 - 4 - 1] = static_cast<char>(250);  // a face claiming 250 corners
  expect_refused(write("huge_list.ply", list), "a list claims 250 items");
  expect_refused(write("huge.stl", binary_stl(kTetraPoints, kTetraFaces, 0xFFFFFFFFu)),
                 "its header counts 4294967295 triangles");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST_F(BadFiles, IndicesOutOfRangeAreRefused) {
  expect_refused(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
                 "line 4: face refers to vertex 9, but the file has 3 vertices");
  expect_refused(write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "vertex index 0");
  expect_refused(write("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"),
                 "reaches before the first vertex");
  LoadReport report;
  EXPECT_EQ(load_mesh(write("comments.obj", "v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nf 1 2 3 # one\n"),
                      &report)
                .n_faces(),
            1u);
  expect_refused(write("letters.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n"),
                 "is not a vertex index");
  expect_refused(write("overflow.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n"),
                 "is not a vertex index");
  expect_refused(write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                 "face refers to vertex 7, but the file has 3 vertices");
  expect_refused(write("negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"),
                 "face refers to vertex -1");
  expect_refused(write("range.ply", binary_ply(kTetraPoints, {{0, 1, 100}}, false)),
                 "refers to vertex 100, but the file has 4 vertices");
  expect_refused(write("negative.ply", binary_ply(kTetraPoints, {{0, -5, 1}}, true)),
                 "invalid vertex index");
}

TEST_F(BadFiles, NonFiniteCoordinatesAreRefused) {
  expect_refused(write("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n"),
                 "line 2: vertex 2 has a non-finite (NaN or infinite) coordinate");
  expect_refused(write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n"), "non-finite");
  expect_refused(write("overflow.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"), "non-finite");
  expect_refused(write("nan.off", "OFF\n3 1 0\n0 0 0\nNaN 0 0\n0 1 0\n3 0 1 2\n"), "non-finite");
  std::vector<Point> points = kTetraPoints;
  points[2][1] = std::numeric_limits<double>::quiet_NaN();
  expect_refused(write("nan.ply", binary_ply(points, kTetraFaces, false)), "non-finite");
  points[2][1] = std::numeric_limits<double>::infinity();
  expect_refused(write("inf.stl", binary_stl(points, kTetraFaces, 4)), "non-finite");
  expect_refused(write("inf.ply", ascii_ply(points, kTetraFaces)), "non-finite");
}

TEST_F(BadFiles, PolygonsAreTriangulatedWithoutFolding) {
  // A quad and an L-shaped (non-convex) hexagon side by side in the plane z = 0.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "v 2 0 0\nv 4 0 0\nv 4 1 0\nv 3 1 0\nv 3 3 0\nv 2 3 0\n"
      "f 1 2 3 4\nf 5 6 7 8 9 10\n";
  for (const auto& file :
       {write("polygons.obj", obj),
        write("polygons.off",
              "OFF\n10 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n4 0 0\n4 1 0\n3 1 0\n3 3 0\n2 3 0\n"
              "4 0 1 2 3\n6 4 5 6 7 8 9\n")}) {
    LoadReport report;
    const Mesh mesh = expect_loads(file, report);
    EXPECT_EQ(report.polygons_triangulated, 2u);
    EXPECT_TRUE(has_warning(report, "2 polygons with more than 3 corners were triangulated"));
    EXPECT_EQ(mesh.n_faces(), 2u + 4u);
    double area = 0.0;
    for (const auto f : mesh.faces()) {
      const Point n = mesh.calc_face_normal(f);
      EXPECT_GT(n[2], 0.99) << "a folded triangle in " << file;
      std::vector<Point> p;
      for (const auto v : mesh.fv_range(f)) p.push_back(mesh.point(v));
      area += 0.5 * OpenMesh::cross(p[1] - p[0], p[2] - p[0]).norm();
    }
    EXPECT_NEAR(area, 1.0 + 4.0, 1e-12);  // nothing overlaps: the areas add up
    // A flat sheet's rim is not a hole: a patch would cover its back (it once was, exit 5).
    const CliRun run = expect_fill_exit(file, cli::kOk);
    EXPECT_NE(run.err.find("loop 0 is not a hole but the rim of a flat piece of 4 faces"),
              std::string::npos)
        << run.err;
  }
}

TEST_F(BadFiles, ObjTextureAndNormalIndicesAndSeamsKeepOneVertexPerPosition) {
  // A cube written like an exporter does: per-face normals, UV seams, groups, materials, CRLF.
  const fs::path file = kData / "textured_cube.obj";
  LoadReport report;
  const Mesh mesh = expect_loads(file, report);
  EXPECT_EQ(mesh.n_vertices(), 8u);
  EXPECT_EQ(mesh.n_faces(), 12u);
  EXPECT_EQ(report.polygons_triangulated, 6u);
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_EQ(report.faces_flipped, 0u);
  EXPECT_EQ(report.elements_ignored, 1u);  // its one polyline
  const CliRun run = run_cli({"info", file.string()});
  EXPECT_EQ(run.code, cli::kOk);
  EXPECT_NE(run.out.find("8 vertices, 12 faces, 1 components, 0 holes"), std::string::npos)
      << run.out;
}

TEST_F(BadFiles, ExporterStyleOffWithColoursAndCommentsReads) {
  LoadReport report;
  const Mesh mesh = expect_loads(kData / "colored_tetra.off", report);
  EXPECT_EQ(mesh.n_faces(), 4u);
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_TRUE(report.warnings.empty());
}

TEST_F(BadFiles, DuplicateVerticesAreKeptAndCountedAndStlIsWelded) {
  // Two triangles of a square, each with its own copies of the shared corners (a "soup").
  const fs::path soup =
      write("soup.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 4 5 6\n");
  LoadReport report;
  const Mesh mesh = expect_loads(soup, report);
  EXPECT_EQ(mesh.n_vertices(), 6u);
  EXPECT_EQ(report.duplicate_positions, 2u);
  EXPECT_TRUE(has_warning(report, "2 vertices have exactly the position of another vertex"));
  // Unstitched, each triangle is alone: its boundary is not a hole but its own back.
  const CliRun run = expect_fill_exit(soup, cli::kOk, {"--no-stitch"});
  EXPECT_NE(run.err.find("loop 1 is not a hole but the rim of a lone triangle (face 2)"),
            std::string::npos)
      << run.err;
  // Stitched, they are one flat square, whose rim is not a hole either.
  EXPECT_NE(expect_fill_exit(soup, cli::kOk).err.find("the rim of a flat piece of 2 faces"),
            std::string::npos);

  // STL stores corners by value: equal positions are one vertex.
  LoadReport stl_report;
  const Mesh welded =
      expect_loads(write("tetra.stl", ascii_stl(kTetraPoints, kTetraFaces)), stl_report);
  EXPECT_EQ(welded.n_vertices(), 4u);
  EXPECT_EQ(stl_report.duplicate_positions, 0u);
}

TEST_F(BadFiles, DegenerateAndDuplicateFacesAreDroppedAndSaid) {
  const fs::path file = write(
      "dirty.obj", obj_text(kTetraPoints, kTetraFaces) + "f 1 1 2\nf 1 2\nf 1 3 2\nf 3 2 1\n");
  LoadReport report;
  const Mesh mesh = expect_loads(file, report);
  EXPECT_EQ(mesh.n_faces(), 4u);
  EXPECT_EQ(report.degenerate_faces_dropped, 2u);
  EXPECT_EQ(report.duplicate_faces_dropped, 2u);
  EXPECT_TRUE(find_holes(mesh).empty());
  expect_fill_exit(file, cli::kOk);
}

}  // namespace
}  // namespace holefill::testing
