// Loading a dirty soup gives one mesh whatever the file format, and that mesh is the one OpenMesh's
// add_face builds from its faces: the loader's linear-time repairs and its direct construction of
// the half-edges (core/src/io) against the library's own construction, on one thread and two.
// The construction's own contract: mesh_assembly_contract_test.cpp.
#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>

#include "dirty_meshes.h"
#include "holefill/holes.h"
#include "holefill/obj_attributes.h"
#include "io/mesh_from_triangles.h"
#include "io/readers.h"
#include "io/soup_to_mesh.h"
#include "io/two_threads.h"
#include "mesh_room.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

std::string off_text(const Soup& soup) {
  std::ostringstream text;
  text.precision(17);
  text << "OFF\n" << soup.points.size() << ' ' << soup.faces.size() << " 0\n";
  for (const auto& p : soup.points) text << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& f : soup.faces) {
    text << f.size();
    for (const int c : f) text << ' ' << c;
    text << '\n';
  }
  return text.str();
}

std::string binary_ply(const Soup& soup) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(soup.points.size()) +
      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
      std::to_string(soup.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  auto put = [&out](auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    out.append(raw, sizeof value);
  };
  for (const auto& p : soup.points) put(p[0]), put(p[1]), put(p[2]);
  for (const auto& f : soup.faces) {
    put(static_cast<std::uint8_t>(f.size()));
    for (const int c : f) put(static_cast<std::int32_t>(c));
  }
  return out;
}

// Every half-edge as (from, to, face, the next half-edge's end), and the positions: two meshes
// with equal structures have the same elements in the same order, linked alike.
using Structure = std::tuple<std::vector<Point>, std::vector<std::tuple<int, int, int, int>>>;
Structure structure(const Mesh& mesh) {
  Structure s;
  for (const auto v : mesh.vertices()) std::get<0>(s).push_back(mesh.point(v));
  for (const auto h : mesh.halfedges()) {
    std::get<1>(s).emplace_back(mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx(),
                                mesh.face_handle(h).idx(),
                                mesh.to_vertex_handle(mesh.next_halfedge_handle(h)).idx());
  }
  return s;
}

std::vector<std::vector<int>> face_lists(const Mesh& mesh) {
  std::vector<std::vector<int>> faces;
  for (const auto f : mesh.faces()) {
    faces.emplace_back();
    for (const auto v : mesh.fv_range(f)) faces.back().push_back(v.idx());
  }
  return faces;
}

// The inner half-edges as a set of (from, to, next's end), and each boundary loop's vertices
// from its smallest, sorted: what must not depend on how the mesh was built.
std::pair<std::set<std::tuple<int, int, int>>, std::vector<std::vector<int>>> connectivity(
    const Mesh& mesh) {
  std::set<std::tuple<int, int, int>> inner;
  for (const auto h : mesh.halfedges()) {
    if (mesh.is_boundary(h)) continue;
    inner.emplace(mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx(),
                  mesh.to_vertex_handle(mesh.next_halfedge_handle(h)).idx());
  }
  std::vector<std::vector<int>> loops;
  for (const auto& hole : find_holes(mesh)) {
    loops.emplace_back();
    for (const auto v : hole.vertices) loops.back().push_back(v.idx());
    std::rotate(loops.back().begin(), std::min_element(loops.back().begin(), loops.back().end()),
                loops.back().end());
  }
  std::sort(loops.begin(), loops.end());
  return {inner, loops};
}

Mesh built_by_add_face(const Mesh& loaded) {
  Mesh mesh;
  for (const auto v : loaded.vertices()) mesh.add_vertex(loaded.point(v));
  for (const auto& face : face_lists(loaded)) {
    std::vector<VertexHandle> corners;
    for (const int v : face) corners.emplace_back(v);
    EXPECT_TRUE(mesh.add_face(corners).is_valid());
  }
  return mesh;
}

struct DirtySoup {
  const char* name;
  Soup soup;
};

