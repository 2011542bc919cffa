// One reader per format: each turns a file's bytes into a Soup or throws FileError naming the
// file, the line or record where it can, and the reason. sniff() tells the formats apart.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

#include "holefill/io.h"
#include "holefill/mesh_format.h"
#include "huge_pages.h"
#include "soup.h"

namespace holefill::io {

// Reserves, on huge pages, room for `faces` faces a reader is about to read and their corners as
// triangles (most files' faces), at most one corner per byte of the `bytes` that hold them.
inline void reserve_faces(Soup& soup, std::size_t faces, std::size_t bytes) {
  reserve_on_huge_pages(soup.corners, std::min(3 * faces, bytes));
  reserve_on_huge_pages(soup.face_end, faces);
}

// What the first bytes of a file say it is: the format the contents clearly are (a PLY or OFF
// header, a binary STL's size, ...), or none; `decided` false when more of the file could change
// that (the first line with a keyword runs past the bytes given, or they hold less than the
// 64 KiB looked at).
struct Sniffed {
  std::optional<MeshFormat> format;
  bool decided = true;
};

// `first_bytes` are the start of a file of `file_size` bytes.
Sniffed sniff_start(std::string_view first_bytes, std::uint64_t file_size);

// The format the contents clearly are, or none: sniff_start on the whole of them.
std::optional<MeshFormat> sniff(std::string_view bytes);

// OBJ through tinyobjloader (obj_reader.cpp says who reads what): positions and colours, faces
// (polygons of any size; relative indices) with their texture coordinates, normals, materials,
// groups, objects and smoothing groups, and the material libraries; lines, points and curves are
// counted in report.elements_ignored, other statements not kept named in a warning.
Soup parse_obj(std::string_view text, const std::filesystem::path& path, LoadReport& report);
// The same, with the text cut at the first line boundary from byte `split_near` on that does
// not cut a continued statement, when there is one, and the part after it read on a second
// thread: the same soup, warnings and messages. The three-argument form cuts texts of 8 MB and
// more in the middle, and reads smaller ones whole (tests cut small ones anywhere).
Soup parse_obj(std::string_view text, const std::filesystem::path& path, LoadReport& report,
               std::size_t split_near);

// ASCII OFF, 3D, with the optional ST/C/N prefixes of the keyword. Lines after the counted
// faces are ignored with a warning.
Soup parse_off(std::string_view text, const std::filesystem::path& path, LoadReport& report);
// The same, with the body cut at the first line boundary from byte `split_near` on, when there
// is one, and the part after it read on a second thread: the same soup, warnings and messages.
// The three-argument form cuts texts of 8 MB and more in the middle (tests cut small ones
// anywhere). NOFF and COFF files, whose vertex attributes the first vertex line sets, are read
// whole.
Soup parse_off(std::string_view text, const std::filesystem::path& path, LoadReport& report,
               std::size_t split_near);

// PLY, ASCII or binary of either byte order: the vertex element's x, y, z and the face
// element's vertex index list. ASCII is read one record a line; a line with more or fewer values
// than the header's properties is refused, naming it. Data after the counted records: a warning.
Soup parse_ply(std::string_view bytes, const std::filesystem::path& path, LoadReport& report);
// The same, with an ASCII body cut at the first line boundary from byte `split_near` of the file
// on, when there is one, and the part after it read on a second thread; a binary body, when
// `split_near` lies inside the file, cut where its face element begins (when the records before
// it have one size), the faces read on a second thread: the same soup, warnings and messages.
// The three-argument form cuts files of 8 MB and more (in the middle, for ASCII).
Soup parse_ply(std::string_view bytes, const std::filesystem::path& path, LoadReport& report,
               std::size_t split_near);

// STL, binary (when the size matches the header's count) or ASCII; equal corners are welded.
Soup parse_stl(std::string_view bytes, const std::filesystem::path& path, LoadReport& report);

// Refuses, from the first bytes of an OFF file of `file_size` bytes, what its header rules out.
void check_off_start(std::string_view first_bytes, std::uint64_t file_size,
                     const std::filesystem::path& path);

// "OFF" with the optional prefixes of the format: ST (texture), C (colour), N (normal), 4 (4D),
// n (nD). Returns false when `keyword` is no OFF keyword.
bool parse_off_keyword(std::string_view keyword, bool& three_dimensional);

// The triangle count in a binary STL header, and whether the file's size agrees with it.
bool binary_stl_size_matches(std::string_view bytes, std::uint32_t& count);
// The same from a file's first bytes (at least 84) and its size.
bool binary_stl_size_matches(std::string_view first_bytes, std::uint64_t file_size,
                             std::uint32_t& count);

// Refuses, from the first bytes of a PLY file of `file_size` bytes, what its header rules out
// (when those bytes hold the whole header).
void check_ply_start(std::string_view first_bytes, std::uint64_t file_size,
                     const std::filesystem::path& path);

}  // namespace holefill::io
