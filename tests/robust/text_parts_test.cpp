// A big OBJ, OFF or ASCII PLY is read in two parts on two threads (two_parts.h), a binary PLY's
// faces apart from its vertices (ply_reader.cpp): cut at every
// line of files that carry state across the cut (OBJ: relative indices into the first part,
// materials, groups, objects and smoothing groups set before it, colours, texture coordinates
// and normals on one side only, material libraries, ignored statements, continued lines; OFF and
// PLY: the vertex and face records, colours typed by the first face, comments, blank and extra
// lines; all: mixed line ends), with errors of every kind on either side, the soup, the report
// and every error message are those of the one-thread reading, byte for byte.
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "io/face_lines.h"
#include "io/mesh_from_triangles.h"
#include "io/obj_estimate.h"
#include "io/readers.h"
#include "robust_test_util.h"

namespace holefill::testing {
namespace {

std::string hex(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%a ", value);
  return text;
}

template <class Values>
std::string listed(const Values& values) {
  std::string out;
  for (const auto& value : values) out += std::to_string(value) + ' ';
  return out + '\n';
}

std::string listed_runs(const std::vector<std::pair<std::size_t, std::size_t>>& runs) {
  std::string out;
  for (const auto& [face, line] : runs)
    out += std::to_string(face) + ':' + std::to_string(line) + ' ';
  return out + '\n';
}

using Parse = io::Soup (*)(std::string_view, const std::filesystem::path&, LoadReport&,
                           std::size_t);

// Everything a reading returns, as text (positions bit for bit), or the error it threw.
std::string read_whole_or_cut(const std::string& text, std::size_t split_near,
                              Parse parse = io::parse_obj, const char* path = "/data/cut.obj") {
  LoadReport report;
  io::Soup soup;
  try {
    soup = parse(text, path, report, split_near);
  } catch (const std::exception& error) {
    return std::string("refused: ") + error.what() +
           (dynamic_cast<const FileError*>(&error) ? " (FileError)" : " (other)");
  }
  std::string out;
  for (const auto& p : soup.positions) out += hex(p[0]) + hex(p[1]) + hex(p[2]) + '\n';
  for (const auto& values : soup.vertex_values) out += "colour " + listed(values);
  for (const auto& attribute : soup.layout.vertex) {
    out += attribute.name + ' ' + std::to_string(static_cast<int>(attribute.type)) + ' ';
  }
  for (const auto& values : soup.face_values) out += "face values " + listed(values);
  for (const auto& attribute : soup.layout.face) {
    out += attribute.name + ' ' + std::to_string(static_cast<int>(attribute.type)) + ' ';
  }
  out += "\ncorners " + listed(soup.corners) + "ends " + listed(soup.face_end) + "lines " +
         listed_runs(soup.face_line.runs()) + "texcoord " + listed(soup.corner_texcoord) +
         "normal " + listed(soup.corner_normal) + "material " + listed(soup.face_material) +
         "group " + listed(soup.face_group) + "object " + listed(soup.face_object) + "smoothing " +
         listed(soup.face_smoothing);
  const ObjTables& obj = soup.obj;
  for (const auto& uvw : obj.texcoords) out += hex(uvw[0]) + hex(uvw[1]) + hex(uvw[2]);
  for (const auto& n : obj.normals) out += hex(n[0]) + hex(n[1]) + hex(n[2]);
  out += "\nsizes " + std::to_string(obj.texcoord_size) + ' ' + std::to_string(obj.file_texcoords) +
         ' ' + std::to_string(obj.file_normals) + '\n';
  for (const auto* names : {&obj.materials, &obj.groups, &obj.objects, &obj.smoothing_groups}) {
    for (const auto& name : *names) out += name + '|';
    out += '\n';
  }
  for (const auto& file : obj.material_libraries) out += file.string() + '|';
  out += "\nignored " + std::to_string(report.elements_ignored) + " empty " +
         std::to_string(report.degenerate_faces_dropped) + '\n';
  for (const auto& warning : report.warnings) out += warning + '\n';
  return out;
}

// Reads `text` whole, then cut after every line, and expects the same each time.
void expect_same_at_every_cut(const std::string& text, Parse parse = io::parse_obj,
                              const char* path = "/data/cut.obj") {
  const std::string whole = read_whole_or_cut(text, std::string::npos, parse, path);
  int cuts = 0;
  for (std::size_t at = 0; at < text.size(); ++at) {
    if (at > 0 && text[at - 1] != '\n') continue;
    ++cuts;
    ASSERT_EQ(read_whole_or_cut(text, at, parse, path), whole) << "cut at byte " << at << " of\n"
                                                               << text;
  }
  EXPECT_GT(cuts, 3);
}

// `text` with its line ends mixed: of every three LFs, one kept, one CR LF, one a lone CR.
std::string with_mixed_line_ends(std::string text) {
  for (std::size_t at = text.find('\n'), n = 0; at != std::string::npos;
       at = text.find('\n', at + 1), ++n) {
    if (n % 3 == 1) text.insert(at++, "\r");
    if (n % 3 == 2) text[at] = '\r';
  }
  return text;
}

const std::string kStateAcrossTheCut =
    "mtllib a.mtl\n# a comment\nv 0 0 0\nv 1 0 0 0.5 0.25 1\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\n"
    "vn 0 0 1\ng left side\nusemtl red\ns 1\no first\nf 1 2 3\nf -3/-2 -2/-1 -1/1\n"
    "f 2/1/1 4/2/1 3/1/-1\nl 1 2\nfoo bar\nv 2 0 0\nv 2 1 0\nf -5 -2 -1\nusemtl blue\n"
    "f 2 5 4\\\n 6\ng\nf 3 4 6\nmtllib b.mtl a.mtl\ns off\nfo 4 6 5\nusemtl red\nf\n"
    "vt 0.5 0.5 0.5\nf 1/-1 2/-1 3/3\nf 1/1 2/2 4\nv 3 3 3 0 0 0\nf -1 -2 -3\nbar\n"
    "o second\ng left side\nf 1//1 5//1 6//-1\ncurv 0 1 1 2\n";

TEST(ObjParts, StateCarriedAcrossTheCutReadsAsOneReading) {
  expect_same_at_every_cut(kStateAcrossTheCut);
  // Lone CRs, CR LF and continued lines with CR LF: lines counted as one reading counts them.
  std::string mixed = kStateAcrossTheCut;
  for (std::size_t at = 0, n = 0; (at = mixed.find('\n', at)) != std::string::npos; ++n) {
    if (n % 3 == 1) mixed.insert(at++, "\r");
    if (n % 3 == 2 && (at == 0 || mixed[at - 1] != '\\')) mixed[at] = '\r';
    ++at;
  }
  expect_same_at_every_cut(mixed);
}

TEST(ObjParts, NothingButNamesOrNothingAtAllOnOneSide) {
  expect_same_at_every_cut("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl m\ng g\no o\ns 2\n");
  expect_same_at_every_cut("usemtl m\ng g\no o\ns 2\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\n\n");
  expect_same_at_every_cut("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 1\nusemtl m\nf 1 2 3\n");
  expect_same_at_every_cut("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf 1 2 3\nf 1 2 3\n");
}

TEST(ObjParts, ErrorsOnEitherSideAreOneReadingsMessages) {
  const std::string start = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1 2 3\n";
  for (const std::string bad :
       {"f -4 -3 -2\n", "f 1/-2 2/1 3/1\n", "f 1//-2 2//1 3//1\n", "f 0 1 2\n", "f 1 2 3x\n",
        "v 1 x 0\n", "v 1e999 0 0\n", "vt\n", "vn 0 0\n", "f 1 2 9\n", "f 1/7 2/1 3/1\n",
        "f 1//5 2//1 3//1\n", "f 1 2 99999999999\n", "f 1 -99999999999 3\n"}) {
    expect_same_at_every_cut(start + bad + start + "f -1 -2 -3\n");
    expect_same_at_every_cut(start + "f -1 -2 -3\n" + start + bad + "f 4 5 6\n");
    // An error in each half: the first one's is the message.
    expect_same_at_every_cut(start + bad + start + "f 1 2 3 x\nf 1 2 77\n");
  }
}

// Each half looks for a NUL on its own thread: a NUL anywhere is refused, naming the first one,
// before any error the reading of either half meets, as one reading refuses it before reading.
TEST(ObjParts, ANulOnEitherSideIsRefusedBeforeAnyOtherError) {
  const std::string start = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", nul("v 0 0 \0\n", 8);
  for (const std::string bad : {"", "v 1 x 0\n", "f 1 2 9\n", "f 1 -99 3\n"}) {
    expect_same_at_every_cut(start + bad + nul + start + start);
    expect_same_at_every_cut(start + bad + start + start + nul);
    expect_same_at_every_cut(start + nul + start + bad + start + nul);
  }
  // The first half's error, the second half's NUL.
  EXPECT_EQ(read_whole_or_cut(start + "v 1 x 0\n" + start + nul, start.size() + 8),
            "refused: /data/cut.obj: is not a text OBJ file: it holds binary data (byte " +
                std::to_string(2 * start.size() + 14) + " is NUL) (FileError)");
}

void expect_same_off_at_every_cut(const std::string& text) {
  expect_same_at_every_cut(text, io::parse_off, "/data/cut.off");
  expect_same_at_every_cut(with_mixed_line_ends(text), io::parse_off, "/data/cut.off");
}

const std::string kOffStart = "OFF # a comment\n\n4 3 0\n0 0 0\n1 0 0 # c\n\n  0 1 0\n";

TEST(OffParts, RecordsCommentsAndExtraLinesReadAsOneReading) {
  expect_same_off_at_every_cut(kOffStart + "1 1 0\n3 0 1 2\n# c\n3 1 3 2\n4 0 1 3 2\n");
  expect_same_off_at_every_cut(
      "OFF 4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n"
      "x\n\n y z\n");
  // Colours typed by the first face (on either side of the cut), kept or counted as dropped.
  expect_same_off_at_every_cut(kOffStart + "1 1 0\n3 0 1 2 1 0 0\n3 1 3 2 0.5 1 1\n3 0 1 3\n");
  expect_same_off_at_every_cut(kOffStart + "1 1 0\n3 0 1 2\n3 1 3 2 255 0 0\n3 0 1 3 1 1 1\n");
  // COFF's vertex colours, planned from the first vertex line: read whole.
  expect_same_off_at_every_cut("COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n3 0 1 2\n");
}

TEST(OffParts, ErrorsOnEitherSideAreOneReadingsMessages) {
  const std::string vertices = "OFF\n6 4 0\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string more = "1 1 0\n2 0 0\n2 1 0\n";
  for (const std::string bad : {"1 x 0\n", "1 1e999 0\n", "1 1\n", "1 1 0 0.5x\n"}) {
    expect_same_off_at_every_cut(vertices + bad + more.substr(6) + "3 0 1 2\n3 1 3 2\n" +
                                 "3 0 1 3\n3 3 4 5\n");
  }
  for (const std::string bad : {"3 0 1 9\n", "3 0 1 -1\n", "3x 0 1 2\n", "-3 0 1 2\n", "3 0 1\n",
                                "3 0 1 2x\n", "3 0 1 99999999999999999999\n"}) {
    expect_same_off_at_every_cut(vertices + more + bad + "3 1 3 2\n3 0 1 3\n3 3 4 5\n");
    expect_same_off_at_every_cut(vertices + more + "3 1 3 2\n3 0 1 3\n3 3 4 5\n" + bad);
    // An error in each part: the first one's is the message.
    expect_same_off_at_every_cut(vertices + more + bad + "3 1 3 2\n3 0 1 3\n3 3 4 x\n");
  }
  // Truncated in the vertices, in the faces.
  expect_same_off_at_every_cut(vertices + "1 1 0\n");
  expect_same_off_at_every_cut(vertices + more + "3 1 3 2\n3 0 1 3\n");
}

// The OFF reader gives its arrays the room of the counted records from the start (each growing
// past its room copied it into one twice its size), whole or in two parts, whose second part is
// then appended without a copy.
TEST(OffParts, ArraysHaveTheRoomOfTheCountedRecords) {
  constexpr int kVertices = 300, kFaces = 1001;  // neither a power of two
  std::string text = "OFF\n" + std::to_string(kVertices) + ' ' + std::to_string(kFaces) + " 0\n";
  for (int v = 0; v < kVertices; ++v)
    text += std::to_string(v) + " 0.5 " + std::to_string(v % 7) + '\n';
  for (int f = 0; f < kFaces; ++f) {
    text += "3 " + std::to_string(f % 298) + ' ' + std::to_string(f % 298 + 1) + ' ' +
            std::to_string(f % 298 + 2) + '\n';
  }
  for (const std::size_t split_near : {std::string::npos, text.size() / 4, text.size() / 2}) {
    LoadReport report;
    const io::Soup soup = io::parse_off(text, "/data/room.off", report, split_near);
    ASSERT_EQ(soup.face_count(), std::size_t{kFaces});
    EXPECT_EQ(soup.positions.capacity(), io::mesh_capacity(kVertices)) << split_near;
    EXPECT_EQ(soup.corners.capacity(), std::size_t{3 * kFaces}) << split_near;
    EXPECT_EQ(soup.face_end.capacity(), std::size_t{kFaces}) << split_near;
    EXPECT_TRUE(soup.face_line.runs().empty()) << split_near;  // no line is kept per face
  }
}

// A textured grid of side x side vertices (v, vt and vn each), a group and a material, and its
// faces by v/vt/vn: 3 MB at side 150, enough to be sampled (obj_estimate.h).
std::string textured_grid_obj(int side) {
  std::string text = "mtllib grid.mtl\n";
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const std::string x = std::to_string(i * 0.01), y = std::to_string(j * 0.01);
      text += "v " + x + ' ' + y + " 0.5\nvt " + x + ' ' + y + "\nvn 0 0 1\n";
    }
  }
  text += "g grid\nusemtl ground\n";
  auto corner = [](int v) {
    return ' ' + std::to_string(v) + '/' + std::to_string(v) + '/' + std::to_string(v);
  };
  for (int i = 0; i + 1 < side; ++i) {
    for (int j = 0; j + 1 < side; ++j) {
      const int a = i * side + j + 1, b = a + 1, c = a + side, d = c + 1;
      text += 'f' + corner(a) + corner(b) + corner(d) + "\nf" + corner(a) + corner(d) + corner(c) +
              '\n';
    }
  }
  return text;
}

