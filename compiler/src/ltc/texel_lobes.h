// Visiting every texel of an LTC table of `size` with its GGX lobe, rows on several threads
// (fill_rows_in_parallel: the result does not depend on the thread count): what the scores of a
// table (ltc_polygon_errors, held_out_polygons) share.
#pragma once

#include <cstddef>

#include "base/parallel_rows.h"
#include "ltc/ggx_lobe.h"
#include "ltc/ltc_fit.h"

namespace matc {

// visit(index = y * size + x, x, y, lobe, ndotv, roughness) once per texel of a table whose
// columns lie on `axis`.
template <typename Visit>
void for_each_texel_lobe(std::size_t size, runtime::LtcViewAxis axis, unsigned threads,
                         const Visit& visit) {
  fill_rows_in_parallel(size, threads, [&] {
    return [&](std::size_t y) {
      const double roughness = ltc_texel_roughness(y, size);
      for (std::size_t x = 0; x < size; ++x) {
        const double ndotv = ltc_texel_ndotv(x, size, axis);
        visit(y * size + x, x, y, GgxLobe(ndotv, roughness), ndotv, roughness);
      }
    };
  });
}

}  // namespace matc
