// fill's keyword options in Python: the command line's options under Python names (--tau is
// tau, --no-stitch is stitch=False, --remesh on|off is remesh=True|False), parsed by the command
// line's own parser, so that their defaults, ranges and messages are the CLI's.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "fill_arguments.h"

namespace holefill::python {

// The arguments `options` (name -> value; None leaves an option at its default) give, with
// `holes` (None, an id or a list of ids) as --holes. Throws holefill::cli::UsageError, with the
// option's Python name in the message, for an unknown name or a value out of range.
cli::FillArguments fill_arguments(const pybind11::dict& options, pybind11::handle holes);

// The command line's message with its option names (--tau) as Python spells them (tau).
std::string python_message(std::string message);

// name -> default value of every option (holefill.FILL_OPTIONS).
pybind11::dict option_defaults();

// A docstring paragraph listing every option: name, default and the command line's help.
std::string options_doc();

}  // namespace holefill::python
