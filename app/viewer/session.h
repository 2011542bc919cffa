// What the user is working on: the open mesh, its holes (found once, at load), each hole's
// progress through the stages (holefill::advance), the fill options, undo/redo, and the
// comparison of two weights on the selected hole. No GL and no window: tests drive it directly.
//
// The session's state is a log of stage steps (replay.h), each "advance hole h with these
// options", applied in order to the mesh as loaded. A step extends the log and runs on the
// current mesh; undo, redo, reset and an option change give another log, whose mesh is rebuilt
// from the states kept before the selected hole's steps (a change of τ re-runs refinement and
// smoothing only) or, failing that, by replaying the log from the loaded mesh. Replay runs the
// same operations in the same order, so undo restores the mesh exactly, and the history costs a
// few bytes per step instead of a mesh copy. Each long operation comes as a request that
// compute() runs (on a worker, with progress and cancel) and apply() takes in.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "comparison.h"
#include "feature_view.h"
#include "holefill/fill.h"
#include "holefill/prepare.h"
#include "holefill/progress.h"
#include "replay.h"

namespace holefill::viewer {

struct Notice {
  std::string text;
  bool error = false;
};

// Which holes a fill takes, in order, and how far: one stage, or every remaining stage.
struct FillRequest {
  std::vector<int> hole_ids;
  bool one_stage = false;
  bool summarise = false;  // say afterwards how many were filled, refused, intersecting
  FillOptions options;
  // The loops a listed hole is filled with (its islands, the hole it is bridged to); none when
  // absent.
  std::map<int, std::vector<int>> joined;
  std::size_t borders_left = 0;  // loops the preparation leaves out (prepare.h), skipped
};

// What a fill made, computed apart from the session (Session::compute) and taken in as one
// undoable action (Session::apply).
struct FillResult {
  MeshState state;
  Checkpoints checkpoints;
  std::vector<FillStep> log;
  bool mesh_changed = false;  // some stage ran
  bool all_ran = true;        // no stage failed
  Notice notice;
};

// Undo, redo, resetting the selected hole or changing its options: another log, whose mesh
// Session::compute rebuilds and Session::apply takes in.
struct LogChange {
  enum class Kind { Undo, Redo, Reset, Options, Keep };  // Keep: a side of the comparison
  Kind kind = Kind::Undo;
  std::vector<FillStep> log;
  int selected = -1;
  std::uint64_t revision = 0;  // undo, redo: the revision of that state
  FillOptions options;         // the options the session shows afterwards
  // Undo, redo: the loops selected with `selected` then (shift-click), restored with it.
  std::optional<std::vector<int>> joined;
};

struct ChangeResult {
  LogChange change;
  Rebuilt rebuilt;
};

// A comparison to make (Session::comparison_request), and what it made.
struct ComparisonRequest {
  int hole_id = -1;
  std::vector<int> joined;  // the loops filled with it (Session::joined)
  FillOptions options;
  CompareMode mode = CompareMode::Weights;
  bool triangulation_only = false;
  std::uint64_t generation = 0;
};

struct ComparisonResult {
  Comparison comparison;
  std::uint64_t generation = 0;
};

class Session {
 public:
  // Opens a mesh file. On failure the current mesh stays and notice() says why. With `progress`:
  // reports the read (0.6) and the preparation (0.9) done, and once cancelled stops after the
  // one under way (false, the session unchanged). The preparation removes the pieces of at most
  // `remove_pieces_up_to` faces (0: none; PrepareOptions::remove_pieces_up_to), the largest kept.
  bool open(const std::filesystem::path& path, Progress* progress = nullptr,
            std::size_t remove_pieces_up_to = 0);
  // Starts over on `mesh` (named `name` in the UI), taken as it is: holes found, nothing stitched
  // or welded (open() prepares a file's mesh as the command-line tool does).
  void load(Mesh mesh, std::string name);
  // Writes the current mesh (format by extension: save_mesh); notice() reports either way.
  // A successful save makes the current state the saved one (modified() turns false).
  bool save(const std::filesystem::path& path);
  // True when the mesh differs from the one last opened or saved: a fill, reset or option
  // change since then that undo has not taken back.
  bool modified() const { return revision_ != saved_revision_; }

  const std::string& name() const { return name_; }
  // The lone triangles and small pieces the preparation found beside the surface (prepare.h):
  // "Remove small pieces" opens the file again without those of at most
  // pieces().largest_small_piece faces.
  const PieceCounts& pieces() const { return pieces_; }
  const Mesh& mesh() const { return state_->mesh; }
  const std::vector<Hole>& holes() const { return holes_; }
  // Whether loop `hole_id` looks like the border of an open surface (borders.h).
  bool is_border(int hole_id) const { return borders_.at(hole_id); }
  const HoleFill& fill(int hole_id) const { return state_->fills.at(hole_id); }
  // A new number whenever mesh() changes (unique across sessions), so a renderer knows when to
  // upload it again.
  std::uint64_t mesh_version() const { return mesh_version_; }
  const Notice& notice() const { return notice_; }
  void clear_notice() { notice_ = {}; }
  // Shows a message of the application's own (e.g. where a screenshot went).
  void tell(Notice notice) { notice_ = std::move(notice); }

