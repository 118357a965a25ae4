#include "emit_option.h"

#include "channel_list.h"
#include "named_option.h"

namespace matc::cli {

CLI::Option* add_emit_option(CLI::App& command, std::set<OutputKind>& kinds,
                             const std::string& help) {
  return command
      .add_option_function<std::string>(
          "--emit",
          [&kinds](const std::string& list) {
            kinds.clear();
            for (const std::string& name : split_list(list))
              kinds.insert(*option_value<OutputKind>(name));
            if (kinds.empty()) kinds = all_output_kinds();
          },
          help)
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            for (const std::string& name : split_list(value)) {
              if (!option_value<OutputKind>(name))
                return "'" + name + "' is not one of " +
                       CLI::detail::join(option_name_list<OutputKind>(), ",");
            }
            return {};
          },
          "LIST", "output kinds"));
}

}  // namespace matc::cli