// FaceLines keeps runs of faces a line apart; each face's line is what a vector of one line per
// face held, whole or appended in two parts at any face, and the runs are the same either way.
TEST(FaceLines, RunsGiveEachFacesLineAsALinePerFaceDid) {
  std::mt19937 random(15);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t faces = 1 + random() % 40;
    std::vector<std::size_t> line_of(faces, 0);
    std::size_t line = 1 + random() % 3;
    for (std::size_t f = 0; f < faces; ++f) {
      line += random() % 4 == 0 ? 2 + random() % 3 : 1;  // mostly the next line
      line_of[f] = random() % 9 == 0 ? 0 : line;         // sometimes unknown
    }
    io::FaceLines whole;
    for (std::size_t f = 0; f < faces; ++f) whole.add(f, line_of[f]);
    for (std::size_t f = 0; f < faces; ++f) ASSERT_EQ(whole.line(f), line_of[f]) << trial;
    EXPECT_EQ(whole.line(faces + 3), line_of[faces - 1] == 0 ? 0 : line_of[faces - 1] + 4);
    // Cut after `cut` faces, the second part's lines counted from the first part's last line.
    const std::size_t cut = random() % (faces + 1), lines_before = cut ? line_of[cut - 1] : 0;
    io::FaceLines first, second;
    for (std::size_t f = 0; f < cut; ++f) first.add(f, line_of[f]);
    bool relative = true;
    for (std::size_t f = cut; f < faces; ++f) {
      relative = relative && (line_of[f] == 0 || line_of[f] > lines_before);
      second.add(f - cut, line_of[f] == 0 ? 0 : line_of[f] - lines_before);
    }
    if (!relative) continue;
    first.append(second, cut, faces - cut, lines_before);
    EXPECT_EQ(first.runs(), whole.runs()) << trial << " cut " << cut;
  }
}

