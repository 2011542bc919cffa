#include "mesh_input.h"

#include <ostream>

#include "holefill/io.h"

namespace holefill::cli {

Mesh load_and_warn(const std::string& path, const Streams& streams) {
  LoadReport report;
  Mesh mesh = load_mesh(path, &report);
  for (const auto& warning : report.warnings)
    streams.err << "holefill: " << path << ": " << warning << "\n";
  return mesh;
}

}  // namespace holefill::cli
