#include "color_options.h"

#include <string>

#include "named_option.h"
#include "option_help.h"

namespace matc::cli {

void add_color_options(CLI::App& app, ColorOptions& options) {
  const std::string names = color_space_names();
  app.add_option_function<std::string>(
         "--color-space",
         [&options](const std::string& name) {
           options.working_space = *option_value<ColorSpace>(name);
         },
         kColorSpaceHelp + names + " (docs/color-spaces.md)")
      ->default_str(std::string(option_name(options.working_space)))
      ->check(CLI::Validator(
          [names](std::string& name) -> std::string {
            if (option_value<ColorSpace>(name)) return {};
            return "'" + name + "' is not one of " + names;
          },
          "SPACE", "colour space"));
  add_named_option(app, "--gamut-mapping", options.gamut_mapping, kGamutMappingHelp);
}

}  // namespace matc::cli
