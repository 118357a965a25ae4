// Random quad lights around a shading point, with the GGX lobe's exact share of each: what the
// LTC fit's polygon objective minimises over, and what docs/ltc.md scores every table on
// (polygons from another seed, which no fit saw). Half of the quads are centred where the lobe
// reflects (a sample of its visible normals), half anywhere above 17 degrees below the horizon;
// sizes from 0.03 to 1.2 (half-width over distance), aspect 1:2 to 2:1, turned in their plane
// and tilted up to 50 degrees away from facing the point, so that some cross the horizon.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ltc/ggx_lobe.h"
#include "matc/runtime/ltc.h"

namespace matc {

inline constexpr std::uint64_t kTrainingPolygonSeed = 1;
inline constexpr std::uint64_t kHeldOutPolygonSeed = 2;

struct LobePolygon {
  std::array<Vec3, 4> vertices;  // shading frame, relative to the shading point
  double share = 0.0;            // integral over the quad of f cos, over the lobe's albedo
  double share_error = 0.0;      // the estimate's standard error
};

// A seed for one lobe from a base seed and the lobe's (NdotV, roughness): the same quads for a
// texel whichever thread or table fits it.
std::uint64_t lobe_polygon_seed(std::uint64_t base, double ndotv, double roughness);

// `count` quads from `seed`, each with its share estimated from `samples` sample pairs
// (area_light_reference.h).
std::vector<LobePolygon> lobe_polygons(const GgxLobe& lobe, double albedo, std::uint64_t seed,
                                       std::size_t count, std::size_t samples);

struct PolygonSetError {
  double mean = 0.0;  // of |I_ltc(P) - share(P)| over the quads: relative to the albedo
  double max = 0.0;
};
PolygonSetError ltc_polygon_set_error(const runtime::LtcInverse& inverse,
                                      std::span<const LobePolygon> polygons);

// Held-out quads for every texel of a table of `size` on `axis` (kHeldOutPolygonSeed): `count` per
// texel of `samples` pairs each, rows by roughness like the table; and a table's error on them.
using TexelPolygons = std::vector<std::vector<LobePolygon>>;
TexelPolygons held_out_polygons(std::size_t size, std::size_t count, std::size_t samples,
                                runtime::LtcViewAxis axis = runtime::LtcViewAxis::angular,
                                unsigned threads = 0);
std::vector<PolygonSetError> ltc_held_out_errors(const runtime::LtcTableView& table,
                                                 const TexelPolygons& polygons);

}  // namespace matc
