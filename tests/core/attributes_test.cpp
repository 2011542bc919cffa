// Attributes a file carries survive loading, filling and saving: originals keep their
// values bit for bit, new vertices get values from the boundary, and each format writes back what
// it can hold, PLY in its own encoding and types.
#include "holefill/attributes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill {
namespace {
namespace fs = std::filesystem;

// An icosphere with a hole at its top, as a PLY of `format` ("ascii", "binary_little_endian",
// "binary_big_endian") with float positions, uchar colours that vary with the position, a float
// quality, and a per-face uchar flag (3 on faces with x > 0, 9 elsewhere).
std::string coloured_sphere_ply(const std::string& format) {
  const Mesh mesh =
      testing::without_faces(testing::make_icosphere(3), [](const Point& c) { return c[2] > 0.8; });
  std::string out = "ply\nformat " + format + " 1.0\nelement vertex " +
                    std::to_string(mesh.n_vertices()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
                    "property uchar green\nproperty uchar blue\nproperty float quality\n"
                    "element face " +
                    std::to_string(mesh.n_faces()) +
                    "\nproperty list uchar int vertex_indices\nproperty uchar flags\nend_header\n";
  const bool ascii = format == "ascii";
  const bool big = format == "binary_big_endian";
  auto put = [&](auto value) {
    if (ascii) {
      out += std::to_string(value) + ' ';
      return;
    }
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    if (big != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof value);
    out.append(raw, sizeof value);
  };
  auto end_line = [&] {
    if (ascii) out.back() = '\n';
  };
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    for (int axis = 0; axis < 3; ++axis) put(static_cast<float>(p[axis]));
    for (int axis = 0; axis < 3; ++axis) {
      put(static_cast<unsigned char>(std::lround(127.5 * (p[axis] + 1.0))));
    }
    put(static_cast<float>(p[2] * 0.5));
    end_line();
  }
  for (const auto f : mesh.faces()) {
    put(static_cast<unsigned char>(3));
    for (const auto v : mesh.fv_range(f)) put(static_cast<int>(v.idx()));
    put(static_cast<unsigned char>(mesh.calc_face_centroid(f)[0] > 0 ? 3 : 9));
    end_line();
  }
  return out;
}

class Attributes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("holefill_attributes_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }
  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  fs::path dir_;
};

double value(const Mesh& mesh, const char* name, VertexHandle v) {
  return mesh.property(vertex_attribute(mesh, name), v);
}

// Every vertex attribute and position of `before` is in `after`, same index, same bits.
void expect_originals_kept(const Mesh& before, const Mesh& after) {
  const AttributeLayout layout = attribute_layout(before);
  for (const auto v : before.vertices()) {
    ASSERT_EQ(before.point(v), after.point(v));
    for (const auto& a : layout.vertex) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(value(before, a.name.c_str(), v)),
                std::bit_cast<std::uint64_t>(value(after, a.name.c_str(), v)))
          << a.name << " of vertex " << v.idx();
    }
  }
  for (const auto f : before.faces()) {
    for (const auto& a : layout.face) {
      ASSERT_EQ(before.property(face_attribute(before, a.name), f),
                after.property(face_attribute(after, a.name), f));
    }
  }
}

TEST_F(Attributes, PlyRoundTripsKeepEveryPropertyInItsEncodingAndTypes) {
  for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    const Mesh original = load_mesh(write("in.ply", coloured_sphere_ply(format)));
    const AttributeLayout layout = attribute_layout(original);
    ASSERT_EQ(layout.vertex.size(), 4u);
    EXPECT_EQ(layout.vertex[0].name, "red");
    EXPECT_EQ(layout.vertex[0].type, ScalarType::UInt8);
    EXPECT_EQ(layout.vertex[3].type, ScalarType::Float32);
    ASSERT_EQ(layout.face.size(), 1u);
    EXPECT_EQ(layout.position_types,
              (std::array{ScalarType::Float32, ScalarType::Float32, ScalarType::Float32}));
    save_mesh(original, dir_ / "out.ply");
    const std::string written = read(dir_ / "out.ply");
    EXPECT_NE(written.find("format " + format + " 1.0"), std::string::npos);
    EXPECT_NE(written.find("property float x\n"), std::string::npos);
    EXPECT_NE(written.find("property uchar red\n"), std::string::npos);
    EXPECT_NE(written.find("property uchar flags\n"), std::string::npos);
    const Mesh again = load_mesh(dir_ / "out.ply");
    expect_originals_kept(original, again);
    save_mesh(again, dir_ / "again.ply");
    EXPECT_EQ(read(dir_ / "again.ply"), written);  // a fixed point: nothing drifts
  }
}

