#include "color_options.h"

#include <string>

#include "named_option.h"

namespace matc::cli {

void add_color_options(CLI::App& app, ColorOptions& options) {
  const std::string names = color_space_names();
  app.add_option_function<std::string>(
         "--color-space",
         [&options](const std::string& name) {
           options.working_space = *option_value<ColorSpace>(name);
         },
         "Working space of the outputs, and of RGB values in materials that name none: " + names +
             " (docs/color-spaces.md)")
      ->default_str(std::string(option_name(options.working_space)))
      ->check(CLI::Validator(
          [names](std::string& name) -> std::string {
            if (option_value<ColorSpace>(name)) return {};
            return "'" + name + "' is not one of " + names;
          },
          "SPACE", "colour space"));
  add_named_option(app, "--gamut-mapping", options.gamut_mapping,
                   "What to do with Fresnel curves that leave [0, 1] in the working space: none "
                   "(keep them; a note names each) or desaturate (toward each angle's luminance, "
                   "by the least constant factor that fits)");
}

}  // namespace matc::cli
