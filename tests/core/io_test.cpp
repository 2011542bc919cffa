// Reading and writing: round trips keep positions bit for bit and faces in order; every failure
// names the file and the reason.
#include "holefill/io.h"

#include <gtest/gtest.h>

#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string_view>

#include "holefill/errors.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill {
namespace {
namespace fs = std::filesystem;

class IoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("holefill_io_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

// Something with awkward coordinates: an icosphere has irrational ones.
Mesh sample_mesh() { return testing::make_icosphere(1); }

class RoundTrip : public IoTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(RoundTrip, KeepsPositionsAndFaces) {
  const Mesh original = sample_mesh();
  const fs::path path = dir_ / ("mesh" + GetParam());
  save_mesh(original, path);
  const Mesh loaded = load_mesh(path);
  ASSERT_EQ(loaded.n_vertices(), original.n_vertices());
  ASSERT_EQ(loaded.n_faces(), original.n_faces());
  if (GetParam() == ".obj") {
    // Our OBJ path parses with strtod: 17 significant digits read back bit for bit.
    EXPECT_TRUE(testing::original_part_unchanged(original, loaded));
  } else {
    // OpenMesh's OFF and PLY readers store single precision.
    for (const auto v : original.vertices()) {
      EXPECT_LT((original.point(v) - loaded.point(v)).norm(), 1e-6);
    }
    for (const auto f : original.faces()) {
      auto a = original.fv_range(f).begin();
      auto b = loaded.fv_range(f).begin();
      EXPECT_EQ((*a).idx(), (*b).idx());
    }
  }
  // Nothing but the output file is left in the folder.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip, ::testing::Values(".obj", ".off", ".ply"),
                         [](const auto& info) { return info.param.substr(1); });

TEST_F(IoTest, ObjQuadsAreTriangulatedAndTextureIndicesIgnored) {
  const auto path = write("quad.obj",
                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                          "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1 4/4/1\n");
  LoadReport report;
  const Mesh mesh = load_mesh(path, &report);
  EXPECT_EQ(mesh.n_vertices(), 4u);
  EXPECT_EQ(mesh.n_faces(), 2u);
  EXPECT_EQ(report.polygons_triangulated, 1u);
}

TEST_F(IoTest, NonManifoldFacesAreKeptDetached) {
  // Three triangles on one edge.
  const auto path =
      write("fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  LoadReport report;
  const Mesh mesh = load_mesh(path, &report);
  EXPECT_EQ(mesh.n_faces(), 3u);
  EXPECT_EQ(report.faces_detached, 1u);
  EXPECT_FALSE(report.warnings.empty());
}

void expect_file_error(const fs::path& path, const std::string& reason_part) {
  try {
    load_mesh(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), path);
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find(reason_part), std::string::npos) << e.reason();
  }
}

TEST_F(IoTest, FailuresNameTheFileAndTheReason) {
  expect_file_error(dir_ / "missing.obj", "no such file");
  expect_file_error(dir_, "directory");
  expect_file_error(write("empty.obj", ""), "empty");
  expect_file_error(write("mesh.xyz", "1 2 3\n"), "unsupported");
  expect_file_error(write("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n"), "non-finite");
  expect_file_error(write("points.obj", "v 0 0 0\nv 1 0 0\n"), "no faces");
  expect_file_error(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), "vertex");
  expect_file_error(write("garbage.off", std::string("\x01\x02\x03garbage\xff", 12)), "");
}

TEST_F(IoTest, SaveRefusesUnknownFormatsAndMissingFolders) {
  EXPECT_THROW(save_mesh(sample_mesh(), dir_ / "mesh.xyz"), FileError);
  EXPECT_THROW(save_mesh(sample_mesh(), dir_ / "no" / "such" / "mesh.obj"), FileError);
}

// A mesh built face by face with OpenMesh's add_face, the reference for the loader's direct
// construction of the half-edges.
Mesh built_by_add_face(const Mesh& loaded) {
  Mesh mesh;
  for (const auto v : loaded.vertices()) mesh.add_vertex(loaded.point(v));
  for (const auto f : loaded.faces()) {
    std::vector<VertexHandle> corners;
    for (const auto v : loaded.fv_range(f)) corners.push_back(v);
    EXPECT_TRUE(mesh.add_face(corners).is_valid());
  }
  return mesh;
}

// Each boundary loop as the sequence of its vertices, starting at the smallest, sorted.
std::vector<std::vector<int>> boundary_loops(const Mesh& mesh) {
  std::vector<std::vector<int>> loops;
  for (const auto& hole : find_holes(mesh)) {
    std::vector<int> loop;
    for (const auto v : hole.vertices) loop.push_back(v.idx());
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(loop);
  }
  std::sort(loops.begin(), loops.end());
  return loops;
}

TEST(IoMeshBuilding, LoadedAssetsMatchTheMeshAddFaceBuilds) {
  for (const char* asset : {"bunny.obj", "sphere.obj", "torus.obj"}) {
    SCOPED_TRACE(asset);
    const Mesh loaded = load_mesh(fs::path(HOLEFILL_ASSETS_DIR) / asset);
    EXPECT_TRUE(OpenMesh::Utils::MeshCheckerT<Mesh>(loaded).check());
    const Mesh reference = built_by_add_face(loaded);
    EXPECT_EQ(boundary_loops(loaded), boundary_loops(reference));
    for (const auto v : loaded.vertices()) {
      EXPECT_EQ(loaded.is_boundary(v), reference.is_boundary(v));
    }
  }
}

