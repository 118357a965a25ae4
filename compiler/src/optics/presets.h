// The measured metals matc ships (compiler/data/ior/, sources in compiler/data/SOURCES.md).
#pragma once

#include <span>
#include <string_view>

#include "optics/spectrum.h"

namespace matc {

struct MetalPreset {
  std::string_view symbol;  // the preset name used in material files, e.g. "Au"
  std::string_view name;    // e.g. "gold"
  std::string_view source;  // short literature reference
  // Empty for trustworthy data; otherwise why results from it should not be relied upon.
  std::string_view caveat;
};

std::span<const MetalPreset> metal_presets();
const MetalPreset* find_metal_preset(std::string_view symbol);

// The preset's measured spectrum, parsed once from the embedded data.
const Spectrum& preset_spectrum(const MetalPreset& preset);

}  // namespace matc