// Soups with every kind of repair the loader makes: flipped, duplicated and degenerate faces,
// polygons, a fin on an edge, closed surfaces touching at a vertex, pinched open fans, cuts.
std::vector<DirtySoup> dirty_soups() {
  std::vector<DirtySoup> soups;
  Soup flipped = sphere_soup(2);
  for (std::size_t f = 0; f < flipped.faces.size(); f += 3) {
    std::swap(flipped.faces[f][1], flipped.faces[f][2]);
  }
  flipped.faces.push_back(flipped.faces[10]);                                // a duplicate
  flipped.faces.push_back({flipped.faces[20][0], flipped.faces[20][0], 5});  // degenerate
  soups.push_back({"flipped sphere", flipped});
  Soup fin = sphere_soup(1);
  fin.points.push_back({2.0, 2.0, 2.0});
  fin.faces.push_back({fin.faces[0][0], fin.faces[0][1], static_cast<int>(fin.points.size()) - 1});
  soups.push_back({"sphere with a fin", fin});
  // Two spheres, the second moved so that its point opposite the first's point 0 lies on it;
  // both faces' corners there are made one vertex.
  Soup touching = sphere_soup(1);
  Soup other = touching;
  const Point tip = touching.points[0];
  for (auto& p : other.points) p += 2.0 * tip;
  const auto opposite = std::min_element(
      other.points.begin(), other.points.end(),
      [&](const Point& a, const Point& b) { return (a - tip).sqrnorm() < (b - tip).sqrnorm(); });
  const int glued = static_cast<int>(touching.points.size() + (opposite - other.points.begin()));
  touching = append(touching, other);
  for (auto& face : touching.faces) {
    for (int& c : face) c = c == glued ? 0 : c;
  }
  soups.push_back({"spheres touching at a vertex", touching});
  Soup fans;
  fans.points.push_back({0, 0, 0});
  for (int i = 0; i < 40; ++i) {
    fans.points.push_back({std::cos(0.15 * i), std::sin(0.15 * i), 0.0});
    fans.points.push_back({std::cos(0.15 * i + 0.07), std::sin(0.15 * i + 0.07), 0.1});
    fans.faces.push_back({0, 2 * i + 1, 2 * i + 2});
  }
  soups.push_back({"pinched fans", fans});
  Soup quads = terrain_soup(12);
  for (std::size_t f = 0; f + 1 < quads.faces.size(); f += 8) {
    quads.faces[f].push_back(quads.faces[f + 1][2]);  // some polygons, maybe non-planar
  }
  std::mt19937 rng(3);
  cut_apart(
      quads, [](const Point& p) { return p[0] < 0.5; }, 0.0, rng);
  soups.push_back({"terrain with polygons, cut apart", quads});
  return soups;
}

// Properties that assemble adds before the mesh has elements (a loaded OBJ's corners and faces)
// get the room the mesh's own arrays get, and each element its default value.
TEST(MeshAssembly, PropertiesAddedBeforeTheElementsGetTheMeshsRoom) {
  const Mesh grid = make_grid(40, [](double x, double y) { return 0.1 * x * y; });
  std::vector<Point> positions;
  for (const auto v : grid.vertices()) positions.push_back(grid.point(v));
  std::vector<io::Triangle> triangles;
  for (const auto f : grid.faces()) {
    io::Triangle t;
    int c = 0;
    for (const auto v : grid.fv_range(f)) t[c++] = v.idx();
    triangles.push_back(t);
  }
  OpenMesh::HPropHandleT<int> corner;
  OpenMesh::FPropHandleT<double> weight;
  OpenMesh::VPropHandleT<int> label;
  LoadReport report;
  const Mesh mesh =
      io::assemble(positions, triangles, std::vector<char>(triangles.size(), 0), positions.size(),
                   report, nullptr, {}, io::kTwoThreadsFrom, [&](Mesh& empty) {
                     ASSERT_EQ(empty.n_vertices() + empty.n_halfedges() + empty.n_faces(), 0u);
                     empty.add_property(corner, "corner");
                     empty.add_property(weight, "weight");
                     empty.add_property(label, "label");
                   });
  ASSERT_EQ(mesh.n_faces(), triangles.size());
  const auto& corners = mesh.property(corner).data_vector();
  const auto& weights = mesh.property(weight).data_vector();
  const auto& labels = mesh.property(label).data_vector();
  EXPECT_EQ(corners.size(), mesh.n_halfedges());
  EXPECT_EQ(corners.capacity(), 2 * detail::with_room(mesh.n_edges()));
  EXPECT_EQ(weights.size(), mesh.n_faces());
  EXPECT_EQ(weights.capacity(), detail::with_room(mesh.n_faces()));
  EXPECT_EQ(labels.size(), mesh.n_vertices());
  EXPECT_EQ(labels.capacity(), detail::with_room(mesh.n_vertices()));
  EXPECT_TRUE(std::all_of(corners.begin(), corners.end(), [](int c) { return c == 0; }));
  EXPECT_TRUE(std::all_of(weights.begin(), weights.end(), [](double w) { return w == 0.0; }));
  // A loaded OBJ's corner numbers: made so, not added to the mesh once it had its elements.
  const Mesh textured = load_mesh_from_memory(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 1\n"
      "f 1/1 2/2 3/1\nf 2/2 4/1 3/2\n",
      "two.obj");
  const ObjHandles obj = obj_handles(textured);
  ASSERT_TRUE(obj.valid());
  EXPECT_EQ(textured.property(obj.texcoord).data_vector().capacity(),
            2 * detail::with_room(textured.n_edges()));
}