TEST(ObjEstimate, SamplesGiveTheCountsWithAMarginOrNothingForASmallText) {
  constexpr int kSide = 150;
  const std::string text = textured_grid_obj(kSide);
  ASSERT_GE(text.size(), io::kEstimateObjFrom);
  const io::ObjCounts counts = io::estimate_obj_counts(text);
  const std::size_t vertices = kSide * kSide, faces = 2 * (kSide - 1) * (kSide - 1);
  for (const auto& [estimate, actual] :
       {std::pair{counts.vertices, vertices}, std::pair{counts.texcoords, vertices},
        std::pair{counts.normals, vertices}, std::pair{counts.faces, faces},
        std::pair{counts.corners, 3 * faces}}) {
    EXPECT_GE(estimate, actual);
    EXPECT_LE(estimate, actual + actual / 4);
  }
  EXPECT_TRUE(counts.slashed_corners);
  // The second half holds faces only.
  const io::ObjCounts later =
      io::estimate_obj_counts(std::string_view(text).substr(text.size() / 2));
  EXPECT_EQ(later.vertices, 0u);
  EXPECT_GT(later.faces, 0u);
  EXPECT_GE(later.corners, 3 * later.faces - later.faces / 8);
  const io::ObjCounts small = io::estimate_obj_counts(text.substr(0, io::kEstimateObjFrom - 1));
  EXPECT_EQ(small.vertices + small.faces + small.corners, 0u);
  // A text of shortest statements is bounded by its size.
  std::string shortest;
  while (shortest.size() < 2 * io::kEstimateObjFrom) shortest += "v 0 0 0\nf 1\n";
  const io::ObjCounts bounded = io::estimate_obj_counts(shortest);
  EXPECT_LE(bounded.vertices, shortest.size() / 8);
  EXPECT_LE(bounded.faces, shortest.size() / 4);
}

