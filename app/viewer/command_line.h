// The viewer's command line: a mesh to open, and the scripted mode (select a hole, run stages,
// compare, save a screenshot, exit) used by the GUI test and to make the docs' screenshots.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "holefill/features.h"
#include "holefill/patch.h"

namespace holefill::viewer {

struct CommandLine {
  std::filesystem::path mesh;  // empty: the bundled bunny
  std::optional<int> select_hole;
  std::vector<int> add_holes;  // loops added to the selection (shift-click), in order
  std::vector<Stage> run;      // stages to run on the selected hole, in order
  bool fill_all = false;
  bool remesh = false;  // remesh toward valence 6 after refinement
  bool fair = false;    // fairing instead of umbrella smoothing
  int fair_order = 2;   // with fair: 2 bi-Laplacian, 3 tri-Laplacian
  bool compare = false;
  bool compare_triangulation_only = false;
  bool compare_smoothing = false;  // umbrella | fair instead of liepa | maxmin
  bool compare_features = false;   // without | with sharp features instead
  double feature_angle = FeatureOptions{}.angle_degrees;  // FillOptions::features
  int width = 1280;
  int height = 800;
  std::filesystem::path save;        // set: after the actions, save the mesh here
  std::filesystem::path screenshot;  // set: render, save this PNG and exit
  int frames = 4;                    // frames scripted mode renders before the screenshot
  bool report_frame_time = false;    // print the mean frame time (set by --frames)
  float ui_scale = 0.0f;             // the panel's scale; 0: the monitor's content scale
  unsigned threads = 0;              // Session::set_threads: the worker's (0: every core)
  std::filesystem::path state_file;  // set: the window's state is written here (state_report.h)
  bool help = false;
  bool version = false;
};

// Parses the arguments after the program's name (with CLI11: --opt=value, --, --help, --version);
// throws std::invalid_argument with a message for the user on bad arguments. --help and
// --version set `help` or `version` and nothing else.
CommandLine parse_command_line(const std::vector<std::string>& arguments);

// The help text, generated from the options (with their defaults).
std::string usage();
// "holefill-viewer VERSION".
std::string version();

// The bundled bunny, found from the executable's path (nothing is compiled in): assets/ in the
// executable's folder or up to three folders above it (the source tree, from build/app/viewer),
// or ../share/holefill/assets beside an installed bin/. The last candidate (which does not exist)
// when none does.
std::filesystem::path default_mesh_path(const std::filesystem::path& executable);

}  // namespace holefill::viewer