TEST(MeshAssembly, DirtySoupsLoadAsOneMeshInEveryFormatAndAsAddFaceBuildsIt) {
  for (const auto& [name, soup] : dirty_soups()) {
    SCOPED_TRACE(name);
    LoadReport obj_report, off_report, ply_report;
    const Mesh obj = load_mesh_from_memory(obj_text(soup), "dirty.obj", &obj_report);
    const Mesh off = load_mesh_from_memory(off_text(soup), "dirty.off", &off_report);
    const Mesh ply = load_mesh_from_memory(binary_ply(soup), "dirty.ply", &ply_report);
    EXPECT_TRUE(OpenMesh::Utils::MeshCheckerT<Mesh>(obj).check());
    EXPECT_EQ(structure(obj), structure(off));
    EXPECT_EQ(structure(obj), structure(ply));
    EXPECT_EQ(obj_report.warnings, off_report.warnings);
    EXPECT_EQ(obj_report.warnings, ply_report.warnings);
    const Mesh reference = built_by_add_face(obj);
    EXPECT_EQ(face_lists(obj), face_lists(reference));
    EXPECT_EQ(connectivity(obj), connectivity(reference));
  }
}

TEST(MeshAssembly, EachDirtSoupIsRepairedAsItsDirtRequires) {
  const auto soups = dirty_soups();
  LoadReport report;
  load_mesh_from_memory(obj_text(soups[0].soup), "flipped.obj", &report);
  const std::size_t sphere_faces = soups[0].soup.faces.size() - 2;  // every third one flipped
  EXPECT_EQ(report.faces_flipped, (sphere_faces + 2) / 3);
  EXPECT_EQ(report.duplicate_faces_dropped, 1u);
  EXPECT_EQ(report.degenerate_faces_dropped, 1u);
  load_mesh_from_memory(obj_text(soups[1].soup), "fin.obj", &report);
  EXPECT_EQ(report.faces_detached, 1u);
  const Mesh touching = load_mesh_from_memory(obj_text(soups[2].soup), "touching.obj", &report);
  EXPECT_EQ(report.vertices_split, 1u);
  EXPECT_EQ(touching.n_vertices(), soups[2].soup.points.size() + 1);
  EXPECT_EQ(touching.point(VertexHandle(static_cast<int>(touching.n_vertices()) - 1)),
            touching.point(VertexHandle(0)));
  const Mesh fans = load_mesh_from_memory(obj_text(soups[3].soup), "fans.obj", &report);
  EXPECT_EQ(report.vertices_split, 0u);
  EXPECT_EQ(find_holes(fans).size(), 1u);
}

// Every handle a mesh links, in handle order: each vertex's position and halfedge, each face's
// halfedge, each halfedge's vertex, face, next and previous halfedge.
using LinkedHandles = std::tuple<std::vector<Point>, std::vector<int>, std::vector<int>,
                                 std::vector<std::array<int, 4>>>;
LinkedHandles linked_handles(const Mesh& mesh) {
  LinkedHandles all;
  for (const auto v : mesh.vertices()) {
    std::get<0>(all).push_back(mesh.point(v));
    std::get<1>(all).push_back(mesh.halfedge_handle(v).idx());
  }
  for (const auto f : mesh.faces()) std::get<2>(all).push_back(mesh.halfedge_handle(f).idx());
  for (const auto h : mesh.halfedges()) {
    std::get<3>(all).push_back({mesh.to_vertex_handle(h).idx(), mesh.face_handle(h).idx(),
                                mesh.next_halfedge_handle(h).idx(),
                                mesh.prev_halfedge_handle(h).idx()});
  }
  return all;
}

