#include "emit_option.h"

#include "channel_list.h"

namespace matc::cli {

CLI::Option* add_emit_option(CLI::App& command, std::string& list, const std::string& help) {
  return command.add_option("--emit", list, help)
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            for (const std::string& name : split_list(value)) {
              if (!output_kind_from_name(name))
                return "'" + name + "' is not one of " +
                       CLI::detail::join(output_kind_names(), ",");
            }
            return {};
          },
          "LIST", "output kinds"));
}

std::set<OutputKind> emitted_kinds(const std::string& list) {
  if (list.empty()) return all_output_kinds();
  std::set<OutputKind> kinds;
  for (const std::string& name : split_list(list))
    kinds.insert(*output_kind_from_name(name));
  return kinds;
}

}  // namespace matc::cli
