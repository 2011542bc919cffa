#include "fill_arguments.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "commands.h"
#include "number_checks.h"

namespace holefill::cli {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
constexpr std::int64_t kNoLimit = std::numeric_limits<std::int64_t>::max();

const std::vector<std::pair<std::string, Stage>> kStages{
    {"triangulate", Stage::Triangulated}, {"refine", Stage::Refined}, {"smooth", Stage::Smoothed}};
const std::vector<std::pair<std::string, SmoothMethod>> kSmoothMethods{
    {"umbrella", SmoothMethod::Umbrella}, {"fair", SmoothMethod::Fair}};

template <typename Value>
std::vector<std::string> names(const std::vector<std::pair<std::string, Value>>& table) {
  std::vector<std::string> result;
  for (const auto& entry : table) result.push_back(entry.first);
  return result;
}

template <typename Value>
std::string name_of(const std::vector<std::pair<std::string, Value>>& table, Value value) {
  for (const auto& entry : table) {
    if (entry.second == value) return entry.first;
  }
  return {};
}

template <typename Value>
Value value_of(const std::vector<std::pair<std::string, Value>>& table, const std::string& name) {
  for (const auto& entry : table) {
    if (entry.first == name) return entry.second;
  }
  return table.front().second;  // unreachable: CLI11 checked the name against the table
}

// The texts of the options that name a choice, set to the library's defaults.
void set_defaults(FillArguments& a) {
  a.weight = to_string(a.options.triangulate.weight);
  a.stage = name_of(kStages, a.options.last_stage);
  a.smooth = name_of(kSmoothMethods, a.options.smooth.method);
  a.fair_weights = a.options.smooth.fair.cotangent_weights ? "cotangent" : "uniform";
  a.remesh = a.options.refine.remesh ? "on" : "off";
  a.islands = a.options.islands.detect ? "on" : "off";
  a.fold_limit_degrees = a.options.triangulate.fold_limit * kDegreesPerRadian;
}

void add_triangulation_options(CLI::App& command, FillArguments& a) {
  command.add_option("--weight", a.weight, "triangulation weight (maxmin: the paper's)")
      ->check(CLI::IsMember({"maxmin", "liepa", "area"}));
  command
      .add_option("--fold-limit", a.fold_limit_degrees,
                  "maxmin: dihedral angles above this (degrees) are minimised\n"
                  "first (180: the paper's order)")
      ->check(real_number(0.0, 180.0, true));
  command
      .add_option("--restricted-above", a.options.triangulate.restricted.above_edges,
                  "larger holes (boundary edges) use the restricted search;\n"
                  "0: always the full search, which takes at most " +
                      std::to_string(kMaxFullSearchEdges) + " edges")
      ->transform(whole_number(0, kNoLimit));
  add_feature_angle_option(command, a.options.features);
}

void add_refinement_and_smoothing_options(CLI::App& command, FillArguments& a) {
  command.add_option("--tau", a.options.refine.tau, "refinement density factor")
      ->check(real_number(0.0, std::numeric_limits<double>::max(), true));
  command
      .add_option("--remesh", a.remesh,
                  "flip and relax the refined patch toward valence 6\n(not in the paper)")
      ->check(CLI::IsMember({"on", "off"}));
  command
      .add_option("--smooth", a.smooth,
                  "umbrella (the paper's) or fairing, which continues the\n"
                  "surrounding curvature")
      ->check(CLI::IsMember(names(kSmoothMethods)));
  command
      .add_option("--fair-order", a.options.smooth.fair.order,
                  "fairing: 2 bi-Laplacian, 3 tri-Laplacian")
      ->transform(whole_number(2, 3));
  command.add_option("--fair-weights", a.fair_weights, "fairing: Laplacian weights")
      ->check(CLI::IsMember({"cotangent", "uniform"}));
  command
      .add_option("--smooth-iterations", a.options.smooth.iterations,
                  "umbrella smoothing iterations")
      ->transform(whole_number(0, 1'000'000));
  command.add_option("--smooth-step", a.options.smooth.step, "umbrella step lambda")
      ->check(real_number(0.0, 1.0, true));
}

void add_selection_options(CLI::App& command, FillArguments& a) {
  command
      .add_option("--holes", a.hole_ids,
                  "fill only these hole ids, e.g. 0,3 (as `holefill info`\n"
                  "lists them; default all)")
      ->delimiter(',')
      ->default_str("")
      ->transform(whole_number(0, kNoLimit));
  command
      .add_option("--max-boundary", a.selection.max_boundary_edges,
                  "fill only holes with at most this many boundary edges\n(0: no limit)")
      ->transform(whole_number(0, kNoLimit));
  add_islands_option(command, a.islands);
  command
      .add_option("--bridge", a.bridges,
                  "join holes A and B with one band instead of two caps,\n"
                  "e.g. --bridge 0,3 (may be repeated)")
      ->type_name("A,B")
      ->allow_extra_args(false)
      ->default_str("");
  command.add_option("--stage", a.stage, "stop after this stage")
      ->check(CLI::IsMember(names(kStages)));
  add_threads_option(command, a.options.threads, "read, prepare and fill the mesh");
  command.add_flag("--allow-intersections", a.options.allow_intersections,
                   "keep a hole's best patch even when it intersects the mesh\n"
                   "(exit 5); by default such a hole is left open (exit 1)");
}

}  // namespace