// The mesh the soup read from `bytes` (by `name`'s extension) assembles into, the independent
// parts on two threads from `two_threads_from` faces on; the report as loading fills it.
Mesh assembled(const std::string& bytes, const std::string& name, std::size_t two_threads_from,
               LoadReport& report) {
  report = LoadReport{};
  const std::string ext = name.substr(name.rfind('.') + 1);
  report.format = ext;
  io::Soup soup = ext == "obj"   ? io::parse_obj(bytes, name, report)
                  : ext == "off" ? io::parse_off(bytes, name, report)
                                 : io::parse_ply(bytes, name, report);
  Mesh mesh = io::build_mesh(std::move(soup), report, two_threads_from);
  io::add_warnings(report);
  return mesh;
}

std::vector<std::size_t> report_counts(const LoadReport& r) {
  return {r.polygons_triangulated, r.degenerate_faces_dropped,
          r.faces_detached,        r.vertices_split,
          r.faces_flipped,         r.duplicate_faces_dropped,
          r.duplicate_positions,   r.isolated_vertices,
          r.elements_ignored};
}

// The dirty soups as an OBJ with a texture coordinate and a normal per corner, materials, groups
// and smoothing groups changing along the faces, and unused vertices: every attribute the
// assembly carries to the mesh.
std::string textured_obj(const Soup& soup) {
  std::ostringstream text;
  text.precision(17);
  text << "mtllib dirty.mtl\n";
  for (const auto& p : soup.points) {
    text << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    text << "vt " << p[0] << ' ' << p[1] << '\n';
    text << "vn " << p[2] << ' ' << p[0] << " 1\n";
  }
  text << "v 9 9 9\nv 9 9 9\n";
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    if (f % 7 == 0) text << "usemtl m" << f % 3 << '\n';
    if (f % 11 == 0) text << "g part" << f % 4 << '\n';
    if (f % 13 == 0) text << "s " << f % 2 << '\n';
    text << 'f';
    for (const int c : soup.faces[f]) {
      // Texture coordinates and normals shifted from the vertex, so that a corner's numbers
      // differ from its vertex's.
      const std::size_t n = soup.points.size();
      text << ' ' << c + 1 << '/' << (c + f) % n + 1 << '/' << (c + 2 * f) % n + 1;
    }
    text << '\n';
  }
  return text.str();
}

// The dirty soups as an ASCII PLY with a colour per vertex and a value per face.
std::string ply_with_attributes(const Soup& soup) {
  std::ostringstream text;
  text.precision(17);
  text << "ply\nformat ascii 1.0\nelement vertex " << soup.points.size()
       << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\n"
       << "element face " << soup.faces.size()
       << "\nproperty list uchar int vertex_indices\nproperty float quality\nend_header\n";
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    const auto& p = soup.points[v];
    text << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << v % 256 << '\n';
  }
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    text << soup.faces[f].size();
    for (const int c : soup.faces[f]) text << ' ' << c;
    text << ' ' << 0.5 * static_cast<double>(f) << '\n';
  }
  return text.str();
}

// Two threads assemble the mesh one thread does, handle for handle, with the same attributes
// (the files written from both) and the same report and warnings: every dirty soup, as a plain
// OBJ, an OFF, a binary PLY, a textured OBJ and a PLY with attributes, the soups alone and all of
// them in one (so that each half of the faces holds some of every kind of dirt), with the
// two-thread threshold lowered to one face.
TEST(MeshAssembly, TwoThreadsAssembleTheOneThreadMesh) {
  auto soups = dirty_soups();
  Soup all;
  for (const auto& dirty : soups) all = append(all, dirty.soup);
  soups.push_back({"all dirty soups in one", all});
  Soup odd = all;
  odd.faces.pop_back();
  soups.push_back({"an odd number of faces", odd});
  for (const auto& [name, soup] : soups) {
    const std::pair<std::string, std::string> files[] = {
        {obj_text(soup), "dirty.obj"},
        {off_text(soup), "dirty.off"},
        {binary_ply(soup), "dirty.ply"},
        {textured_obj(soup), "textured.obj"},
        {ply_with_attributes(soup), "attributes.ply"}};
    for (const auto& [bytes, file] : files) {
      SCOPED_TRACE(std::string(name) + ", " + file);
      LoadReport one_report, two_report;
      const Mesh one = assembled(bytes, file, std::numeric_limits<std::size_t>::max(), one_report);
      const Mesh two = assembled(bytes, file, 1, two_report);
      EXPECT_EQ(linked_handles(one), linked_handles(two));
      EXPECT_EQ(report_counts(one_report), report_counts(two_report));
      EXPECT_EQ(one_report.warnings, two_report.warnings);
      const std::string written = file.substr(file.rfind('.'));
      EXPECT_EQ(mesh_to_bytes(one, "one" + written), mesh_to_bytes(two, "two" + written));
    }
  }
}

