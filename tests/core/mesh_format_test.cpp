// MeshFormat: a path's extension names a format in any case, one decision that reading, writing
// and the apps share; writing dispatches on it and refuses, naming the file, what names none.
#include "holefill/mesh_format.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "holefill/errors.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill {
namespace {
namespace fs = std::filesystem;

std::string upper(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}

TEST(MeshFormat, TheExtensionNamesTheFormatInAnyCase) {
  EXPECT_EQ(format_from_path("folder/mesh.obj"), MeshFormat::Obj);
  EXPECT_EQ(format_from_path("MESH.OFF"), MeshFormat::Off);
  EXPECT_EQ(format_from_path("scan.Ply"), MeshFormat::Ply);
  EXPECT_EQ(format_from_path("part.sTl"), MeshFormat::Stl);
  EXPECT_EQ(format_from_path("points.xyz"), std::nullopt);
  EXPECT_EQ(format_from_path("ply"), std::nullopt);   // a name, no extension
  EXPECT_EQ(format_from_path(".ply"), std::nullopt);  // a hidden file's name, no extension
  EXPECT_EQ(format_from_path("mesh.ply.gz"), std::nullopt);
  EXPECT_EQ(format_from_path("mesh.obj/"), std::nullopt);  // a folder
  EXPECT_EQ(lowercase_extension("a/Mesh.XyZ"), ".xyz");
  EXPECT_EQ(lowercase_extension("a/mesh"), "");
  const std::vector<std::string> all{".obj", ".off", ".ply", ".stl"};
  EXPECT_EQ(readable_extensions(), all);
  EXPECT_EQ(writable_extensions(), all);
  for (const MeshFormat format : kMeshFormats) {
    const std::string ext(extension_of(format));
    EXPECT_EQ(format_from_path("m" + ext), format);
    EXPECT_EQ(format_from_path("M" + upper(ext)), format);
    EXPECT_EQ("." + std::string(name_of(format)), ext);
  }
}

// Each format's bytes are its own (no other extension falls back on PLY), the same in either
// case of the extension and for the format given whatever the name, and read back as it: the
// reader tells them apart by their contents alone.
TEST(MeshFormat, WritingDispatchesOnTheFormat) {
  const Mesh mesh = testing::make_icosphere(1);
  std::set<std::string> seen;
  for (const MeshFormat format : kMeshFormats) {
    const std::string ext(extension_of(format));
    const std::string bytes = mesh_to_bytes(mesh, "mesh" + ext);
    EXPECT_TRUE(seen.insert(bytes).second) << ext;
    EXPECT_EQ(mesh_to_bytes(mesh, "MESH" + upper(ext)), bytes) << ext;
    std::string given;
    write_mesh_pieces(mesh, format, "mesh.dat", [&](std::string_view piece) { given += piece; });
    EXPECT_EQ(given, bytes) << ext;
    LoadReport report;
    const Mesh back = load_mesh_from_memory(bytes, "mesh.dat", &report);
    EXPECT_EQ(report.format, name_of(format));
    EXPECT_EQ(back.n_faces(), mesh.n_faces()) << ext;
    EXPECT_EQ(attributes_not_written(mesh, format, "mesh.dat"),
              attributes_not_written(mesh, "mesh" + ext));
  }
}

TEST(MeshFormat, AnExtensionThatNamesNoFormatIsRefusedNamingTheFile) {
  const fs::path dir =
      fs::temp_directory_path() /
      ("holefill_mesh_format_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::create_directories(dir);
  const Mesh mesh = testing::make_icosphere(1);
  for (const std::string name : {"mesh.XYZ", "mesh"}) {
    const std::string ext = lowercase_extension(name);
    try {
      save_mesh(mesh, dir / name);
      ADD_FAILURE() << name << " was written";
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find((dir / name).string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("cannot write '" + ext +
                                           "' files (use .obj, .off, .ply or .stl)"),
                std::string::npos)
          << e.what();
    }
    EXPECT_THROW(mesh_to_bytes(mesh, name), FileError);
  }
  EXPECT_TRUE(fs::is_empty(dir));  // nothing begun
  fs::remove_all(dir);
}

}  // namespace
}  // namespace holefill