TEST_F(Attributes, APlyWithNothingButPositionsAndFacesKeepsItsEncodingAndTypes) {
  // A binary big-endian PLY of float positions and uint indices, with no other property: it is
  // written back the same way, not as ASCII doubles (73 MB for a 27 MB file of 1.4M faces).
  const Mesh sphere =
      testing::without_faces(testing::make_icosphere(2), [](const Point& c) { return c[2] > 0.8; });
  std::string in =
      "ply\nformat binary_big_endian 1.0\nelement vertex " + std::to_string(sphere.n_vertices()) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(sphere.n_faces()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  auto put = [&in](auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    if constexpr (std::endian::native == std::endian::little) std::reverse(raw, raw + sizeof value);
    in.append(raw, sizeof value);
  };
  for (const auto v : sphere.vertices()) {
    for (int axis = 0; axis < 3; ++axis) put(static_cast<float>(sphere.point(v)[axis]));
  }
  for (const auto f : sphere.faces()) {
    put(static_cast<unsigned char>(3));
    for (const auto v : sphere.fv_range(f)) put(static_cast<std::uint32_t>(v.idx()));
  }
  Mesh mesh = load_mesh(write("in.ply", in));
  const Mesh before = mesh;
  fill_holes(mesh, find_holes(mesh), FillOptions{}, HoleSelection{});
  save_mesh(mesh, dir_ / "out.ply");
  const std::string written = read(dir_ / "out.ply");
  EXPECT_EQ(written.find("format binary_big_endian 1.0\n"), 4u) << written.substr(0, 200);
  EXPECT_NE(written.find("property float x\n"), std::string::npos);
  EXPECT_NE(written.find("property list uchar uint vertex_indices\n"), std::string::npos);
  const Mesh again = load_mesh(dir_ / "out.ply");
  EXPECT_EQ(again.n_faces(), mesh.n_faces());
  expect_originals_kept(before, again);
  // An OBJ still becomes an ASCII PLY of doubles, the default.
  save_mesh(load_mesh(write("in.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")), dir_ / "obj.ply");
  EXPECT_EQ(read(dir_ / "obj.ply").find("format ascii 1.0\n"), 4u);
}

TEST_F(Attributes, AFillKeepsOriginalValuesAndGivesNewVerticesValuesFromTheBoundary) {
  const Mesh before = load_mesh(write("in.ply", coloured_sphere_ply("binary_little_endian")));
  Mesh mesh = before;
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 1u);
  double low = 1e9, high = -1e9;
  for (const auto v : holes[0].vertices) {
    low = std::min(low, value(mesh, "red", v));
    high = std::max(high, value(mesh, "red", v));
  }
  const auto fills = fill_holes(mesh, holes, FillOptions{});
  ASSERT_FALSE(fills[0].failed());
  ASSERT_FALSE(fills[0].patch.new_vertices.empty());
  expect_originals_kept(before, mesh);
  // Harmonic values obey the maximum principle: within the boundary's range, and not all equal
  // to one boundary value (the colours vary around the hole).
  double new_low = 1e9, new_high = -1e9;
  for (const auto v : fills[0].patch.new_vertices) {
    const double red = value(mesh, "red", v);
    EXPECT_GE(red, low - 1e-9);
    EXPECT_LE(red, high + 1e-9);
    new_low = std::min(new_low, red);
    new_high = std::max(new_high, red);
  }
  EXPECT_LT(low, high);
  // Faces along the hole: x > 0 (flag 3) and x < 0 (flag 9) equally; the patch takes one of them.
  const auto flags = face_attribute(mesh, "flags");
  for (const auto f : fills[0].patch.faces) {
    const double flag = mesh.property(flags, f);
    EXPECT_TRUE(flag == 3.0 || flag == 9.0) << flag;
  }
  // Written back as floats and uchars: the originals unchanged, new colours rounded in range.
  save_mesh(mesh, dir_ / "filled.ply");
  const Mesh reloaded = load_mesh(dir_ / "filled.ply");
  expect_originals_kept(before, reloaded);
  EXPECT_EQ(reloaded.n_vertices(), mesh.n_vertices());
  EXPECT_TRUE(find_holes(reloaded).empty());
  for (const auto v : fills[0].patch.new_vertices) {
    const double red = value(reloaded, "red", v);
    EXPECT_EQ(red, std::round(red));
    EXPECT_GE(red, std::floor(low));
    EXPECT_LE(red, std::ceil(high));
    EXPECT_EQ(reloaded.point(v)[0], static_cast<double>(static_cast<float>(mesh.point(v)[0])));
  }
}

