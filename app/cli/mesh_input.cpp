#include "mesh_input.h"

#include <istream>
#include <iterator>
#include <ostream>

#include "holefill/io.h"

namespace holefill::cli {

namespace {

// Returned, never assigned: assigning a Mesh copies it (OpenMesh's kernel has no move
// assignment), which held two meshes at the peak of loading and left the kept one without the
// room for patches that loading gives it.
Mesh read_mesh(const std::string& path, const std::string& format, const Streams& streams,
               LoadReport& report, unsigned threads) {
  if (path != "-") return load_mesh(path, &report, threads);
  if (format.empty()) throw UsageError("reading a mesh from standard input needs --format");
  const std::string bytes{std::istreambuf_iterator<char>(streams.in),
                          std::istreambuf_iterator<char>()};
  return load_mesh_from_memory(bytes, "<stdin>." + format, &report, threads);
}

}  // namespace

Mesh load_and_warn(const std::string& path, const std::string& format, const Streams& streams,
                   unsigned threads) {
  LoadReport report;
  Mesh mesh = read_mesh(path, format, streams, report, threads);
  for (const auto& warning : report.warnings)
    streams.err << "holefill: " << path << ": " << warning << "\n";
  return mesh;
}

}  // namespace holefill::cli
