#include "stage_fill.h"

#include <pybind11/numpy.h>

#include <stdexcept>
#include <vector>

#include "commands.h"
#include "errors.h"
#include "fill_functions.h"
#include "fill_options.h"
#include "holefill/fill.h"
#include "holefill/loop_groups.h"
#include "mesh_object.h"
#include "report.h"

namespace py = pybind11;

namespace holefill::python {
namespace {

const char* const kStageFillDoc = R"doc(Fill(mesh, hole, **options): one hole filled stage by stage.

The mesh is prepared in place as fill() prepares it; `hole` is an id as holefill.holes(mesh)
lists them, filled with the loops fill() fills with it (its islands, the hole bridged to it).
triangulate(), refine() and smooth() each run their stage (and any stage before it not yet
run) and return the hole's record, as fill() returns them; undo() takes the last stage back,
exactly. Each stage keeps a copy of the mesh for undo(). The mesh must not be changed otherwise
while the Fill is used: a fill() or another Fill in between makes the next step raise
holefill.Error.

)doc";

struct Snapshot {
  Mesh mesh;
  HoleFill fill;
};

class StageFill {
 public:
  StageFill(py::object mesh, int hole, const py::kwargs& options)
      : owner_(std::move(mesh)), object_(owner_.cast<MeshObject&>()) {
    arguments_ = fill_arguments(options, py::none());
    std::string notes, problem;
    {
      const MeshUse use(object_);
      const py::gil_scoped_release release;
      prepared_ = prepare_in_place(object_, arguments_, notes);
      problem = choose_loops(hole);
      version_ = object_.version;
    }
    warn_lines(notes);
    if (!problem.empty()) throw cli::UsageError(problem);
  }

  py::object run_to(Stage target) {
    if (fill_.stage() >= target) {
      throw cli::UsageError("hole " + std::to_string(hole_id()) + " is " +
                            to_string(fill_.stage()) + " already (undo() first)");
    }
    {
      const MeshUse use(object_);
      require_unchanged();
      const py::gil_scoped_release release;
      while (fill_.stage() < target && !fill_.failed()) {
        undo_.push_back({Mesh(object_.mesh), fill_});
        if (advance_joined(object_.mesh, loops_, fill_, arguments_.options) != StageRun::Ran) {
          undo_.pop_back();
          break;
        }
      }
      version_ = ++object_.version;
    }
    return record();
  }

  void undo() {
    if (undo_.empty())
      throw cli::UsageError("hole " + std::to_string(hole_id()) + " has no stage to undo");
    const MeshUse use(object_);
    require_unchanged();
    const py::gil_scoped_release release;
    object_.mesh = undo_.back().mesh;
    fill_ = undo_.back().fill;
    undo_.pop_back();
    version_ = ++object_.version;
  }

  py::object record() const {
    require_idle(object_);
    const std::vector<HoleFill> fills{fill_};
    cli::ReportInput report;
    report.input_path = object_.name;
    report.options = &arguments_.options;
    report.prepared = &prepared_;
    report.fills = &fills;
    const py::object document = from_json(cli::json_report(report));
    return document["holes"][py::int_(0)];
  }

  int hole_id() const { return loops_.front()->id; }
  std::string stage() const { return to_string(fill_.stage()); }
  std::vector<int> joined() const {
    std::vector<int> ids;
    for (std::size_t i = 1; i < loops_.size(); ++i) ids.push_back(loops_[i]->id);
    return ids;
  }
  py::array_t<std::int64_t> patch_faces() const {
    std::vector<std::int64_t> ids;
    for (const auto f : fill_.patch.faces) ids.push_back(f.idx());
    return py::array_t<std::int64_t>(static_cast<py::ssize_t>(ids.size()), ids.data());
  }
  py::array_t<std::int64_t> new_vertices() const {
    std::vector<std::int64_t> ids;
    for (const auto v : fill_.patch.new_vertices) ids.push_back(v.idx());
    return py::array_t<std::int64_t>(static_cast<py::ssize_t>(ids.size()), ids.data());
  }

 private:
  // The group of loops fill() would fill with `hole`; a problem (in words) when there is none.
  std::string choose_loops(int hole) {
    const auto& holes = prepared_.holes;
    if (hole < 0 || static_cast<std::size_t>(hole) >= holes.size()) {
      return object_.name + " has no hole " + std::to_string(hole) + " (it has " +
             std::to_string(holes.size()) + ")";
    }
    const IslandMap islands = find_islands(object_.mesh, holes, arguments_.options.islands);
    for (const LoopGroup& group : group_loops(
             object_.mesh, holes, islands, arguments_.selection.bridges, arguments_.options.join)) {
      if (std::find(group.holes.begin(), group.holes.end(), hole) == group.holes.end()) continue;
      if (group.problem.failed())
        return "hole " + std::to_string(hole) + ": " + group.problem.message;
      for (const int id : group.holes) loops_.push_back(&holes[id]);
    }
    return {};
  }

  void require_unchanged() const {
    if (object_.version != version_) {
      throw cli::UsageError(object_.name + ": the mesh changed since this Fill of hole " +
                            std::to_string(hole_id()) + " began; start a new Fill");
    }
  }

  py::object owner_;  // keeps the Python mesh alive
  MeshObject& object_;
  cli::FillArguments arguments_;
  PreparedMesh prepared_;
  std::vector<const Hole*> loops_;
  HoleFill fill_;
  std::vector<Snapshot> undo_;
  std::uint64_t version_ = 0;
};

}  // namespace

void bind_stage_fill(py::module_& module) {
  py::class_<StageFill>(module, "Fill", (kStageFillDoc + options_doc()).c_str())
      .def(py::init<py::object, int, const py::kwargs&>(), py::arg("mesh"), py::arg("hole"))
      .def(
          "triangulate", [](StageFill& f) { return f.run_to(Stage::Triangulated); },
          "Triangulates the hole (the dynamic program under the weight); returns the record.")
      .def(
          "refine", [](StageFill& f) { return f.run_to(Stage::Refined); },
          "Refines the patch to the surrounding density (tau); returns the record.")
      .def(
          "smooth", [](StageFill& f) { return f.run_to(Stage::Smoothed); },
          "Smooths the patch (umbrella or fairing); returns the record.")
      .def("undo", &StageFill::undo, "Puts the mesh back as it was before the last stage run.")
      .def_property_readonly("record", &StageFill::record,
                             "The hole's record after the last stage.")
      .def_property_readonly("hole", &StageFill::hole_id, "The hole's id (the group's first loop).")
      .def_property_readonly("joined_holes", &StageFill::joined,
                             "The loops filled with it: its islands, or the hole bridged to it.")
      .def_property_readonly("stage", &StageFill::stage,
                             "'open', 'triangulated', 'refined' or 'smoothed'.")
      .def_property_readonly("patch_faces", &StageFill::patch_faces,
                             "Indices of the patch's faces in mesh.faces.")
      .def_property_readonly("new_vertices", &StageFill::new_vertices,
                             "Indices of the vertices the patch added, in mesh.vertices.");
}

}  // namespace holefill::python
