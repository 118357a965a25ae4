#include "name_options.h"

#include "option_help.h"

namespace matc::cli {

CLI::Option* add_name_option(CLI::App& app, const std::string& flags, std::string& value,
                             std::string_view option, const std::string& help,
                             std::string_view default_name) {
  value = default_name.empty() ? api::option_default(option) : std::string(default_name);
  return app.add_option(flags, value, help)
      ->default_str(value)
      ->check(CLI::IsMember(api::option_names(option)));
}

void add_color_name_options(CLI::App& app, api::CompileOptions& options) {
  std::string names;
  for (const std::string& name : api::option_names("color_space"))
    names += (names.empty() ? "" : ", ") + name;
  options.color_space = api::option_default("color_space");
  app.add_option("--color-space", options.color_space,
                 kColorSpaceHelp + names + " (docs/color-spaces.md)")
      ->default_str(options.color_space)
      ->check(CLI::Validator(
          [names](std::string& name) -> std::string {
            if (api::takes_option_name("color_space", name)) return {};
            return "'" + name + "' is not one of " + names;
          },
          "SPACE", "colour space"));
  add_name_option(app, "--gamut-mapping", options.gamut_mapping, "gamut_mapping",
                  kGamutMappingHelp);
}

}  // namespace matc::cli
