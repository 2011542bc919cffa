// The dispatcher: picks the reader by contents and extension, turns its polygons into a mesh,
// and writes a mesh through the writer and one atomic file write.
#include "holefill/io.h"

#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>

#include "file_bytes.h"
#include "holefill/output_file.h"
#include "readers.h"
#include "soup_to_mesh.h"
#include "text_scan.h"
#include "writers.h"

namespace holefill {
namespace fs = std::filesystem;
namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

// The format to read `bytes` as: the contents' where they are unmistakable (with a warning when
// the extension says otherwise), else the extension's.
io::Format choose_format(std::string_view bytes, const fs::path& name, LoadReport& report) {
  const std::string ext = lower_extension(name);
  const io::Format by_name = io::format_of_extension(ext);
  io::Format by_content = io::sniff(bytes);
  if (by_content == io::Format::Unknown) by_content = io::sniff(io::without_byte_order_mark(bytes));
  if (by_content == io::Format::Unknown || by_content == by_name) {
    if (by_name == io::Format::Unknown) {
      io::fail(name, "unsupported file type '" + ext + "' (use .obj, .off, .ply or .stl)");
    }
    return by_name;
  }
  const std::string read_as = upper(io::name_of(by_content));
  report.warnings.push_back(by_name == io::Format::Unknown
                                ? "the extension '" + ext +
                                      "' is not a mesh format; the contents are " + read_as +
                                      " and were read as such"
                                : "the contents are " + read_as + ", not what the extension '" +
                                      ext + "' says; read as " + read_as);
  return by_content;
}

io::Soup read_soup(io::Format format, std::string_view bytes, const fs::path& name,
                   LoadReport& report) {
  switch (format) {
    case io::Format::Obj:
      return io::parse_obj(bytes, name, report);
    case io::Format::Off:
      return io::parse_off(bytes, name, report);
    case io::Format::Ply:
      return io::parse_ply(bytes, name, report);
    case io::Format::Stl:
      return io::parse_stl(bytes, name, report);
    case io::Format::Unknown:
      break;
  }
  io::fail(name, "unsupported file type");
}

// Refuses, from its first bytes, a file the whole of which could not be read, so that a huge
// file is not read into memory first. A binary STL is recognised by its size.
void check_start(const io::FileStart& start, const fs::path& path) {
  std::uint32_t count = 0;
  const std::string_view first = start.bytes;
  if (io::binary_stl_size_matches(first, start.size, count)) return;
  LoadReport ignored;
  const io::Format format = choose_format(first, path, ignored);
  const std::string_view text = io::without_byte_order_mark(first);
  switch (format) {
    case io::Format::Obj:
      io::require_text(text, path, "OBJ");
      break;
    case io::Format::Off:
      io::check_off_start(text, start.size - (first.size() - text.size()), path);
      break;
    case io::Format::Ply:
      io::check_ply_start(text, start.size - (first.size() - text.size()), path);
      break;
    case io::Format::Stl:
    case io::Format::Unknown:
      break;
  }
}

// The polygons `bytes` describe, read by the reader their contents and name choose (the report's
// format set).
io::Soup soup_of_bytes(const std::string& bytes, const fs::path& name, LoadReport& report) {
  // OpenMesh prints why add_face refuses a face; we count those faces and say so instead.
  omerr().disable();
  if (bytes.empty()) io::fail(name, "is empty");
  const io::Format format = choose_format(bytes, name, report);
  report.format = io::name_of(format);
  std::uint32_t triangles = 0;  // a binary STL's header may start with any bytes
  const std::string_view text = io::binary_stl_size_matches(bytes, triangles)
                                    ? std::string_view(bytes)
                                    : io::without_byte_order_mark(bytes);
  return read_soup(format, text, name, report);
}

Mesh mesh_of_soup(io::Soup soup, const fs::path& name, LoadReport& report) {
  Mesh mesh = io::build_mesh(std::move(soup), report);
  if (mesh.n_faces() == 0) throw InvalidMeshError(name, "contains no faces");
  io::add_warnings(report);
  return mesh;
}

bool has_deleted_elements(const Mesh& mesh) {
  const auto live_vertices =
      static_cast<std::size_t>(std::distance(mesh.vertices().begin(), mesh.vertices().end()));
  const auto live_faces =
      static_cast<std::size_t>(std::distance(mesh.faces().begin(), mesh.faces().end()));
  return live_vertices != mesh.n_vertices() || live_faces != mesh.n_faces();
}

}  // namespace

const std::vector<std::string>& readable_extensions() {
  static const std::vector<std::string> extensions{".obj", ".off", ".ply", ".stl"};
  return extensions;
}

const std::vector<std::string>& writable_extensions() {
  static const std::vector<std::string> extensions{".obj", ".off", ".ply", ".stl"};
  return extensions;
}

Mesh load_mesh_from_memory(const std::string& bytes, const fs::path& name, LoadReport* report) {
  LoadReport local;
  LoadReport& out = report ? *report : local;
  out = LoadReport{};
  return mesh_of_soup(soup_of_bytes(bytes, name, out), name, out);
}

Mesh load_mesh(const fs::path& path, LoadReport* report) {
  const io::FileStart start = io::read_file_start(path);
  if (start.size > start.bytes.size()) check_start(start, path);
  LoadReport local;
  LoadReport& out = report ? *report : local;
  out = LoadReport{};
  // The file's bytes are freed before the mesh is built, so that they are not held at the peak.
  io::Soup soup = soup_of_bytes(io::read_file_bytes(path), path, out);
  return mesh_of_soup(std::move(soup), path, out);
}

// The extension of `name`, lower case, when it is a format save_mesh writes; else throws
// FileError naming `name`.
std::string writable_extension(const fs::path& name) {
  const std::string ext = lower_extension(name);
  const auto& writable = writable_extensions();
  if (std::find(writable.begin(), writable.end(), ext) == writable.end()) {
    throw FileError(name, "cannot write '" + ext + "' files (use .obj, .off, .ply or .stl)");
  }
  return ext;
}

void write_mesh_pieces(const Mesh& mesh, const fs::path& name, const ByteWriter& write) {
  const std::string ext = writable_extension(name);
  // Indices in the file must count live elements only.
  if (has_deleted_elements(mesh)) {
    Mesh compacted = mesh;
    compacted.garbage_collection();
    return io::write_mesh_file(compacted, ext, name, write);
  }
  io::write_mesh_file(mesh, ext, name, write);
}

std::string mesh_to_bytes(const Mesh& mesh, const fs::path& name) {
  std::string bytes;
  write_mesh_pieces(mesh, name, [&bytes](std::string_view piece) { bytes += piece; });
  return bytes;
}

// The file is written as it is made, a piece at a time, never whole in memory.
void save_mesh(const Mesh& mesh, const fs::path& path) {
  writable_extension(path);  // before the output file is begun
  write_output_file(path, [&](const ByteWriter& write) { write_mesh_pieces(mesh, path, write); });
}

}  // namespace holefill
