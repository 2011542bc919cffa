#include "fill_options.h"

#include <vector>

#include "commands.h"

namespace py = pybind11;

namespace holefill::python {
namespace {

// How a Python value becomes command-line words.
enum class Kind {
  Value,    // --flag VALUE (numbers as the shortest text that reads back the same)
  OnOff,    // --flag on|off from a bool (or the word)
  Flag,     // --flag when true
  NotFlag,  // --flag when false (stitch=False: --no-stitch)
  Pairs,    // --flag A,B for each pair
};

struct OptionName {
  const char* python;
  const char* flag;
  Kind kind;
  const char* type;  // as the docstring shows it
};

const std::vector<OptionName> kOptionNames{
    {"weight", "--weight", Kind::Value, "str"},
    {"fold_limit", "--fold-limit", Kind::Value, "float"},
    {"restricted_above", "--restricted-above", Kind::Value, "int"},
    {"tau", "--tau", Kind::Value, "float"},
    {"remesh", "--remesh", Kind::OnOff, "bool"},
    {"smooth", "--smooth", Kind::Value, "str"},
    {"fair_order", "--fair-order", Kind::Value, "int"},
    {"fair_weights", "--fair-weights", Kind::Value, "str"},
    {"smooth_iterations", "--smooth-iterations", Kind::Value, "int"},
    {"smooth_step", "--smooth-step", Kind::Value, "float"},
    {"holes", "--holes", Kind::Value, "list[int] | None"},
    {"max_boundary", "--max-boundary", Kind::Value, "int"},
    {"islands", "--islands", Kind::OnOff, "bool"},
    {"feature_angle", "--feature-angle", Kind::Value, "float"},
    {"bridge", "--bridge", Kind::Pairs, "list[tuple[int, int]]"},
    {"stage", "--stage", Kind::Value, "str"},
    {"stitch", "--no-stitch", Kind::NotFlag, "bool"},
    {"stitch_tolerance", "--stitch-tolerance", Kind::Value, "float | None"},
    {"remove_small_components", "--remove-small-components", Kind::Value, "int"},
    {"keep_borders", "--keep-borders", Kind::Flag, "bool"},
    {"allow_intersections", "--allow-intersections", Kind::Flag, "bool"},
    {"threads", "--threads", Kind::Value, "int"},
};

const OptionName* find_python(const std::string& name) {
  for (const auto& option : kOptionNames) {
    if (name == option.python) return &option;
  }
  return nullptr;
}

std::string word(py::handle value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  return py::repr(value).cast<std::string>();  // floats: the shortest exact text
}

std::string on_off(py::handle value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "on" : "off";
  return word(value);
}

std::string id_list(py::handle ids) {
  if (!py::isinstance<py::iterable>(ids) || py::isinstance<py::str>(ids)) return word(ids);
  std::string text;
  for (const auto id : ids) text += (text.empty() ? "" : ",") + word(id);
  return text;
}

bool truthy(py::handle value) {
  const int truth = PyObject_IsTrue(value.ptr());
  if (truth < 0) throw py::error_already_set();
  return truth == 1;
}

void add_words(const OptionName& option, py::handle value, std::vector<std::string>& args) {
  switch (option.kind) {
    case Kind::Value:
      args.insert(args.end(), {option.flag, std::string(option.python) == "holes" ? id_list(value)
                                                                                  : word(value)});
      return;
    case Kind::OnOff:
      args.insert(args.end(), {option.flag, on_off(value)});
      return;
    case Kind::Flag:
      if (truthy(value)) args.emplace_back(option.flag);
      return;
    case Kind::NotFlag:
      if (!truthy(value)) args.emplace_back(option.flag);
      return;
    case Kind::Pairs:
      for (const auto pair : value) args.insert(args.end(), {option.flag, id_list(pair)});
      return;
  }
}

}  // namespace

std::string python_message(std::string message) {
  for (const auto& option : kOptionNames) {
    const std::string flag = option.flag;
    const std::string name =
        option.kind == Kind::NotFlag ? std::string(option.python) + "=False" : option.python;
    for (auto at = message.find(flag); at != std::string::npos; at = message.find(flag, at)) {
      const std::size_t end = at + flag.size();
      const bool whole =
          end == message.size() || !(std::isalnum(message[end]) || message[end] == '-');
      if (whole) message.replace(at, flag.size(), name);
      at += whole ? name.size() : flag.size();
    }
  }
  return message;
}

cli::FillArguments fill_arguments(const py::dict& options, py::handle holes) {
  std::vector<std::string> args;
  if (!holes.is_none()) add_words(*find_python("holes"), holes, args);
  for (const auto& [key, value] : options) {
    const std::string name = py::str(key).cast<std::string>();
    const OptionName* option = find_python(name);
    if (!option || name == "holes") {
      throw cli::UsageError("fill has no option '" + name + "' (holefill.FILL_OPTIONS lists them)");
    }
    if (!value.is_none()) add_words(*option, value, args);
  }
  try {
    return cli::parse_fill_choices(args);
  } catch (const cli::UsageError& e) {
    throw cli::UsageError(python_message(e.what()));
  }
}

py::dict option_defaults() {
  const cli::FillArguments a = cli::parse_fill_choices({});
  const FillOptions& o = a.options;
  py::dict defaults;
  defaults["weight"] = a.weight;
  defaults["fold_limit"] = a.fold_limit_degrees;
  defaults["restricted_above"] = o.triangulate.restricted.above_edges;
  defaults["tau"] = o.refine.tau;
  defaults["remesh"] = o.refine.remesh;
  defaults["smooth"] = a.smooth;
  defaults["fair_order"] = o.smooth.fair.order;
  defaults["fair_weights"] = a.fair_weights;
  defaults["smooth_iterations"] = o.smooth.iterations;
  defaults["smooth_step"] = o.smooth.step;
  defaults["max_boundary"] = a.selection.max_boundary_edges;
  defaults["islands"] = o.islands.detect;
  defaults["feature_angle"] = o.features.angle_degrees;
  defaults["bridge"] = py::list();
  defaults["stage"] = a.stage;
  defaults["stitch"] = a.preparation.stitch;
  defaults["stitch_tolerance"] = py::none();
  defaults["remove_small_components"] = a.preparation.remove_pieces_up_to;
  defaults["keep_borders"] = a.preparation.keep_borders;
  defaults["allow_intersections"] = o.allow_intersections;
  defaults["threads"] = o.threads;
  return defaults;
}

std::string options_doc() {
  std::string doc = "Options (keywords; the holefill command's, under these names):\n";
  for (const auto& help : cli::fill_choice_help()) {
    const OptionName* option = nullptr;
    for (const auto& candidate : kOptionNames) {
      if (help.flag == candidate.flag) option = &candidate;
    }
    if (!option) continue;
    std::string description = help.description;
    const std::string indent = "\n        ";
    for (std::size_t at = description.find('\n'); at != std::string::npos;
         at = description.find('\n', at + indent.size())) {
      description.replace(at, 1, indent);
    }
    const py::dict defaults = option_defaults();
    std::string default_text = help.default_text;
    if (defaults.contains(option->python) && !defaults[option->python].is_none()) {
      default_text = py::repr(defaults[option->python]).cast<std::string>();
    }
    doc += "    " + std::string(option->python) + " (" + option->type;
    if (!default_text.empty()) doc += ", default " + default_text;
    doc += "): " + std::string(option->kind == Kind::NotFlag ? "False: " : "") +
           python_message(description) + "\n";
  }
  return doc;
}

}  // namespace holefill::python
