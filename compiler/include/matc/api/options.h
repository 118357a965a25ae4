// The names the public API's options take (and the CLI's: the same registry), for a face that
// lists or checks them before calling (docs/api.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "matc/api/material.h"

namespace matc::api {

// The names of "basis", "build_basis" (a build's or a compile's: "auto", a basis per material,
// then the bases), "color_space", "gamut_mapping", "emit", "lut_format", "lut_precision"
// (also coefficient_table_precision's), "ltc_objective" (api/regeneration.h), in the order help
// and errors list them. Another option
// throws std::invalid_argument naming the options there are.
std::vector<std::string> option_names(std::string_view option);
// The name of the option's default ("powers", "lin_rec709", "none", "ktx2", "f32", "polygons";
// "emit": empty, every output).
std::string option_default(std::string_view option);
// Whether the option takes `name` (a colour space also takes its aliases, such as lin_srgb).
bool takes_option_name(std::string_view option, std::string_view name);

// Per-channel values as the CLI's options take them ("0.9,0.6,0.3" or one grey "0.5"), each in
// [0, max]. Throws std::invalid_argument: "LABEL: problem; give one value (grey) or three
// (R,G,B), each in [0, MAX], comma-separated".
Rgb parse_channel_values(std::string_view label, std::string_view text, double max = 1.0);

}  // namespace matc::api