// Every corner of a loaded textured OBJ has the texture coordinate and normal its face gave its
// vertex in the file, whatever the repairs did (flipped, detached, duplicate and degenerate
// faces, split vertices, polygons), on one thread and on two. textured_obj gives soup face f's
// corner at vertex v the numbers (v + f) % n + 1 and (v + 2 f) % n + 1, which name both.
TEST(MeshAssembly, EveryCornerOfATexturedObjKeepsTheNumbersItsFaceGaveIt) {
  auto soups = dirty_soups();
  Soup all;
  for (const auto& dirty : soups) all = append(all, dirty.soup);
  soups.push_back({"all dirty soups in one", all});
  for (const auto& [name, soup] : soups) {
    const auto n = static_cast<int>(soup.points.size());
    for (const std::size_t two_threads_from :
         {std::numeric_limits<std::size_t>::max(), std::size_t{1}}) {
      SCOPED_TRACE(std::string(name) + (two_threads_from == 1 ? ", two threads" : ""));
      LoadReport report;
      const Mesh mesh = assembled(textured_obj(soup), "textured.obj", two_threads_from, report);
      const ObjHandles obj = obj_handles(mesh);
      ASSERT_TRUE(obj.valid());
      for (const auto f : mesh.faces()) {
        std::set<int> face_numbers;  // the soup face (modulo n) each corner names
        for (const auto h : mesh.fh_range(f)) {
          const int texcoord = mesh.property(obj.texcoord, h) - 1,
                    normal = mesh.property(obj.normal, h) - 1;
          ASSERT_GE(texcoord, 0);
          ASSERT_GE(normal, 0);
          const int face = ((normal - texcoord) % n + n) % n;
          const int vertex = ((texcoord - face) % n + n) % n;
          face_numbers.insert(face);
          EXPECT_EQ(mesh.point(mesh.to_vertex_handle(h)), soup.points[vertex]) << f.idx();
          bool in_face = false;
          for (std::size_t g = face; g < soup.faces.size(); g += n) {
            const auto& corners = soup.faces[g];
            in_face = in_face || std::find(corners.begin(), corners.end(), vertex) != corners.end();
          }
          EXPECT_TRUE(in_face) << f.idx();
        }
        EXPECT_EQ(face_numbers.size(), 1u) << f.idx();
      }
    }
  }
}

// The first half's error is the one thrown when both halves fail, after both are done; the
// second's when only it fails; none runs twice.
TEST(MeshAssembly, TwoThreadsThrowWhatTheOneThreadAssemblyWould) {
  for (const bool two : {false, true}) {
    int first_runs = 0, second_runs = 0;
    EXPECT_THROW(io::run_both(
                     two, [&] { ++first_runs; },
                     [&] {
                       ++second_runs;
                       throw std::length_error("second");
                     }),
                 std::length_error);
    EXPECT_EQ(first_runs, 1);
    EXPECT_EQ(second_runs, 1);
    try {
      io::run_both(
          two, [] { throw std::runtime_error("first"); },
          [&] { throw std::length_error("second"); });
      ADD_FAILURE() << "nothing thrown";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "first");
    }
    std::vector<int> seen(1001, 0);
    io::run_in_halves(two, seen.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) ++seen[i];
    });
    EXPECT_EQ(seen, std::vector<int>(1001, 1));
  }
}

}  // namespace
}  // namespace holefill::testing