void add_feature_angle_option(CLI::App& command, FeatureOptions& features) {
  command
      .add_option("--feature-angle", features.angle_degrees,
                  "continue sharp edges (faces meeting at more than this many\n"
                  "degrees) through holes: creases and corners; 0: off")
      ->check(real_number(0.0, 180.0));
}

void add_threads_option(CLI::App& command, unsigned& threads, const std::string& work) {
  command
      .add_option("--threads", threads,
                  "threads that " + work +
                      " (0: every core\n"
                      "this process may run on); the output is the same whatever\n"
                      "the number")
      ->transform(whole_number(0, 4096));
}

void add_format_option(CLI::App& command, std::string& format) {
  command.add_option("--format", format, "the format of - (standard input or output)")
      ->check(CLI::IsMember({"obj", "off", "ply", "stl"}));
}

void add_fill_options(CLI::App& command, FillArguments& a) {
  command.option_defaults()->always_capture_default();
  command
      .add_option("MESH", a.inputs,
                  "the mesh to fill (.obj .off .ply .stl; -: stdin); several, or\n"
                  "folders of them: each filled into the folder -o names")
      ->required();
  command
      .add_option("-o,--output", a.output,
                  "where to write the result (.obj .off .ply .stl; -: stdout),\n"
                  "or a folder (ending in /) for several meshes")
      ->required();
  command
      .add_option("-j,--jobs", a.jobs,
                  "several meshes: how many to fill at once (0: one per core),\n"
                  "each on --threads threads (0: the cores shared among them,\n"
                  "at least one each)")
      ->transform(whole_number(0, 1024));
  add_format_option(command, a.format);
  command.add_option("--report", a.report_path,
                     "write per-hole statistics as JSON to this file (-: stdout)");
  add_fill_choices(command, a);
}

void add_fill_choices(CLI::App& command, FillArguments& a) {
  set_defaults(a);
  command.option_defaults()->always_capture_default();
  add_triangulation_options(command, a);
  add_refinement_and_smoothing_options(command, a);
  add_selection_options(command, a);
  add_preparation_options(command, a.preparation);
}

FillArguments parse_fill_choices(const std::vector<std::string>& args) {
  CLI::App command;
  FillArguments a;
  add_fill_choices(command, a);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    command.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  finish_fill_options(a);
  return a;
}

std::vector<OptionHelp> fill_choice_help() {
  CLI::App command;
  FillArguments a;
  add_fill_choices(command, a);
  std::vector<OptionHelp> help;
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_lnames().empty() || option == command.get_help_ptr()) continue;
    help.push_back({"--" + option->get_lnames().front(), option->get_description(),
                    option->get_default_str()});
  }
  return help;
}

void finish_fill_options(FillArguments& a) {
  if (a.inputs.size() == 1) a.input = a.inputs.front();
  parse_weight(a.weight, a.options.triangulate.weight);
  a.options.triangulate.fold_limit = a.fold_limit_degrees / kDegreesPerRadian;
  a.options.refine.remesh = a.remesh == "on";
  a.options.islands.detect = a.islands == "on";
  a.preparation.islands = a.options.islands;
  a.preparation.threads = a.options.threads;
  a.options.smooth.method = value_of(kSmoothMethods, a.smooth);
  a.options.smooth.fair.cotangent_weights = a.fair_weights == "cotangent";
  a.options.last_stage = value_of(kStages, a.stage);
}

}  // namespace holefill::cli
