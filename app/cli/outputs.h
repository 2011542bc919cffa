// Where `holefill fill` puts its results: the mesh (-o) and the JSON report (--report), each a
// path or "-" for standard output. Checked before any work, written after it.
#pragma once

#include <iosfwd>
#include <string>

#include "commands.h"
#include "holefill/mesh.h"
#include "holefill/mesh_format.h"

namespace holefill::cli {

// Before any work: throws UsageError when the outputs cannot be meant (the report naming the
// input or the mesh output, by file identity; both on standard output; a format holefill cannot
// write), FileError when an output cannot be written (its folder missing or read-only, a
// read-only file, a loop of links), with the reason. Returns the mesh output's format (-o's
// extension, or --format for standard output), decided here once.
MeshFormat check_outputs(const FillArguments& arguments);

// Writes `bytes` to `path`, or to `out` when `path` is "-". Throws FileError with the reason.
void write_output(const std::string& path, const std::string& bytes, std::ostream& out);

// Writes the mesh's file in `format` (check_outputs') to -o (save_mesh: as it is made, never
// whole in memory), or to standard output for "-"; throws FileError as write_output does.
void write_mesh_output(const Mesh& mesh, MeshFormat format, const FillArguments& arguments,
                       std::ostream& out);

// What that file leaves out of what the mesh carries (io.h: attributes_not_written).
std::vector<std::string> mesh_output_losses(const Mesh& mesh, MeshFormat format,
                                            const FillArguments& arguments);

// " (REASON)" for the last system call's error number, or "" when it is 0 (clear errno first).
std::string last_system_error();

// Whether standard output carries a file (the mesh or the report), so the table goes to stderr.
bool stdout_carries_a_file(const FillArguments& arguments);

}  // namespace holefill::cli
