// The dispatcher: decides a file's format once (by contents and extension) and hands it to that
// reader, turns its polygons into a mesh, and writes a mesh through the writer of the format its
// path names (mesh_format.h) and one atomic file write.
#include "holefill/io.h"

#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <optional>

#include "../available_cores.h"
#include "file_bytes.h"
#include "holefill/output_file.h"
#include "readers.h"
#include "soup_to_mesh.h"
#include "text_scan.h"
#include "writers.h"

namespace holefill {
namespace fs = std::filesystem;
namespace {

std::string upper(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}

// The format to read a file as, from `first`, the start of it (`size` bytes in all): the
// contents' where they are unmistakable (with a warning when the extension says otherwise), else
// the extension's. None when more of the file could change that (io::sniff_start): never for the
// whole file.
std::optional<MeshFormat> choose_format(std::string_view first, std::uint64_t size,
                                        const fs::path& name, LoadReport& report) {
  const std::optional<MeshFormat> by_name = format_from_path(name);
  io::Sniffed by_content = io::sniff_start(first, size);
  if (by_content.decided && !by_content.format) {
    const std::string_view text = io::without_byte_order_mark(first);
    by_content = io::sniff_start(text, size - (first.size() - text.size()));
  }
  if (!by_content.decided) return std::nullopt;
  const std::string ext = lowercase_extension(name);
  if (!by_content.format || by_content.format == by_name) {
    if (!by_name)
      io::fail(name, "unsupported file type '" + ext + "' (use .obj, .off, .ply or .stl)");
    return by_name;
  }
  const std::string read_as = upper(name_of(*by_content.format));
  report.warnings.push_back(
      !by_name ? "the extension '" + ext + "' is not a mesh format; the contents are " + read_as +
                     " and were read as such"
               : "the contents are " + read_as + ", not what the extension '" + ext +
                     "' says; read as " + read_as);
  return by_content.format;
}

// On one thread a text is read whole (never cut in two), else as the readers choose.
io::Soup read_soup(MeshFormat format, std::string_view bytes, const fs::path& name,
                   LoadReport& report, unsigned threads) {
  const bool one = threads == 1;
  switch (format) {
    case MeshFormat::Obj:
      return one ? io::parse_obj(bytes, name, report, std::string_view::npos)
                 : io::parse_obj(bytes, name, report);
    case MeshFormat::Off:
      return one ? io::parse_off(bytes, name, report, std::string_view::npos)
                 : io::parse_off(bytes, name, report);
    case MeshFormat::Ply:
      return one ? io::parse_ply(bytes, name, report, std::string_view::npos)
                 : io::parse_ply(bytes, name, report);
    case MeshFormat::Stl:
      return io::parse_stl(bytes, name, report);
  }
  io::fail(name, "unsupported file type");
}

// Refuses, from its first bytes, a file of `format` the whole of which could not be read, so
// that a huge file is not read into memory first. A binary STL is recognised by its size.
void check_start(const io::FileStart& start, MeshFormat format, const fs::path& path) {
  std::uint32_t count = 0;
  const std::string_view first = start.bytes;
  if (io::binary_stl_size_matches(first, start.size, count)) return;
  const std::string_view text = io::without_byte_order_mark(first);
  switch (format) {
    case MeshFormat::Obj:
      io::require_text(text, path, "OBJ");
      break;
    case MeshFormat::Off:
      io::check_off_start(text, start.size - (first.size() - text.size()), path);
      break;
    case MeshFormat::Ply:
      io::check_ply_start(text, start.size - (first.size() - text.size()), path);
      break;
    case MeshFormat::Stl:
      break;
  }
}

// The polygons `bytes` describe, read as `format` when the file's start decided it, else as the
// contents and name choose (the report's format set).
io::Soup soup_of_bytes(const std::string& bytes, const fs::path& name, LoadReport& report,
                       std::optional<MeshFormat> format, unsigned threads) {
  // OpenMesh prints why add_face refuses a face; we count those faces and say so instead.
  omerr().disable();
  if (bytes.empty()) io::fail(name, "is empty");
  if (!format) format = choose_format(bytes, bytes.size(), name, report);
  report.format = name_of(*format);
  std::uint32_t triangles = 0;  // a binary STL's header may start with any bytes
  const std::string_view text = io::binary_stl_size_matches(bytes, triangles)
                                    ? std::string_view(bytes)
                                    : io::without_byte_order_mark(bytes);
  return read_soup(*format, text, name, report, threads);
}

Mesh mesh_of_soup(io::Soup soup, const fs::path& name, LoadReport& report, unsigned threads) {
  Mesh mesh = io::build_mesh(std::move(soup), report,
                             threads == 1 ? io::kOneThreadAlways : io::kTwoThreadsFrom);
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

// The format save_mesh writes `name` in; throws FileError naming `name` for another extension.
MeshFormat writable_format(const fs::path& name) {
  if (const std::optional<MeshFormat> format = format_from_path(name)) return *format;
  throw FileError(name, "cannot write '" + lowercase_extension(name) +
                            "' files (use .obj, .off, .ply or .stl)");
}

std::vector<std::string> all_extensions() {
  std::vector<std::string> extensions;
  for (const MeshFormat format : kMeshFormats) extensions.emplace_back(extension_of(format));
  return extensions;
}

}  // namespace

const std::vector<std::string>& readable_extensions() {
  static const std::vector<std::string> extensions = all_extensions();
  return extensions;
}

const std::vector<std::string>& writable_extensions() {
  static const std::vector<std::string> extensions = all_extensions();
  return extensions;
}

Mesh load_mesh_from_memory(const std::string& bytes, const fs::path& name, LoadReport* report,
                           unsigned threads) {
  LoadReport local;
  LoadReport& out = report ? *report : local;
  out = LoadReport{};
  return mesh_of_soup(soup_of_bytes(bytes, name, out, std::nullopt, threads), name, out, threads);
}

// The format is decided once: from the file's start when the file is bigger (to check that start
// before the rest is read), else from all of it.
Mesh load_mesh(const fs::path& path, LoadReport* report, unsigned threads) {
  const io::FileStart start = io::read_file_start(path);
  LoadReport local;
  LoadReport& out = report ? *report : local;
  out = LoadReport{};
  std::optional<MeshFormat> format;
  if (start.size > start.bytes.size()) {
    format = choose_format(start.bytes, start.size, path, out);
    if (format) check_start(start, *format, path);
  }
  // The file's bytes are freed before the mesh is built, so that they are not held at the peak.
  io::Soup soup = soup_of_bytes(io::read_file_bytes(path), path, out, format, threads);
  return mesh_of_soup(std::move(soup), path, out, threads);
}

void write_mesh_pieces(const Mesh& mesh, MeshFormat format, const fs::path& name,
                       const ByteWriter& write, unsigned threads) {
  if (threads == 0) threads = detail::available_cores();
  // Indices in the file must count live elements only.
  if (has_deleted_elements(mesh)) {
    Mesh compacted = mesh;
    compacted.garbage_collection();
    return io::write_mesh_file(compacted, format, name, write, threads);
  }
  io::write_mesh_file(mesh, format, name, write, threads);
}

void write_mesh_pieces(const Mesh& mesh, const fs::path& name, const ByteWriter& write,
                       unsigned threads) {
  write_mesh_pieces(mesh, writable_format(name), name, write, threads);
}

std::string mesh_to_bytes(const Mesh& mesh, const fs::path& name, unsigned threads) {
  std::string bytes;
  write_mesh_pieces(
      mesh, name, [&bytes](std::string_view piece) { bytes += piece; }, threads);
  return bytes;
}

// The file is written as it is made, a piece at a time, never whole in memory.
void save_mesh(const Mesh& mesh, const fs::path& path, MeshFormat format, unsigned threads) {
  write_output_file(path, [&](const ByteWriter& write) {
    write_mesh_pieces(mesh, format, path, write, threads);
  });
}

void save_mesh(const Mesh& mesh, const fs::path& path, unsigned threads) {
  save_mesh(mesh, path, writable_format(path), threads);  // decided before the file is begun
}

}  // namespace holefill
