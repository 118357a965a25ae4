// Options whose value is a name from the registry (matc/options/option_names.h): CLI11 checks the
// text against the registry's names and the option's variable holds the typed value from then
// on, so no command looks a name up again.
#pragma once

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "matc/options/option_names.h"
#include "matc/runtime/basis.h"
#include "option_help.h"

namespace matc::cli {

// Adds `flags` to `app`; `value` holds the default (shown in help) until the option is given.
// `allowed`, when not empty, is the subset of the kind's values the option takes.
template <typename Value>
CLI::Option* add_named_option(CLI::App& app, const std::string& flags, Value& value,
                              const std::string& help, std::span<const Value> allowed = {}) {
  std::vector<std::string> names;
  for (const OptionName<Value>& entry : option_names<Value>()) {
    if (allowed.empty() || std::find(allowed.begin(), allowed.end(), entry.value) != allowed.end())
      names.emplace_back(entry.name);
  }
  return app
      .add_option_function<std::string>(
          flags, [&value](const std::string& name) { value = *option_value<Value>(name); }, help)
      ->default_str(std::string(option_name(value)))
      ->check(CLI::IsMember(names));
}

// Adds --basis to `app`, typed (the commands not yet on the public API's names: bake, basis).
inline CLI::Option* add_basis_option(CLI::App& app, runtime::BasisKind& basis) {
  return add_named_option(app, "--basis", basis, kBasisHelp);
}

}  // namespace matc::cli
