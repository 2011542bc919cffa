#include "fill_functions.h"

#include <vector>

#include "commands.h"
#include "errors.h"
#include "fill_options.h"
#include "hole_selection.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/prepare.h"
#include "preparation.h"
#include "python_progress.h"
#include "report.h"

namespace py = pybind11;

namespace holefill::python {
namespace {

const char* const kFillDoc =
    R"doc(Fills the mesh's holes in place, as `holefill fill` does, and returns one record
per filled group of loops (the "holes" of fill's JSON report: hole, boundary_edges, filled,
stage, failure, failure_kind, notes, self_intersections, new_vertices, new_faces, angles, area, valence
histogram, seconds).

The mesh is prepared first as the command prepares it (seams stitched, small pieces removed
when asked, borders kept when asked), each step named in a HolefillWarning; hole ids are those
holefill.holes(mesh) gives with the same options. holes: ids to fill (None: every hole but the
rims of flat pieces and, with keep_borders, borders). Refused ids raise holefill.Error after the
preparation, which then stays applied.

The work runs without the GIL, on every core. progress: None or callable(fraction) called as
the holes are triangulated (0 to 0.5) and added (0.5 to 1); returning False cancels: a cancel
during the triangulations leaves the mesh as it was and returns [], a later one stops before the
next hole and returns the records of the patches added. An exception in the callback, or Ctrl-C,
cancels the same way and is then raised. Out of memory raises MemoryError, the mesh unchanged.

)doc";

std::string with_options(const char* doc) { return doc + options_doc(); }

// The preparation's messages as the command prints them on stderr, without "holefill: ", naming
// the options by their Python names (remove_small_components=N removes small pieces).
std::string lines_of(const PreparedMesh& prepared, const std::string& name) {
  const auto option = [](std::size_t faces) {
    return "remove_small_components=" + std::to_string(faces);
  };
  std::string text;
  for (const auto& message : cli::preparation_lines(prepared, option))
    text += name + ": " + python_message(message) + "\n";
  return text;
}

// info's JSON document for the mesh as fill would prepare it (on a copy: the mesh is unchanged).
py::object info_document(MeshObject& object, const py::kwargs& options) {
  cli::FillArguments a = fill_arguments(options, py::none());
  std::string notes, json;
  {
    const MeshUse use(object);
    const py::gil_scoped_release release;
    Mesh mesh(object.mesh);
    const PreparedMesh prepared = prepare_mesh(mesh, a.preparation);
    notes = lines_of(prepared, object.name);
    json = cli::json_info(object.name, mesh, prepared);
  }
  warn_lines(notes);
  return from_json(json);
}

py::object fill(MeshObject& object, py::object holes, py::object progress,
                const py::kwargs& options) {
  cli::FillArguments a = fill_arguments(options, holes);
  PythonProgress watcher(std::move(progress));
  std::string notes, json;
  {
    const MeshUse use(object);
    const py::gil_scoped_release release;
    Mesh& mesh = object.mesh;
    const PreparedMesh prepared = prepare_in_place(object, a, notes);
    cli::ReportInput report;
    report.input_path = object.name;
    report.options = &a.options;
    report.prepared = &prepared;
    report.vertices_before = mesh.n_vertices();
    report.faces_before = mesh.n_faces();
    report.holes_before = prepared.holes.size();
    if (a.selection.hole_ids.empty()) a.selection.hole_ids = prepared.ids_to_fill;
    const auto fills = a.selection.hole_ids.empty()
                           ? std::vector<HoleFill>{}
                           : fill_holes(mesh, prepared.holes, prepared.islands, a.options,
                                        a.selection, watcher.progress());
    const std::string unwelded = undo_unused_welds(mesh, prepared.weld);
    if (!unwelded.empty()) notes += object.name + ": " + unwelded + "\n";
    ++object.version;
    report.vertices_after = mesh.n_vertices();
    report.faces_after = mesh.n_faces();
    report.holes_after = find_holes(mesh).size();
    report.fills = &fills;
    json = cli::json_report(report);
  }
  warn_lines(notes);
  watcher.raise_if_failed();
  return py::object(from_json(json)["holes"]);
}

}  // namespace

PreparedMesh prepare_in_place(MeshObject& object, cli::FillArguments& a, std::string& notes) {
  PreparedMesh prepared = prepare_mesh(object.mesh, a.preparation);
  ++object.version;
  notes += lines_of(prepared, object.name);
  a.input = object.name;
  try {
    cli::select_holes(a, prepared.holes);
  } catch (const cli::UsageError& e) {
    throw cli::UsageError(python_message(e.what()));
  }
  return prepared;
}

py::object from_json(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

void bind_fill_functions(py::module_& module) {
  module.attr("FILL_OPTIONS") = option_defaults();
  module.def("info", &info_document, py::arg("mesh"),
             "What `holefill info --json` prints for the mesh: counts, the preparation "
             "(stitching, pieces, loops that are not plain holes) and every hole, as a dict. The "
             "mesh is prepared on a copy, as fill would prepare it with the same options (any of "
             "fill's may be given); the mesh itself is unchanged.");
  module.def(
      "holes",
      [](MeshObject& object, const py::kwargs& options) {
        return py::object(info_document(object, options)["holes"]);
      },
      py::arg("mesh"),
      "The mesh's holes as `holefill info --json` lists them: dicts with id, boundary_edges, "
      "perimeter, pinched, kind (hole, border, flat piece), islands, island_of and problem "
      "where they apply. The ids are those fill takes with the same options (info(mesh) says "
      "more); the mesh is unchanged.");
  module.def("fill", &fill, py::arg("mesh"), py::arg("holes") = py::none(), py::kw_only(),
             py::arg("progress") = py::none(), with_options(kFillDoc).c_str());
}

}  // namespace holefill::python