// The OBJ reader gives its arrays the room of the estimate from the start (each growing past its
// room was copied into one twice its size), whole or in two parts, whose second part is then
// appended without a copy; and reads what it read without.
TEST(ObjParts, ArraysHaveTheRoomOfTheEstimate) {
  const std::string text = textured_grid_obj(150);
  const io::ObjCounts counts = io::estimate_obj_counts(text);
  const std::string whole = read_whole_or_cut(text, std::string::npos);
  for (const std::size_t split_near : {std::string::npos, text.size() / 3, text.size() / 2}) {
    LoadReport report;
    const io::Soup soup = io::parse_obj(text, "/data/room.obj", report, split_near);
    EXPECT_EQ(soup.positions.capacity(), io::mesh_capacity(counts.vertices)) << split_near;
    EXPECT_EQ(soup.obj.texcoords.capacity(), counts.texcoords) << split_near;
    EXPECT_EQ(soup.obj.normals.capacity(), counts.normals) << split_near;
    EXPECT_EQ(soup.corners.capacity(), counts.corners) << split_near;
    EXPECT_EQ(soup.corner_texcoord.capacity(), counts.corners) << split_near;
    EXPECT_EQ(soup.corner_normal.capacity(), counts.corners) << split_near;
    EXPECT_EQ(soup.face_end.capacity(), counts.faces) << split_near;
    // The faces follow each other a line apart: one run.
    EXPECT_EQ(soup.face_line.runs().size(), 1u) << split_near;
    EXPECT_EQ(soup.face_material.capacity(), counts.faces) << split_near;
    EXPECT_EQ(soup.face_group.capacity(), counts.faces) << split_near;
    EXPECT_EQ(read_whole_or_cut(text, split_near), whole);
  }
}

