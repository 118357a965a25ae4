// libFuzzer target for area lights: matc eval's --quad-light parser (and the polygon checks behind
// it) on arbitrary text, then what the tools do with a light it accepts: the clipped form factor
// and the LTC integral stay finite and within [0, 1], the disk and sphere polygons and the
// Monte-Carlo reference stay finite. Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ltc/area_light_reference.h"
#include "ltc/polygon_light.h"
#include "matc/runtime/ltc.h"

namespace {

void check_unit(double value) {
  if (!(value >= 0.0 && value <= 1.0)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const matc::PolygonLightParse parsed = matc::parse_polygon_light(text, 4);
  if (parsed.error.empty() == parsed.vertices.empty()) __builtin_trap();
  if (!parsed.error.empty()) return 0;
  check_unit(matc::runtime::clipped_polygon_form_factor(parsed.vertices));
  const auto table = matc::runtime::shipped_ltc_table();
  for (const double ndotv : {0.0, 0.37, 1.0}) {
    for (const double roughness : {0.0, 0.5, 1.0}) {
      check_unit(matc::runtime::ltc_polygon_integral(
          matc::runtime::sample_ltc(table, ndotv, roughness), parsed.vertices));
    }
  }
  const matc::GgxLobe lobe(0.5, 0.4);
  const auto estimate = matc::integrate_polygon_light(
      lobe, parsed.vertices,
      [](double) {
        return matc::runtime::Rgb{1.0, 1.0, 1.0};
      },
      16);
  if (!std::isfinite(estimate.mean[0]) || estimate.mean[0] < 0.0) __builtin_trap();
  // The first vertex as a disk's centre and the second as its normal.
  const auto& v = parsed.vertices;
  if (std::hypot(v[1][0], v[1][1], v[1][2]) > 0.0) {
    const auto disk = matc::runtime::disk_light_polygon(v[0], v[1], std::abs(v[2][0]));
    check_unit(matc::runtime::clipped_polygon_form_factor(disk));
  }
  // ... and as a sphere's centre, with a radius inside its distance.
  const double distance = std::hypot(v[0][0], v[0][1], v[0][2]);
  if (distance > 0.0) {
    const double radius = distance * std::min(std::abs(v[2][1]), 0.99);
    check_unit(matc::runtime::clipped_polygon_form_factor(
        matc::runtime::sphere_light_polygon({0.0, 0.0, 0.0}, v[0], radius)));
  }
  return 0;
}
