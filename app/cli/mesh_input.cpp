#include "mesh_input.h"

#include <istream>
#include <iterator>
#include <ostream>

#include "holefill/io.h"

namespace holefill::cli {

Mesh load_and_warn(const std::string& path, const std::string& format, const Streams& streams) {
  LoadReport report;
  Mesh mesh;
  if (path == "-") {
    if (format.empty()) throw UsageError("reading a mesh from standard input needs --format");
    const std::string bytes{std::istreambuf_iterator<char>(streams.in),
                            std::istreambuf_iterator<char>()};
    mesh = load_mesh_from_memory(bytes, "<stdin>." + format, &report);
  } else {
    mesh = load_mesh(path, &report);
  }
  for (const auto& warning : report.warnings)
    streams.err << "holefill: " << path << ": " << warning << "\n";
  return mesh;
}

}  // namespace holefill::cli