void expect_same_ply_at_every_cut(const std::string& text) {
  expect_same_at_every_cut(text, io::parse_ply, "/data/cut.ply");
  expect_same_at_every_cut(with_mixed_line_ends(text), io::parse_ply, "/data/cut.ply");
}

const std::string kPlyHeader =
    "ply\nformat ascii 1.0\ncomment c\nelement vertex 5\nproperty float x\nproperty float y\n"
    "property double z\nproperty uchar red\nelement edge 2\nproperty int a\nproperty int b\n"
    "element face 4\nproperty list uchar int vertex_indices\nproperty short flag\n"
    "end_header\n";
const std::string kPlyVertices = "0 0 0 1\n1 0 0 2\n\n 0 1 0 3\n1 1 0.1 4\n2 0 0 5\n";
const std::string kPlyEdges = "0 1\n1 2\n";

TEST(PlyParts, RecordsOfEveryElementReadAsOneReading) {
  const std::string faces = "3 0 1 2 -1\n3 1 3 2 7\n4 1 4 3 2 0\n  3 0 1 3 1\n";
  expect_same_ply_at_every_cut(kPlyHeader + kPlyVertices + kPlyEdges + faces);
  // Lines after the last record: counted on either side.
  expect_same_ply_at_every_cut(kPlyHeader + kPlyVertices + kPlyEdges + faces + "1 2\n\n3 4\n");
}

TEST(PlyParts, ErrorsOnEitherSideAreOneReadingsMessages) {
  const std::string start = kPlyHeader + kPlyVertices + kPlyEdges;
  const std::string first_face = "3 0 1 2 -1\n", middle_faces = "3 1 3 2 7\n4 1 4 3 2 0\n";
  for (const std::string bad :
       {"1 x 0 2\n", "1 1e999 0 2\n", "1 1 0 300\n", "1 1 0\n", "1 1 0 2 2\n", "1 1 0 2x\n"}) {
    expect_same_ply_at_every_cut(kPlyHeader + bad + kPlyVertices.substr(8) + kPlyEdges +
                                 first_face + middle_faces + first_face);
  }
  for (const std::string bad : {"3 0 1 9 0\n", "3 0 1 -1 0\n", "3 0 1 1.5 0\n", "250 0 1 2 0\n",
                                "3 0 1 2 99999\n", "3 0 1 2\n"}) {
    expect_same_ply_at_every_cut(start + bad + middle_faces + first_face);
    expect_same_ply_at_every_cut(start + first_face + middle_faces + bad);
    // An error in each part: the first one's is the message.
    expect_same_ply_at_every_cut(start + bad + middle_faces + "3 0 x 1 0\n");
  }
  // Truncated in the vertices, in the faces.
  expect_same_ply_at_every_cut(kPlyHeader + kPlyVertices.substr(0, 16));
  expect_same_ply_at_every_cut(start + first_face + "3 1 3 2 7\n");
}

