#include "emit_option.h"

#include "matc/api/options.h"
#include "split_list.h"

namespace matc::cli {

CLI::Option* add_emit_option(CLI::App& command, std::vector<std::string>& kinds,
                             const std::string& help) {
  return command
      .add_option_function<std::string>(
          "--emit", [&kinds](const std::string& list) { kinds = split_list(list); }, help)
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            for (const std::string& name : split_list(value)) {
              if (!api::takes_option_name("emit", name))
                return "'" + name + "' is not one of " +
                       CLI::detail::join(api::option_names("emit"), ",");
            }
            return {};
          },
          "LIST", "output kinds"));
}

}  // namespace matc::cli
