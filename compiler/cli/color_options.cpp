#include "color_options.h"

namespace matc::cli {

void add_color_options(CLI::App& app, ColorCliOptions& options) {
  app.add_option("--color-space", options.space,
                 "Working space of the outputs, and of RGB values in materials that name none: " +
                     color_space_names() + " (docs/color-spaces.md)")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {
            if (find_color_space(name)) return {};
            return "'" + name + "' is not one of " + color_space_names();
          },
          "SPACE", "colour space"));
  app.add_option("--gamut-mapping", options.gamut_mapping,
                 "What to do with Fresnel curves that leave [0, 1] in the working space: none "
                 "(keep them; a note names each) or desaturate (toward each angle's luminance, by "
                 "the least constant factor that fits)")
      ->capture_default_str()
      ->check(CLI::IsMember({std::string(gamut_mapping_name(GamutMapping::none)),
                             std::string(gamut_mapping_name(GamutMapping::desaturate))}));
}

ColorOptions color_options_of(const ColorCliOptions& options) {
  return {*find_color_space(options.space), *find_gamut_mapping(options.gamut_mapping)};
}

}  // namespace matc::cli