// A binary PLY (in this machine's byte order) of the elements of kPlyHeader: vertices x, y, z,
// red, two edges, faces as lists of int with a short flag each; `tail` after the last record.
std::string binary_ply(const std::vector<std::array<double, 4>>& vertices,
                       const std::vector<std::vector<int>>& faces, const std::string& tail = "") {
  std::string text = std::string("ply\nformat binary_") +
                     (std::endian::native == std::endian::little ? "little" : "big") +
                     "_endian 1.0\nelement vertex " + std::to_string(vertices.size()) +
                     "\nproperty float x\nproperty float y\nproperty double z\nproperty uchar "
                     "red\nelement edge 2\nproperty int a\nproperty int b\nelement face " +
                     std::to_string(faces.size()) +
                     "\nproperty list uchar int vertex_indices\nproperty short flag\nend_header\n";
  const auto put = [&text](auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    text.append(raw, sizeof value);
  };
  for (const auto& v : vertices) {
    put(static_cast<float>(v[0])), put(static_cast<float>(v[1])), put(v[2]);
    put(static_cast<unsigned char>(v[3]));
  }
  for (const int end : {0, 1, 1, 2}) put(end);
  for (const auto& face : faces) {
    put(static_cast<unsigned char>(face.size()));
    for (const int corner : face) put(corner);
    put(static_cast<short>(face.size()));
  }
  return text + tail;
}

// Read whole and with its faces apart (any byte inside the file asks for the cut).
void expect_same_binary_ply_either_way(const std::string& text) {
  const std::string whole = read_whole_or_cut(text, std::string::npos, io::parse_ply, "/d/b.ply");
  for (const std::size_t at : {std::size_t{0}, text.size() / 2, text.size() - 1}) {
    EXPECT_EQ(read_whole_or_cut(text, at, io::parse_ply, "/d/b.ply"), whole) << at;
  }
}

const std::vector<std::array<double, 4>> kBinaryVertices{
    {0, 0, 0, 1}, {1, 0, 0, 2}, {0, 1, 0, 3}, {1, 1, 0.1, 4}, {2, 0, 0, 5}};
const std::vector<std::vector<int>> kBinaryFaces{{0, 1, 2}, {1, 3, 2}, {1, 4, 3, 2}, {0, 1, 3}};

TEST(PlyParts, BinaryFacesReadApartFromTheVerticesAsOneReading) {
  expect_same_binary_ply_either_way(binary_ply(kBinaryVertices, kBinaryFaces));
  expect_same_binary_ply_either_way(binary_ply(kBinaryVertices, kBinaryFaces, "extra"));
  EXPECT_EQ(
      read_whole_or_cut(binary_ply(kBinaryVertices, kBinaryFaces), 0, io::parse_ply).substr(0, 8),
      "0x0p+0 0");  // read, not refused
}

TEST(PlyParts, BinaryErrorsOnEitherSideAreOneReadingsMessages) {
  auto bad_vertex = kBinaryVertices;
  bad_vertex[1][2] = std::nan("");
  auto bad_face = kBinaryFaces;
  bad_face[2][1] = 9;
  expect_same_binary_ply_either_way(binary_ply(bad_vertex, kBinaryFaces));
  expect_same_binary_ply_either_way(binary_ply(kBinaryVertices, bad_face));
  // An error in each part: the vertex's is the message.
  expect_same_binary_ply_either_way(binary_ply(bad_vertex, bad_face));
  // Truncated in the faces; a list longer than the file.
  const std::string whole = binary_ply(kBinaryVertices, kBinaryFaces);
  expect_same_binary_ply_either_way(whole.substr(0, whole.size() - 5));
  auto long_list = kBinaryFaces;
  long_list[0].assign(200, 0);
  const std::string listed = binary_ply(kBinaryVertices, long_list);
  expect_same_binary_ply_either_way(listed.substr(0, listed.size() - 700));
}

}  // namespace
}  // namespace holefill::testing
