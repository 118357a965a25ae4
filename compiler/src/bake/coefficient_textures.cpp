#include "bake/coefficient_textures.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <utility>

#include "base/parallel_rows.h"
#include "compile/compile.h"  // kPoorFitMaxError
#include "fit/conductor_solver.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/shader_basis.h"
#include "optics/gulbrandsen.h"

namespace matc {
namespace {

constexpr std::size_t kCodes = 256;  // distinct values per channel of an 8-bit map
// Cosines at which the table path measures its error map (the exact path has the solve's 401).
constexpr std::size_t kErrorMapCosines = 65;

struct PairSolution {
  float c2 = 0.0f, c3 = 0.0f, error = 0.0f;
};

// Per-row counts of poorly fitted texels and each row's worst, filled by the row workers and
// summed afterwards (the result does not depend on the thread count).
class ErrorTally {
 public:
  explicit ErrorTally(std::size_t rows) : poor_(rows, 0), worst_(rows, {-1.0f, 0}) {}
  void add(std::size_t row, std::size_t texel, float error) {
    if (error > kPoorFitMaxError) ++poor_[row];
    if (error > worst_[row].first) worst_[row] = {error, texel};
  }
  void finish(BakedCoefficients& baked) const {
    std::pair<float, std::size_t> worst{-1.0f, 0};
    for (std::size_t row = 0; row < poor_.size(); ++row) {
      baked.poor_fit_texels += poor_[row];
      if (worst_[row].first > worst.first) worst = worst_[row];
    }
    baked.max_error = std::max(0.0f, worst.first);
    baked.worst_texel = worst.second;
  }

