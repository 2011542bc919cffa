// PLY properties as a header declares them: each position axis keeps its own type through a
// fill (issue 32, #6), a repeated name is not dropped silently (#12), and an element with more
// properties than the reader's limit is refused naming it (#5).
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "holefill/attributes.h"
#include "io/ply_header.h"
#include "robust_test_util.h"

namespace holefill::testing {
namespace {

// A triangle in ASCII PLY whose vertex element declares `properties` (lines without "property ")
// and whose three records are `records`.
std::string triangle_ply(const std::vector<std::string>& properties,
                         const std::vector<std::string>& records) {
  std::string text = "ply\nformat ascii 1.0\nelement vertex 3\n";
  for (const auto& property : properties) text += "property " + property + "\n";
  text += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& record : records) text += record + "\n";
  return text + "3 0 1 2\n";
}

TEST(PlyProperties, EachPositionAxisKeepsItsOwnTypeWhenWrittenBack) {
  // z double declared first, x float last: all three were written as float (the last axis read
  // set the type), so every z was rounded to a float, with exit 0 and no warning.
  const std::string text = triangle_ply({"double z", "float y", "float x"},
                                        {"0.1000000000001 0 0", "0.25 0 1", "0.5 1 0"});
  const Mesh mesh = load_mesh_from_memory(text, "t.ply");
  const AttributeLayout layout = attribute_layout(mesh);
  EXPECT_EQ(layout.position_types,
            (std::array{ScalarType::Float32, ScalarType::Float32, ScalarType::Float64}));
  const std::string written = mesh_to_bytes(mesh, "out.ply");
  EXPECT_NE(written.find("property float x\nproperty float y\nproperty double z\n"),
            std::string::npos)
      << written;
  const Mesh again = load_mesh_from_memory(written, "out.ply");
  ASSERT_EQ(again.n_vertices(), 3u);
  for (const auto v : mesh.vertices()) {
    EXPECT_EQ(again.point(v), mesh.point(v)) << v.idx();
  }
  EXPECT_EQ(again.point(VertexHandle(0))[2], 0.1000000000001);

  // An integer axis is written as double (new positions would not fit it); the others keep
  // their types.
  const Mesh integer = load_mesh_from_memory(
      triangle_ply({"int x", "float y", "double z"}, {"0 0 0", "1 0 0", "0 1 0"}), "t.ply");
  EXPECT_EQ(attribute_layout(integer).position_types,
            (std::array{ScalarType::Float64, ScalarType::Float32, ScalarType::Float64}));
}

TEST(PlyProperties, ARepeatedPropertyNameIsNamedInAWarningAndTheFirstKept) {
  // The second 'red' was dropped with no word; a second 'x' is read past as well (the first is
  // the position).
  const std::string text =
      triangle_ply({"float x", "float y", "float z", "uchar red", "uchar red", "float x"},
                   {"0 0 0 10 20 7", "1 0 0 11 21 8", "0 1 0 12 22 9"});
  LoadReport report;
  const Mesh mesh = load_mesh_from_memory(text, "t.ply", &report);
  EXPECT_TRUE(has_warning(report,
                          "2 properties repeat an earlier property's name and were not "
                          "kept (the first of that name is): 'red' of the 'vertex' "
                          "element at line 8"))
      << (report.warnings.empty() ? "" : report.warnings.front());
  const AttributeLayout layout = attribute_layout(mesh);
  ASSERT_EQ(layout.vertex.size(), 1u);
  EXPECT_EQ(layout.vertex[0].name, "red");
  const auto red = vertex_attribute(mesh, "red");
  for (int v = 0; v < 3; ++v) {
    EXPECT_EQ(mesh.property(red, VertexHandle(v)), 10.0 + v);
    EXPECT_EQ(mesh.point(VertexHandle(v))[0], v == 1 ? 1.0 : 0.0);
  }
}

TEST(PlyProperties, AnElementWithTooManyPropertiesIsRefusedNamingTheLimit) {
  // 100,000 properties took over 120 s (OpenMesh passes over every property to add or find
  // one); the limit refuses such a header at once and the limit's own count is read.
  auto with_extra = [](std::size_t extra) {
    std::vector<std::string> properties{"float x", "float y", "float z"};
    std::string values;
    for (std::size_t i = 0; i < extra; ++i) {
      properties.push_back("uchar p" + std::to_string(i));
      values += ' ' + std::to_string(i % 256);
    }
    return triangle_ply(properties, {"0 0 0" + values, "1 0 0" + values, "0 1 0" + values});
  };
  const std::string refused = refusal(with_extra(100000), "t.ply");
  EXPECT_NE(refused.find("line " + std::to_string(4 + io::kMaxPlyProperties) +
                         ": the 'vertex' element has more than " +
                         std::to_string(io::kMaxPlyProperties) + " properties"),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find("kMaxPlyProperties"), std::string::npos) << refused;

  const Mesh mesh = load_mesh_from_memory(with_extra(io::kMaxPlyProperties - 3), "t.ply");
  const AttributeLayout layout = attribute_layout(mesh);
  ASSERT_EQ(layout.vertex.size(), io::kMaxPlyProperties - 3);
  const auto handles = vertex_attributes(mesh, layout.vertex);
  for (std::size_t i = 0; i < handles.size(); i += 997) {
    EXPECT_EQ(layout.vertex[i].name, "p" + std::to_string(i));
    EXPECT_EQ(mesh.property(handles[i], VertexHandle(2)), static_cast<double>(i % 256));
  }
}

}  // namespace
}  // namespace holefill::testing
