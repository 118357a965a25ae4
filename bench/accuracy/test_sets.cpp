#include "test_sets.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/core.h>

#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/spectrum.h"
#include "random_artistic.h"

namespace matc::bench {
namespace {

std::unique_ptr<ReflectanceCurve> grey(ComplexIor ior) {
  return std::make_unique<IorCurve>(std::array<ComplexIor, 3>{ior, ior, ior});
}

std::array<ArtisticParameters, 3> grey_artistic(ArtisticParameters parameters) {
  return {parameters, parameters, parameters};
}

}  // namespace

void TestSet::add(std::string curve_name, std::unique_ptr<ReflectanceCurve> exact,
                  std::size_t channels, std::optional<std::array<ArtisticParameters, 3>> artistic) {
  TestCurve curve{std::move(curve_name), std::move(exact), nullptr, channels, artistic};
  curve.cached = std::make_unique<AccuracyGridCurve>(*curve.exact);
  curves.push_back(std::move(curve));
}

TestSet measured_metals() {
  TestSet set{"measured metals (23)", {}};
  for (const MetalPreset& preset : metal_presets()) {
    if (!preset.caveat.empty()) continue;
    set.add(std::string(preset.symbol), std::make_unique<SpectralCurve>(preset_spectrum(preset)),
            3);
  }
  return set;
}

TestSet alternative_metals(const std::filesystem::path& directory) {
  TestSet set{"alternative data sets", {}};
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(directory))
    if (entry.path().extension() == ".csv") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const std::string content = text.str();
    Diagnostics diagnostics;
    const auto spectrum = parse_nk_csv(content, TextLocator(file.string(), content), diagnostics);
    if (!spectrum) throw std::runtime_error("cannot read " + file.string());
    set.add(file.parent_path().filename().string() + "/" + file.stem().string(),
            std::make_unique<SpectralCurve>(*spectrum), 3);
  }
  set.name = fmt::format("alternative data sets ({})", set.curves.size());
  return set;
}

TestSet artistic(std::size_t count, double r_max) {
  TestSet set{fmt::format("random artistic, r <= {:.2f} ({})", r_max, count), {}};
  for (const auto& [r, g] : random_artistic_inputs(count, r_max)) {
    set.add(fmt::format("r={:.3f} g={:.3f}", r, g), grey(gulbrandsen_to_ior({r, g})), 1,
            grey_artistic({r, g}));
  }
  return set;
}

TestSet edge_tint_line(double g, double first, double last, double step) {
  const auto count = static_cast<int>(std::lround((last - first) / step)) + 1;
  TestSet set{fmt::format("artistic, g = {:g}, r {:g}-{:g} ({})", g, first, last, count), {}};
  for (int i = 0; i < count; ++i) {
    const double r = first + step * i;
    set.add(fmt::format("r={:.2f} g={:g}", r, g), grey(gulbrandsen_to_ior({r, g})), 1,
            grey_artistic({r, g}));
  }
  return set;
}

TestSet dielectrics() {
  TestSet set{"dielectrics, eta 1.2-2.5 (14)", {}};
  for (int i = 0; i <= 13; ++i) {
    const double eta = 1.2 + 0.1 * i;
    set.add(fmt::format("eta={:.1f}", eta), grey({eta, 0.0}), 1,
            grey_artistic(ior_to_gulbrandsen({eta, 0.0})));
  }
  return set;
}

std::vector<TestSet> study_test_sets(const std::filesystem::path& alternative_directory) {
  std::vector<TestSet> tests;
  tests.push_back(measured_metals());
  tests.push_back(alternative_metals(alternative_directory));
  tests.push_back(artistic(500, 0.8));
  tests.push_back(artistic(500, 1.0));
  tests.push_back(edge_tint_line(1.0, 0.05, 0.95, 0.05));
  // Gulbrandsen's g = 0 is a dielectric whose index grows with r (4.4 at r = 0.4): the red and
  // blue channels of the talk's Figure 2 material.
  tests.push_back(edge_tint_line(0.0, 0.2, 0.6, 0.1));
  tests.push_back(dielectrics());
  return tests;
}

}  // namespace matc::bench
