// A material of a measured preset's spectrum, built in code (no file): what the compile tests of
// coats and films put their layer on.
#pragma once

#include <string>
#include <utility>

#include "material/material.h"
#include "optics/presets.h"

namespace matc::test {

inline Material preset_material(const MetalPreset& preset, std::string name) {
  Material material;
  material.name = std::move(name);
  material.model = SpectralInput{std::string(preset.symbol), "", "", "", preset_spectrum(preset)};
  return material;
}

}  // namespace matc::test