  // The selected hole, -1 for none. Selecting an island that has not been filled selects the
  // hole it lies in, and selecting a loop that another hole's patch closed selects that hole.
  int selected() const { return selected_; }
  // The sharp features entering the selected hole under the options (feature_view.h), found on
  // the mesh as loaded; none without a selection. features_version() changes when they do.
  const HoleFeatures& selected_features() const;
  std::uint64_t features_version() const { return features_.version(); }
  void select(int hole_id);
  // The loops filled together with the selected hole (one patch around them): its islands as
  // found at load (islands.h), or what shift-click made of them, or the hole to bridge to.
  // Empty for a lone hole. A filled hole's are the ones its patch closed.
  const std::vector<int>& joined() const { return joined_; }
  bool in_selection(int hole_id) const;
  // Shift-click: adds loop `hole_id` to the selection, or takes it out (the selected hole
  // itself too: the next loop takes its place). False, with a notice, when the selected hole is
  // filled already (reset it first) or the loop is filled or closed by another patch.
  bool toggle(int hole_id);
  // The islands found at load.
  const IslandMap& islands() const { return islands_; }
  // The hole whose patch also closed loop `hole_id`; -1 when none.
  int closed_by(int hole_id) const;
  // Why "Bridge" cannot close the gap between the selected loops: not exactly two loops, the
  // first filled already, or the loops too far apart (JoinOptions::max_gap, as the command
  // line's --bridge). Empty when it can: fill_selected() then joins the two with one band.
  const std::string& bridge_problem() const { return bridge_problem_; }

  // The threads that open, prepare and fill (load_mesh's, PrepareOptions::threads,
  // FillOptions::threads; 0: every core this process may run on). The machine's business, not
  // the fill's: no step logs it and a change re-runs nothing; every later open, step, replay and
  // comparison runs on it. Set it only while no compute() runs (it reads it).
  unsigned threads() const { return threads_; }
  void set_threads(unsigned threads) { threads_ = threads; }

  // The options the next step uses. Setting them while the selected hole has been stepped
  // re-runs that hole's steps with the new options, so its statistics stay live (from the
  // first stage they change: τ re-runs refinement and smoothing, not the triangulation).
  const FillOptions& options() const { return options_; }
  void set_options(const FillOptions& options);

  // The stage the selected hole's next step would produce; nothing when it cannot step
  // (no selection, all stages done, or a stage failed).
  std::optional<Stage> next_stage() const;
  bool can_step(Stage stage) const { return next_stage() == stage; }
  // Runs `stage` on the selected hole when it is the next one.
  bool step(Stage stage);
  // Runs the selected hole's remaining stages.
  bool fill_selected();
  // Runs every hole's remaining stages with the current options (only holes of at most
  // `max_edges` boundary edges when it is not 0; each with its islands; not the borders of open
  // surfaces, which the user fills one by one) and says how many were filled.
  bool fill_all(std::size_t max_edges = 0);

  // The same three as requests, for running them elsewhere (nothing when there is nothing to
  // do), then compute() and apply(): step(s) is apply(compute(*step_request(s))).
  std::optional<FillRequest> step_request(Stage stage) const;
  std::optional<FillRequest> fill_selected_request() const;
  std::optional<FillRequest> fill_all_request(std::size_t max_edges = 0) const;
  // Runs `request` on copies of the mesh, the fills and the log. It only reads the session, so
  // it may run on another thread while nothing steps, undoes, resets or changes options.
  // Checks `progress` between holes: nothing when cancelled (the session never changed).
  std::optional<FillResult> compute(const FillRequest& request, Progress* progress = nullptr) const;
  // Takes a computed result in, as one undoable action.
  void apply(FillResult result);
  // Takes the selected hole's patch out again.
  bool reset_selected();

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  bool undo();
  bool redo();

  // The same four as log changes, for running them elsewhere: undo() is
  // apply(*compute(*undo_request())). Nothing when there is nothing to do;
  // options_request(options) also when the selected hole has no steps (set_options then only
  // sets them).
  std::optional<LogChange> undo_request() const;
  std::optional<LogChange> redo_request() const;
  std::optional<LogChange> reset_request() const;
  std::optional<LogChange> options_request(const FillOptions& options) const;
  // The comparison's left or right result as the selected hole's fill: its steps with that
  // side's options, up to the side's last stage, in place of the hole's own; turns the
  // comparison off. Nothing when no comparison is showing.
  std::optional<LogChange> keep_request(bool right) const;
  // Rebuilds the mesh of `change`'s log. Reads the session only, like compute(FillRequest);
  // reports the share of the steps it re-runs; nothing when cancelled.
  std::optional<ChangeResult> compute(const LogChange& change, Progress* progress = nullptr) const;
  void apply(ChangeResult result);
  static constexpr std::size_t kHistoryLimit = 200;