TEST_F(Attributes, NormalsOfNewVerticesAreTheNewGeometrysUnitNormals) {
  Mesh mesh = load_mesh(write("in.ply", coloured_sphere_ply("ascii")));
  AttributeLayout layout = attribute_layout(mesh);
  layout.vertex.push_back({"nx", ScalarType::Float32});
  layout.vertex.push_back({"ny", ScalarType::Float32});
  layout.vertex.push_back({"nz", ScalarType::Float32});
  set_attribute_layout(mesh, layout);
  const auto fills = fill_holes(mesh, find_holes(mesh), FillOptions{});
  ASSERT_FALSE(fills[0].failed());
  for (const auto v : fills[0].patch.new_vertices) {
    const Point normal(value(mesh, "nx", v), value(mesh, "ny", v), value(mesh, "nz", v));
    EXPECT_NEAR(normal.norm(), 1.0, 1e-9);
    for (const auto f : mesh.vf_range(v)) EXPECT_GT(normal | mesh.calc_face_normal(f), 0.0);
    EXPECT_GT(normal[2], 0.8);  // the cap over the sphere's top faces up
  }
}

TEST_F(Attributes, OffColoursOfVerticesAndFacesRoundTrip) {
  const std::string off =
      "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 9 9 9 128\n"
      "3 0 2 1 10 20 30\n3 0 1 3 10 20 30\n3 0 3 2 40 50 60\n3 1 2 3 40 50 60\n";
  const Mesh mesh = load_mesh(write("in.off", off));
  const AttributeLayout layout = attribute_layout(mesh);
  ASSERT_EQ(layout.vertex.size(), 4u);  // red green blue alpha
  ASSERT_EQ(layout.face.size(), 3u);
  EXPECT_EQ(value(mesh, "alpha", VertexHandle(3)), 128.0);
  save_mesh(mesh, dir_ / "out.off");
  EXPECT_EQ(read(dir_ / "out.off"),
            "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
            "0 0 1 9 9 9 128\n3 0 2 1 10 20 30\n3 0 1 3 10 20 30\n3 0 3 2 40 50 60\n"
            "3 1 2 3 40 50 60\n");
}

TEST_F(Attributes, ObjVertexColoursRoundTripBesideMaterialsAndUvs) {
  const std::string obj =
      "mtllib a.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 0 0 1 0.25 0.5 0.75\n"
      "vt 0 0\nusemtl red\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  LoadReport report;
  const Mesh mesh = load_mesh(write("in.obj", obj), &report);
  EXPECT_EQ(value(mesh, "blue", VertexHandle(3)), 0.75);
  EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
  save_mesh(mesh, dir_ / "out.obj");
  expect_originals_kept(mesh, load_mesh(dir_ / "out.obj"));
  const std::string written = read(dir_ / "out.obj");
  EXPECT_NE(written.find("v 0 0 1 0.25 0.5 0.75\n"), std::string::npos);
  EXPECT_NE(written.find("mtllib a.mtl\n"), std::string::npos);
  EXPECT_NE(written.find("vt 0 0\nusemtl red\nf "), std::string::npos) << written;
}

TEST_F(Attributes, VertexColoursForDisplayAreScaledByTheirType) {
  const Mesh uchar_colours = load_mesh(write("in.ply", coloured_sphere_ply("ascii")));
  std::vector<std::array<float, 3>> rgb;
  ASSERT_TRUE(vertex_colors(uchar_colours, rgb));
  ASSERT_EQ(rgb.size(), uchar_colours.n_vertices());
  const VertexHandle v(5);
  EXPECT_FLOAT_EQ(rgb[5][0], static_cast<float>(value(uchar_colours, "red", v) / 255.0));
  const Mesh float_colours =
      load_mesh(write("in.obj", "v 0 0 0 0.5 0.25 1\nv 1 0 0 0 0 0\nv 0 1 0 1 1 1\nf 1 2 3\n"));
  ASSERT_TRUE(vertex_colors(float_colours, rgb));
  EXPECT_FLOAT_EQ(rgb[0][1], 0.25f);
  EXPECT_FALSE(vertex_colors(testing::make_icosphere(0), rgb));
  EXPECT_TRUE(rgb.empty());
}

TEST_F(Attributes, StlIsWrittenBinaryAndReadsBack) {
  const Mesh mesh = testing::make_icosphere(1);
  save_mesh(mesh, dir_ / "out.stl");
  EXPECT_EQ(fs::file_size(dir_ / "out.stl"), 84 + 50 * mesh.n_faces());
  const Mesh again = load_mesh(dir_ / "out.stl");
  EXPECT_EQ(again.n_faces(), mesh.n_faces());
  EXPECT_EQ(again.n_vertices(), mesh.n_vertices());  // welded back
  EXPECT_TRUE(find_holes(again).empty());
}

}  // namespace
}  // namespace holefill