// Filling adds a patch to a loaded mesh without moving its arrays: growing each into a copy twice
// its size held both copies of the largest at the peak of filling a big mesh. A PLY's positions
// become the mesh's points as they were read (the reader leaves the room), an OBJ's are copied.
TEST_F(IoTest, ALoadedMeshHasRoomForAPatch) {
  const fs::path obj = fs::path(HOLEFILL_ASSETS_DIR) / "bunny.obj";
  const fs::path ply = dir_ / "bunny.ply";
  save_mesh(load_mesh(obj), ply);
  for (const fs::path& path : {obj, ply}) {
    Mesh mesh = load_mesh(path);
    const Hole hole = find_holes(mesh).front();
    const Point* points = mesh.points();
    const auto* edge = &mesh.edge(EdgeHandle(0));
    const auto* face = &mesh.face(FaceHandle(0));
    const VertexHandle centre = mesh.add_vertex(hole.centroid);  // a fan across the largest hole
    for (std::size_t i = 0; i < hole.size(); ++i) {
      ASSERT_TRUE(
          mesh.add_face(hole.vertices[i], hole.vertices[(i + 1) % hole.size()], centre).is_valid());
    }
    EXPECT_EQ(mesh.points(), points) << path;
    EXPECT_EQ(&mesh.edge(EdgeHandle(0)), edge) << path;
    EXPECT_EQ(&mesh.face(FaceHandle(0)), face) << path;
  }
}

// Files are made and handed on in pieces (a megabyte each), never whole: every format's pieces
// are each about a megabyte, together the file save_mesh writes, and it reads back to the same
// mesh.
TEST_F(IoTest, SavedFilesAreMadeInPiecesOfAboutAMegabyte) {
  const Mesh mesh = testing::make_icosphere(6);  // 40,962 vertices: megabytes of text
  for (const std::string ext : {".ply", ".off", ".stl", ".obj"}) {
    const fs::path path = dir_ / ("big" + ext);
    std::vector<std::size_t> piece_sizes;
    std::string pieces;
    write_mesh_pieces(mesh, path, [&](std::string_view piece) {
      piece_sizes.push_back(piece.size());
      pieces += piece;
    });
    EXPECT_GT(piece_sizes.size(), 1u) << ext;
    // A piece is handed on at the first record end past a megabyte, or cut at one (blocks of
    // records).
    EXPECT_LE(*std::max_element(piece_sizes.begin(), piece_sizes.end()), (1u << 20) + 256) << ext;
    save_mesh(mesh, path);
    std::ifstream in(path, std::ios::binary);
    const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(file, pieces) << ext;
    const Mesh back = load_mesh(path);
    ASSERT_EQ(back.n_faces(), mesh.n_faces()) << ext;
    if (ext == ".stl") continue;  // floats, welded
    ASSERT_EQ(back.n_vertices(), mesh.n_vertices()) << ext;
    for (const auto v : mesh.vertices()) ASSERT_EQ(back.point(v), mesh.point(v)) << ext;
  }
}

// OpenMesh's status flags (4 bytes on every element) are not part of a loaded mesh: deleting code
// requests them for its deletion (deletion_flags.h).
TEST(IoMeshBuilding, ALoadedMeshCarriesNoStatusFlags) {
  const Mesh mesh = load_mesh(fs::path(HOLEFILL_ASSETS_DIR) / "bunny.obj");
  EXPECT_FALSE(mesh.has_vertex_status());
  EXPECT_FALSE(mesh.has_edge_status());
  EXPECT_FALSE(mesh.has_halfedge_status());
  EXPECT_FALSE(mesh.has_face_status());
}

// Many open fans around one vertex (a fan of separate triangles): one boundary loop passes the
// hub once per fan, and the structure is consistent. This loaded in quadratic time before
// (80,000 fans: 103 s); bench/io_bench.cpp measures it.
TEST(IoMeshBuilding, ManyPinchedFansAroundOneVertexMakeOneConsistentLoop) {
  constexpr int kFans = 300;
  std::string text = "v 0 0 0\n";
  for (int i = 0; i < kFans; ++i) {
    const double a = 2 * std::numbers::pi * i / kFans, b = a + std::numbers::pi / kFans;
    text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\nv " +
            std::to_string(std::cos(b)) + " " + std::to_string(std::sin(b)) + " 0.1\n";
  }
  for (int i = 0; i < kFans; ++i) {
    text += "f 1 " + std::to_string(2 + 2 * i) + " " + std::to_string(3 + 2 * i) + "\n";
  }
  const Mesh mesh = load_mesh_from_memory(text, "fans.obj");
  EXPECT_TRUE(OpenMesh::Utils::MeshCheckerT<Mesh>(mesh).check());
  EXPECT_EQ(mesh.n_faces(), static_cast<std::size_t>(kFans));
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_EQ(holes[0].size(), static_cast<std::size_t>(3 * kFans));
  EXPECT_TRUE(holes[0].pinched);
  EXPECT_EQ(boundary_loops(mesh), boundary_loops(built_by_add_face(mesh)));
}

}  // namespace
}  // namespace holefill