  const std::vector<FillStep>& log() const { return log_; }

  // Valence histogram of every vertex of mesh(), cached per mesh version.
  const std::map<int, std::size_t>& mesh_valences();

  // The comparison of liepa and maxmin on the selected hole (filled from the mesh without that
  // hole's own patch), recomputed when the selection, the options or the mesh change.
  void set_compare(bool on);
  bool compare() const { return compare_; }
  void set_compare_triangulation_only(bool on);
  // What the comparison sets side by side: the weights (default) or the smoothing.
  void set_compare_mode(CompareMode mode);
  CompareMode compare_mode() const { return compare_mode_; }
  bool compare_triangulation_only() const { return compare_triangulation_only_; }
  // Nothing when comparison is off or no hole is selected. Computes it here when out of date
  // (scripts, tests); the window computes it on the worker instead (comparison_request).
  const Comparison* comparison();
  // The comparison to compute, when it shows and is out of date; compute() makes it (reading
  // the session only) and apply() shows it, unless something changed meanwhile (then another
  // request follows).
  std::optional<ComparisonRequest> comparison_request() const;
  std::optional<ComparisonResult> compute(const ComparisonRequest& request,
                                          Progress* progress = nullptr) const;
  void apply(ComparisonResult result);
  // The last comparison made for the selected hole, possibly out of date; nothing when
  // comparison is off, no hole is selected or none was made for it yet.
  const Comparison* shown_comparison() const;
  std::uint64_t comparison_version() const { return comparison_version_; }

 private:
  // Starts over on `mesh` as `prepared` found it (its holes, their kinds, which to fill).
  void adopt(Mesh mesh, std::string name, PreparedMesh prepared);
  struct Snapshot {
    std::vector<FillStep> log;
    int selected = -1;
    std::vector<int> joined;
    std::uint64_t revision = 0;
  };

  void remember();
  // Undo or redo to the state `to`.
  LogChange return_to(LogChange::Kind kind, const Snapshot& to) const;
  void take(std::shared_ptr<const MeshState> state, Checkpoints checkpoints);
  bool run(const std::optional<FillRequest>& request);
  bool run(const std::optional<LogChange>& change);
  bool has_steps(int hole_id) const;
  std::vector<int> default_joined(int hole_id) const;
  void selection_changed();
  void changed();
  void revised();

  std::string name_;
  PieceCounts pieces_;
  // The mesh as loaded, and the one the log makes of it with every hole's fill: shared, not
  // copied, with the checkpoints that keep them (a million-face mesh is about 100 MB).
  std::shared_ptr<const MeshState> loaded_ = std::make_shared<const MeshState>();
  std::shared_ptr<const MeshState> state_ = loaded_;
  std::uint64_t loaded_version_ = 0;  // a new number for each mesh adopted
  mutable FeatureView features_;      // the selected hole's, cached
  std::vector<Hole> holes_;
  std::vector<bool> borders_;   // per hole, from classify_loops
  std::vector<bool> fillable_;  // per hole: among the preparation's ids_to_fill (prepare.h)
  WeldReport welds_;  // where the preparation welded touching holes (save() undoes unused welds)
  std::vector<FillStep> log_;
  Checkpoints checkpoints_;
  std::vector<Snapshot> undo_;
  std::vector<Snapshot> redo_;
  // Which state of the log the mesh shows: a new number for every edit, the snapshot's on undo
  // and redo, so that undoing back to the saved state reads as unmodified.
  std::uint64_t revision_ = 0;
  std::uint64_t saved_revision_ = 0;
  std::uint64_t last_revision_ = 0;
  bool last_change_was_options_ = false;
  int selected_ = -1;
  std::vector<int> joined_;
  std::string bridge_problem_;
  IslandMap islands_;
  FillOptions options_;
  unsigned threads_ = 0;
  Notice notice_;
  std::uint64_t mesh_version_ = 0;
  std::uint64_t valences_version_ = ~std::uint64_t{0};
  std::map<int, std::size_t> valences_;

  bool compare_ = false;
  bool compare_triangulation_only_ = false;
  CompareMode compare_mode_ = CompareMode::Weights;
  // Each change the comparison depends on asks for a new one; comparison_ was made for the
  // request `comparison_made_`.
  std::uint64_t comparison_wanted_ = 1;
  std::uint64_t comparison_made_ = 0;
  std::optional<Comparison> comparison_;
  std::uint64_t comparison_version_ = 0;
};

}  // namespace holefill::viewer
