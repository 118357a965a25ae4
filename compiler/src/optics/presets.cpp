#include "optics/presets.h"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <string>

#include "base/embedded_data.h"

namespace matc {
namespace {

constexpr std::string_view kJohnsonChristy72 = "Johnson & Christy 1972";
constexpr std::string_view kJohnsonChristy74 = "Johnson & Christy 1974";
constexpr std::string_view kPalik = "Palik, Handbook of Optical Constants of Solids (via luxpop)";

constexpr std::array<MetalPreset, 24> kPresets = {{
    {"Ag", "silver", kJohnsonChristy72, ""},
    {"Al", "aluminium", "Rakic 1995", ""},
    {"Au", "gold", kJohnsonChristy72, ""},
    {"Be", "beryllium", kPalik, ""},
    {"Co", "cobalt", kJohnsonChristy74, ""},
    {"Cr", "chromium", kJohnsonChristy74, ""},
    {"Cu", "copper", kJohnsonChristy72, ""},
    {"CuZn", "brass (Cu70 Zn30)", "Querry 1985", ""},
    {"Fe", "iron", kJohnsonChristy74, ""},
    {"Hg", "mercury (liquid)", "Inagaki et al. 1981", ""},
    {"Ir", "iridium", kPalik, ""},
    {"K", "potassium", "Smith 1969", ""},
    {"Li", "lithium", "Inagaki et al. 1976", ""},
    {"Mo", "molybdenum", kPalik, ""},
    {"Na", "sodium", "Inagaki et al. 1976", ""},
    {"Ni", "nickel", kJohnsonChristy74, ""},
    {"Pd", "palladium", kJohnsonChristy74, ""},
    {"Pt", "platinum", "Tselin et al. 2024", ""},
    {"Rh", "rhodium", "Weaver et al. 1977", ""},
    {"Ta", "tantalum", kPalik, ""},
    {"Ti", "titanium", kJohnsonChristy74, ""},
    {"V", "vanadium", kJohnsonChristy74, ""},
    {"W", "tungsten", kPalik, ""},
    {"Zn", "zinc", "Querry 1987",
     "the only visible-range zinc data found (Querry 1987) has n = 9-14, which behaves like a "
     "dielectric, not a metal; its colour and angular curve do not match real zinc"},
}};

}  // namespace

std::span<const MetalPreset> metal_presets() {
  return kPresets;
}

const MetalPreset* find_metal_preset(std::string_view symbol) {
  const auto found = std::find_if(kPresets.begin(), kPresets.end(),
                                  [&](const MetalPreset& p) { return p.symbol == symbol; });
  return found == kPresets.end() ? nullptr : &*found;
}

const Spectrum& preset_spectrum(const MetalPreset& preset) {
  static const std::map<std::string_view, Spectrum> spectra = [] {
    std::map<std::string_view, Spectrum> parsed;
    for (const MetalPreset& p : kPresets) {
      const std::string path = "ior/" + std::string(p.symbol) + ".csv";
      const std::string_view text = embedded_data::file(path);
      Diagnostics diagnostics;
      auto spectrum = parse_nk_csv(text, TextLocator(path, text), diagnostics);
      if (!spectrum) throw std::logic_error("embedded preset data is malformed: " + path);
      parsed.emplace(p.symbol, std::move(*spectrum));
    }
    return parsed;
  }();
  return spectra.at(preset.symbol);
}

}  // namespace matc