 private:
  std::vector<std::size_t> poor_;
  std::vector<std::pair<float, std::size_t>> worst_;
};

// The index of a texel channel's value among an 8-bit map's codes, or a constant's channels.
std::size_t value_code(const MapSamples& map, std::size_t texel, std::size_t channel) {
  return map.image ? map.image->codes[3 * texel + channel] : channel;
}
float code_value(const MapSamples& map, std::size_t code) {
  return map.image ? map.image->code_values[code] : static_cast<float>(map.constant[code]);
}

void allocate_level(CoefficientLevel& level, std::size_t width, std::size_t height, bool f0) {
  level.width = width;
  level.height = height;
  for (std::vector<float>* plane : {&level.c2, &level.c3})
    plane->assign(width * height * kCoefficientTextureChannels, 1.0f);
  if (f0) level.f0.assign(width * height * kCoefficientTextureChannels, 1.0f);
}

void store(CoefficientLevel& level, std::size_t texel, std::size_t channel, double f0, double c2,
           double c3) {
  const std::size_t offset = texel * kCoefficientTextureChannels + channel;
  if (!level.f0.empty()) level.f0[offset] = static_cast<float>(f0);
  level.c2[offset] = static_cast<float>(c2);
  level.c3[offset] = static_cast<float>(c3);
}

// Level 0 of 8-bit maps and constants: every distinct (r, g) pair present is solved once with
// the basis' own solve, then looked up per texel.
void solve_exact(const BakeInputs& inputs, const BakeOptions& options, BakedCoefficients& baked) {
  const std::size_t texels = inputs.width * inputs.height;
  std::vector<std::atomic<bool>> present(kCodes * kCodes);
  fill_rows_in_parallel(inputs.height, options.threads, [&] {
    return [&](std::size_t y) {
      for (std::size_t t = y * inputs.width; t < (y + 1) * inputs.width; ++t)
        for (std::size_t c = 0; c < 3; ++c)
          present[value_code(inputs.first, t, c) * kCodes + value_code(inputs.second, t, c)].store(
              true, std::memory_order_relaxed);
    };
  });
  std::vector<std::size_t> pairs;
  for (std::size_t pair = 0; pair < present.size(); ++pair)
    if (present[pair].load(std::memory_order_relaxed)) pairs.push_back(pair);

  const ConductorSolver solver(options.basis);
  std::vector<PairSolution> solutions(kCodes * kCodes);
  fill_rows_in_parallel(pairs.size(), options.threads, [&] {
    return [&](std::size_t i) {
      const std::size_t pair = pairs[i];
      const ChannelSolution solution = solver.solve(code_value(inputs.first, pair / kCodes),
                                                    code_value(inputs.second, pair % kCodes));
      solutions[pair] = {static_cast<float>(solution.coefficients[2]),
                         static_cast<float>(solution.coefficients[3]),
                         static_cast<float>(solution.max_error)};
    };
  });
  baked.solved_pairs = pairs.size();

  CoefficientLevel& level = baked.levels.front();
  if (options.error_map) baked.error.assign(texels, 0.0f);
  ErrorTally tally(inputs.height);
  fill_rows_in_parallel(inputs.height, options.threads, [&] {
    return [&](std::size_t y) {
      for (std::size_t t = y * inputs.width; t < (y + 1) * inputs.width; ++t) {
        float error = 0.0f;
        for (std::size_t c = 0; c < 3; ++c) {
          const std::size_t r_code = value_code(inputs.first, t, c);
          const PairSolution& solution =
              solutions[r_code * kCodes + value_code(inputs.second, t, c)];
          store(level, t, c, code_value(inputs.first, r_code), solution.c2, solution.c3);
          error = std::max(error, solution.error);
        }
        if (options.error_map) baked.error[t] = error;
        tally.add(y, t, error);
      }
    };
  });
  tally.finish(baked);
}

// The shader basis at the error map's cosines mu_j = j / (kErrorMapCosines - 1), evaluated once
// per bake rather than once per texel and channel.
using ErrorMapBasis = std::array<runtime::ChannelCoefficients, kErrorMapCosines>;
ErrorMapBasis error_map_basis(runtime::BasisKind kind) {
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(kind);
  ErrorMapBasis basis{};
  for (std::size_t j = 0; j < kErrorMapCosines; ++j)
    basis[j] = runtime::evaluate_shader_basis(
        shader_basis, static_cast<double>(j) / static_cast<double>(kErrorMapCosines - 1));
  return basis;
}

// The largest |F - exact| of one channel's coefficients over kErrorMapCosines cosines, against
// the curve of the metal the maps describe: the texel's n + ik for n and k maps (so the error of
// clamping an IOR outside the artistic range to the nearest edge tint shows), Gulbrandsen's
// conductor of (r, g) otherwise.
double channel_error(const ErrorMapBasis& basis, const runtime::ChannelCoefficients& c,
                     const ComplexIor& ior) {
  double largest = 0.0;
  for (std::size_t j = 0; j < kErrorMapCosines; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(kErrorMapCosines - 1);
    const auto& b = basis[j];
    const double f = c[0] * b[0] + c[1] * b[1] + c[2] * b[2] + c[3] * b[3];
    largest = std::max(largest, std::abs(f - fresnel_conductor(mu, ior)));
  }
  return largest;
}

// Level 0 of 16-bit and float maps, and of n and k maps: the coefficient table per texel.
void solve_with_table(const BakeInputs& inputs, const BakeOptions& options,
                      BakedCoefficients& baked) {
  const runtime::CoefficientTableView table = runtime::shipped_coefficient_table(options.basis);
  const ErrorMapBasis basis = error_map_basis(options.basis);
  const std::size_t texels = inputs.width * inputs.height;
  if (options.error_map) baked.error.assign(texels, 0.0f);
  CoefficientLevel& level = baked.levels.front();
  ErrorTally tally(inputs.height);
  fill_rows_in_parallel(inputs.height, options.threads, [&] {
    return [&](std::size_t y) {
      for (std::size_t t = y * inputs.width; t < (y + 1) * inputs.width; ++t) {
        runtime::Rgb r{}, g{};
        for (std::size_t c = 0; c < 3; ++c) {
          r[c] = inputs.first.value(t, c);
          g[c] = inputs.second.value(t, c);
        }
        const runtime::Rgb first = r, second = g;
        if (inputs.model == BakeModel::ior) {
          const runtime::ArtisticRgb artistic = runtime::artistic_from_ior(r, g);
          r = artistic.reflectivity;
          g = artistic.edge_tint;
        }
        float error = 0.0f;
        for (std::size_t c = 0; c < 3; ++c) {
          const runtime::ChannelCoefficients coefficients =
              runtime::channel_coefficients_from_table(table, r[c], g[c]);
          store(level, t, c, coefficients[0], coefficients[2], coefficients[3]);
          if (options.error_map && r[c] < 1.0) {
            const ComplexIor ior = inputs.model == BakeModel::ior
                                       ? ComplexIor{first[c], second[c]}
                                       : gulbrandsen_to_ior({r[c], g[c]});
            error = std::max(error, static_cast<float>(channel_error(basis, coefficients, ior)));
          }
        }
        if (options.error_map) {
          baked.error[t] = error;
          tally.add(y, t, error);
        }
      }
    };
  });
  if (options.error_map) tally.finish(baked);
}

// For each texel of the next level along one axis: the source texels it covers and their
// weights (overlap of [x * size / next, (x + 1) * size / next) with each texel), summing to 1.
struct AxisFootprint {
  std::size_t first = 0;
  std::vector<double> weights;
};
std::vector<AxisFootprint> axis_footprints(std::size_t size, std::size_t next) {
  std::vector<AxisFootprint> footprints(next);
  const double scale = static_cast<double>(size) / static_cast<double>(next);
  for (std::size_t x = 0; x < next; ++x) {
    const double begin = static_cast<double>(x) * scale, end = begin + scale;
    AxisFootprint& footprint = footprints[x];
    footprint.first = static_cast<std::size_t>(std::floor(begin));
    for (std::size_t s = footprint.first; s < size && static_cast<double>(s) < end; ++s) {
      const double overlap =
          std::min(end, static_cast<double>(s + 1)) - std::max(begin, static_cast<double>(s));
      footprint.weights.push_back(overlap / scale);
    }
  }
  return footprints;
}

}  // namespace

std::string_view bake_solve_name(BakeSolve solve) {
  return solve == BakeSolve::exact ? "exact" : "coefficient-table";
}

std::size_t mip_level_count(std::size_t width, std::size_t height) {
  std::size_t levels = 1;
  for (std::size_t size = std::max(width, height); size > 1; size /= 2)
    ++levels;
  return levels;
}

std::vector<float> downsample_level(const std::vector<float>& texels, std::size_t width,
                                    std::size_t height, std::size_t next_width,
                                    std::size_t next_height, unsigned threads) {
  const std::vector<AxisFootprint> columns = axis_footprints(width, next_width);
  const std::vector<AxisFootprint> rows = axis_footprints(height, next_height);
  constexpr std::size_t kChannels = kCoefficientTextureChannels;
  std::vector<float> next(next_width * next_height * kChannels);
  fill_rows_in_parallel(next_height, threads, [&] {
    return [&](std::size_t y) {
      for (std::size_t x = 0; x < next_width; ++x) {
        double sum[kChannels] = {};
        for (std::size_t j = 0; j < rows[y].weights.size(); ++j) {
          for (std::size_t i = 0; i < columns[x].weights.size(); ++i) {
            const double weight = rows[y].weights[j] * columns[x].weights[i];
            const float* texel =
                &texels[((rows[y].first + j) * width + columns[x].first + i) * kChannels];
            for (std::size_t c = 0; c < kChannels; ++c)
              sum[c] += weight * texel[c];
          }
        }
        for (std::size_t c = 0; c < kChannels; ++c)
          next[(y * next_width + x) * kChannels + c] = static_cast<float>(sum[c]);
      }
    };
  });
  return next;
}

std::vector<std::vector<float>> mip_chain(std::vector<float> level0, std::size_t width,
                                          std::size_t height, unsigned threads) {
  std::vector<std::vector<float>> levels;
  levels.push_back(std::move(level0));
  while (width > 1 || height > 1) {
    const std::size_t next_width = std::max<std::size_t>(1, width / 2);
    const std::size_t next_height = std::max<std::size_t>(1, height / 2);
    levels.push_back(
        downsample_level(levels.back(), width, height, next_width, next_height, threads));
    width = next_width;
    height = next_height;
  }
  return levels;
}

BakedCoefficients bake_coefficients(const BakeInputs& inputs, const BakeOptions& options) {
  BakedCoefficients baked;
  baked.basis = options.basis;
  baked.levels.resize(mip_level_count(inputs.width, inputs.height));
  allocate_level(baked.levels.front(), inputs.width, inputs.height, options.f0);
  const bool exact = inputs.model == BakeModel::artistic && inputs.first.is_quantised() &&
                     inputs.second.is_quantised();
  baked.solve = exact ? BakeSolve::exact : BakeSolve::table;
  if (exact)
    solve_exact(inputs, options, baked);
  else
    solve_with_table(inputs, options, baked);

  for (std::size_t k = 1; k < baked.levels.size(); ++k) {
    baked.levels[k].width = std::max<std::size_t>(1, inputs.width >> k);
    baked.levels[k].height = std::max<std::size_t>(1, inputs.height >> k);
  }
  for (std::vector<float> CoefficientLevel::*plane :
       {&CoefficientLevel::f0, &CoefficientLevel::c2, &CoefficientLevel::c3}) {
    if ((baked.levels.front().*plane).empty()) continue;
    std::vector<std::vector<float>> chain = mip_chain(std::move(baked.levels.front().*plane),
                                                      inputs.width, inputs.height, options.threads);
    for (std::size_t k = 0; k < chain.size(); ++k)
      baked.levels[k].*plane = std::move(chain[k]);
  }
  return baked;
}

runtime::ChannelCoefficients level_coefficients(const CoefficientLevel& level, std::size_t x,
                                                std::size_t y, std::size_t channel) {
  const std::size_t offset = (y * level.width + x) * kCoefficientTextureChannels + channel;
  const double f0 = level.f0[offset];
  return {f0, 1.0 - f0, level.c2[offset], level.c3[offset]};
}

}  // namespace matc
