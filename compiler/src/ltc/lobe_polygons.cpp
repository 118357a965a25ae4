#include "ltc/lobe_polygons.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <random>

#include "ltc/area_light_reference.h"
#include "ltc/ltc_fit.h"
#include "texel_lobes.h"

namespace matc {
namespace {

using runtime::cross;
using runtime::normalize;
using runtime::plus;
using runtime::scaled;

constexpr double kLowestCentre = -0.3;  // z of a quad's centre direction (17 degrees below)
constexpr double kSmallest = 0.03, kLargest = 1.2;  // half-width over distance
constexpr double kMaxAspect = 2.0;
constexpr double kMaxTilt = 50.0 * std::numbers::pi / 180.0;

// SplitMix64's finaliser: spreads nearby inputs over all 64 bits.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::uint64_t lobe_polygon_seed(std::uint64_t base, double ndotv, double roughness) {
  return mix(mix(base ^ std::bit_cast<std::uint64_t>(ndotv)) ^
             std::bit_cast<std::uint64_t>(roughness));
}

std::vector<LobePolygon> lobe_polygons(const GgxLobe& lobe, double albedo, std::uint64_t seed,
                                       std::size_t count, std::size_t samples) {
  // mt19937_64 and this conversion are fully specified: the same quads everywhere.
  std::mt19937_64 random(seed);
  const auto uniform = [&] { return static_cast<double>(random() >> 11) * 0x1p-53; };
  const auto log_uniform = [&](double low, double high) {
    return low * std::exp(std::log(high / low) * uniform());
  };
  const FresnelAtCosine one = [](double) { return runtime::Rgb{1.0, 1.0, 1.0}; };
  std::vector<LobePolygon> polygons;
  polygons.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    Vec3 centre;
    if (i % 2 == 0) {
      const double u1 = uniform(), u2 = uniform();
      centre = lobe.sample(u1, u2);
    } else {
      const double z = kLowestCentre + (1.0 - kLowestCentre) * uniform();
      const double phi = 2.0 * std::numbers::pi * uniform();
      const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
      centre = {ring * std::cos(phi), ring * std::sin(phi), z};
    }
    const Vec3 w = normalize(centre);
    const double half = log_uniform(kSmallest, kLargest);
    const double aspect = std::sqrt(log_uniform(1.0 / kMaxAspect, kMaxAspect));
    const double turn = 2.0 * std::numbers::pi * uniform();
    const double tilt = kMaxTilt * uniform();
    // A frame facing the point (a, b across w), turned in its plane, then b tilted towards w.
    const Vec3 across =
        normalize(std::abs(w[2]) < 0.9 ? cross(w, {0.0, 0.0, 1.0}) : cross(w, {1.0, 0.0, 0.0}));
    const Vec3 other = cross(w, across);
    const Vec3 a = plus(scaled(across, std::cos(turn)), scaled(other, std::sin(turn)));
    const Vec3 b0 = plus(scaled(across, -std::sin(turn)), scaled(other, std::cos(turn)));
    const Vec3 b = plus(scaled(b0, std::cos(tilt)), scaled(w, std::sin(tilt)));
    LobePolygon polygon;
    constexpr std::array<std::array<double, 2>, 4> kCorners = {
        {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    for (std::size_t k = 0; k < 4; ++k) {
      polygon.vertices[k] = plus(w, plus(scaled(a, kCorners[k][0] * half * aspect),
                                         scaled(b, kCorners[k][1] * half / aspect)));
    }
    const AreaLightEstimate estimate =
        integrate_polygon_light(lobe, polygon.vertices, one, samples, mix(seed + i));
    polygon.share = estimate.mean[0] / albedo;
    polygon.share_error = estimate.standard_error[0] / albedo;
    polygons.push_back(polygon);
  }
  return polygons;
}

PolygonSetError ltc_polygon_set_error(const runtime::LtcInverse& inverse,
                                      std::span<const LobePolygon> polygons) {
  PolygonSetError error;
  for (const LobePolygon& polygon : polygons) {
    const double e =
        std::abs(runtime::ltc_polygon_integral(inverse, polygon.vertices) - polygon.share);
    error.mean += e;
    error.max = std::max(error.max, e);
  }
  error.mean /= static_cast<double>(std::max<std::size_t>(polygons.size(), 1));
  return error;
}

TexelPolygons held_out_polygons(std::size_t size, std::size_t count, std::size_t samples,
                                runtime::LtcViewAxis axis, unsigned threads) {
  TexelPolygons polygons(size * size);
  for_each_texel_lobe(size, axis, threads,
                      [&](std::size_t index, std::size_t, std::size_t, const GgxLobe& lobe,
                          double ndotv, double roughness) {
                        polygons[index] =
                            lobe_polygons(lobe, lobe.albedo(kLtcFitSamplesPerAxis),
                                          lobe_polygon_seed(kHeldOutPolygonSeed, ndotv, roughness),
                                          count, samples);
                      });
  return polygons;
}

std::vector<PolygonSetError> ltc_held_out_errors(const runtime::LtcTableView& table,
                                                 const TexelPolygons& polygons) {
  std::vector<PolygonSetError> errors(table.size * table.size);
  for (std::size_t y = 0; y < table.size; ++y) {
    for (std::size_t x = 0; x < table.size; ++x) {
      const auto t = table.texel(x, y);
      errors[y * table.size + x] =
          ltc_polygon_set_error({t[0], t[1], t[2], t[3]}, polygons[y * table.size + x]);
    }
  }
  return errors;
}

}  // namespace matc
