#include "outputs.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string_view>

#include "holefill/errors.h"
#include "holefill/io.h"
#include "holefill/output_file.h"

namespace holefill::cli {
namespace {

std::filesystem::path mesh_output_name(const FillArguments& a) {
  return std::filesystem::path(a.output == "-" ? "<stdout>." + a.format : a.output);
}

MeshFormat output_format(const FillArguments& a) {
  if (a.output == "-" && a.format.empty()) {
    throw UsageError("writing the mesh to standard output (-o -) needs --format");
  }
  const std::filesystem::path name = mesh_output_name(a);
  if (const std::optional<MeshFormat> format = format_from_path(name)) return *format;
  throw UsageError("-o " + a.output + ": cannot write '" + lowercase_extension(name) +
                   "' files (use .obj, .off, .ply or .stl)");
}

// The mesh output must not be the input: the original would be lost (by any name: a link, a hard
// link, another spelling of the path).
void check_mesh_output_path(const FillArguments& a) {
  if (a.input == "-" || a.output == "-" || !same_file(a.output, a.input)) return;
  throw UsageError("-o " + a.output + " is the input mesh " + a.input +
                   "; holefill will not replace its input (write elsewhere, then move it)");
}

void check_report_path(const FillArguments& a) {
  const std::string& report = a.report_path;
  if (report.empty()) return;
  if (report == "-" && a.output == "-") {
    throw UsageError("-o - and --report - would both go to standard output");
  }
  if (report == "-") return;
  if (a.input != "-" && same_file(report, a.input)) {
    throw UsageError("--report " + report + " is the input mesh " + a.input +
                     "; holefill will not replace it with the report");
  }
  if (a.output != "-" && same_file(report, a.output)) {
    throw UsageError("--report " + report + " is the same file as -o " + a.output);
  }
}

}  // namespace

std::string last_system_error() {
  return errno ? std::string(" (") + std::strerror(errno) + ")" : std::string();
}

MeshFormat check_outputs(const FillArguments& a) {
  const MeshFormat format = output_format(a);
  check_mesh_output_path(a);
  check_report_path(a);
  if (a.output != "-") check_output_file(a.output);
  if (!a.report_path.empty() && a.report_path != "-") check_output_file(a.report_path);
  return format;
}

namespace {

void write_to_stream(std::string_view bytes, std::ostream& out) {
  errno = 0;
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw FileError("standard output", "could not be written" + last_system_error());
}

void flush_stream(std::ostream& out) {
  errno = 0;
  out.flush();
  if (!out) throw FileError("standard output", "could not be written" + last_system_error());
}

}  // namespace

void write_output(const std::string& path, const std::string& bytes, std::ostream& out) {
  if (path != "-") return write_output_file(path, bytes);
  write_to_stream(bytes, out);
  flush_stream(out);
}

// To standard output the mesh goes a piece at a time as it is made, never whole in memory.
void write_mesh_output(const Mesh& mesh, MeshFormat format, const FillArguments& a,
                       std::ostream& out) {
  if (a.output != "-") return save_mesh(mesh, a.output, format, a.options.threads);
  write_mesh_pieces(
      mesh, format, mesh_output_name(a),
      [&out](std::string_view piece) { write_to_stream(piece, out); }, a.options.threads);
  flush_stream(out);
}

std::vector<std::string> mesh_output_losses(const Mesh& mesh, MeshFormat format,
                                            const FillArguments& a) {
  return attributes_not_written(mesh, format, mesh_output_name(a));
}

bool stdout_carries_a_file(const FillArguments& a) {
  return a.output == "-" || a.report_path == "-";
}

}  // namespace holefill::cli
