// The similarity policy options that the similarity, matrix and evaluate sub-commands share: the
// command-line face of the front end's Policy_choice, from the front end's table.
#pragma once

#include "parameters.h"

#include <frontend/similarity.h>

#include <CLI/CLI.hpp>

namespace deformseg::tool {

using Policy_options = frontend::Policy_choice;

/// Adds --policy, --alignment, --threshold, --up, --bands and --sides.
inline void add_policy_options(CLI::App& command, Policy_options& o) {
  add_parameters(command, frontend::policy_parameters, o);
}

}  // namespace deformseg::tool
