#include "ltc/ltc_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "base/parallel_rows.h"
#include "formats/header_arrays.h"
#include "ltc/area_light_reference.h"
#include "ltc/ggx_lobe.h"
#include "ltc/lobe_polygons.h"
#include "ltc/polygon_light.h"
#include "matc/version.h"
#include "nelder_mead.h"
#include "texel_lobes.h"

namespace matc {
namespace {

constexpr double kMinShape = 1e-7;  // m11, m22 stay positive
constexpr std::size_t kMaxIterations = 400;
constexpr double kRelativeTolerance = 1e-6;
constexpr double kPolygonFitL1Slack = 1.5;

// M = [X Y Z] S for a lobe axis Z = (zx, 0, zz), X = (zz, 0, -zx), Y = (0, 1, 0).
struct LtcMatrix {
  explicit LtcMatrix(const LtcShape& shape)
      : m11(std::max(shape.m11, kMinShape)),
        m22(std::max(shape.m22, kMinShape)),
        m13(shape.m13),
        zx(std::sin(shape.angle)),
        zz(std::cos(shape.angle)) {}

  // M w.
  Vec3 transform(const Vec3& w) const {
    const double x = m11 * w[0] + m13 * w[2];
    const double y = m22 * w[1];
    const double z = w[2];
    return {zz * x + zx * z, y, -zx * x + zz * z};
  }
  // M^-1 w.
  Vec3 inverse(const Vec3& w) const {
    const double x = zz * w[0] - zx * w[2];
    const double z = zx * w[0] + zz * w[2];
    return {(x - m13 * z) / m11, w[1] / m22, z};
  }
  double determinant() const { return m11 * m22; }

  // The transformed cosine's density at the unit direction w.
  double density(const Vec3& w) const {
    const Vec3 o = inverse(w);
    const double length2 = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
    const double length = std::sqrt(length2);
    if (o[2] <= 0.0) return 0.0;
    return (o[2] / length) / (std::numbers::pi * determinant() * length2 * length);
  }

  // M^-1 scaled so that its middle entry is 1.
  runtime::LtcInverse normalized_inverse() const {
    return {m22 * (zz - m13 * zx) / m11, m22 * (-zx - m13 * zz) / m11, m22 * zx, m22 * zz};
  }

  double m11, m22, m13, zx, zz;
};

// The shape (and frame angle) of the LTC whose normalised inverse is `inverse`: M's xz-block
// F = [[d, -b], [-c, a]] / (ad - bc) split as rotation times [[u11, u12], [0, u22]] (QR), then
// scaled so that the corner is 1 (M's scale is free: m22 = 1 / u22 keeps M^-1's middle entry 1).
LtcShape shape_of(const runtime::LtcInverse& inverse) {
  const double det = inverse.a * inverse.d - inverse.b * inverse.c;
  const double f00 = inverse.d / det, f01 = -inverse.b / det;
  const double f10 = -inverse.c / det, f11 = inverse.a / det;
  const double u11 = std::hypot(f00, f10);
  const double zz = f00 / u11, zx = -f10 / u11;
  const double u12 = zz * f01 - zx * f11;
  const double u22 = zx * f01 + zz * f11;
  return {u11 / u22, 1.0 / u22, u12 / u22, std::atan2(zx, zz)};
}

// The fixed point sets of one texel: cosine directions (LTC samples before M) and the lobe's own
// samples with their densities.
struct FitSamples {
  std::vector<Vec3> cosine;
  std::vector<Vec3> lobe_direction;
  std::vector<double> lobe_density;  // normalised lobe at the sample
  std::vector<double> lobe_pdf;
  double albedo = 0.0;
};

FitSamples make_samples(const GgxLobe& lobe) {
  constexpr std::size_t n = kLtcFitSamplesPerAxis;
  FitSamples s;
  s.cosine.reserve(n * n);
  std::vector<Vec3> directions;
  std::vector<GgxLobe::Value> values;
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double u1 = (static_cast<double>(i) + 0.5) / static_cast<double>(n);
      const double u2 = (static_cast<double>(j) + 0.5) / static_cast<double>(n);
      const double radius = std::sqrt(u1);
      const double phi = 2.0 * std::numbers::pi * u2;
      s.cosine.push_back({radius * std::cos(phi), radius * std::sin(phi), std::sqrt(1.0 - u1)});
      directions.push_back(lobe.sample(u1, u2));
      values.push_back(lobe.evaluate(directions.back()));
    }
  }
  s.albedo = lobe.albedo(n);
  for (std::size_t k = 0; k < values.size(); ++k) {
    s.lobe_direction.push_back(directions[k]);
    s.lobe_density.push_back(values[k].lobe / s.albedo);
    s.lobe_pdf.push_back(values[k].pdf);
  }
  return s;
}

struct Errors {
  double cubed = 0.0;
  double absolute = 0.0;
};

// Both integrals of |D_ggx - D_ltc|^p, each point weighted by the balance heuristic.
Errors fit_errors(const GgxLobe& lobe, const FitSamples& s, const LtcMatrix& m) {
  Errors e;
  const auto add = [&](double difference, double pdf_sum) {
    if (pdf_sum <= 0.0) return;
    e.absolute += difference / pdf_sum;
    e.cubed += difference * difference * difference / pdf_sum;
  };
  for (const Vec3& w : s.cosine) {
    const Vec3 direction = m.transform(w);
    const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                    direction[2] * direction[2]);
    const Vec3 l{direction[0] / length, direction[1] / length, direction[2] / length};
    // D_ltc at M w / |M w| = D_o(w) |M w|^3 / det M.
    const double ltc = w[2] / std::numbers::pi * length * length * length / m.determinant();
    const GgxLobe::Value value = lobe.evaluate(l);
    add(std::abs(value.lobe / s.albedo - ltc), ltc + value.pdf);
  }
  for (std::size_t k = 0; k < s.lobe_direction.size(); ++k) {
    const double ltc = m.density(s.lobe_direction[k]);
    add(std::abs(s.lobe_density[k] - ltc), ltc + s.lobe_pdf[k]);
  }
  const double count = static_cast<double>(s.cosine.size());
  return {e.cubed / count, e.absolute / count};
}

// Nelder-Mead from `first_guess` over m11 = m22 alone (isotropic) or the whole shape.
template <typename Minimised>
LtcCellFit fit_shape(const GgxLobe& lobe, const FitSamples& samples, const LtcShape& first_guess,
                     bool isotropic, const Minimised& minimised) {
  LtcShape shape = first_guess;
  if (isotropic) {
    const auto best = nelder_mead_minimum<1>(
        {first_guess.m11}, {0.5 * first_guess.m11},
        [&](const std::array<double, 1>& p) {
          return minimised({p[0], p[0], 0.0, 0.0});
        },
        kMaxIterations, kRelativeTolerance);
    shape = {std::max(best[0], kMinShape), std::max(best[0], kMinShape), 0.0, 0.0};
  } else {
    const double step = 0.25 * std::max(first_guess.m11, first_guess.m22);
    const auto best = nelder_mead_minimum<4>(
        {first_guess.m11, first_guess.m22, first_guess.m13, first_guess.angle},
        {step, step, step, std::min(step, 0.05)},
        [&](const std::array<double, 4>& p) {
          return minimised({p[0], p[1], p[2], p[3]});
        },
        kMaxIterations, kRelativeTolerance);
    shape = {std::max(best[0], kMinShape), std::max(best[1], kMinShape), best[2], best[3]};
  }
  const LtcMatrix matrix(shape);
  const Errors errors = fit_errors(lobe, samples, matrix);
  return {matrix.normalized_inverse(), shape, errors.cubed, errors.absolute};
}

// `inverse` as it is, scored against the lobe on `samples`.
LtcCellFit score_ltc_cell(const GgxLobe& lobe, const FitSamples& samples,
                          const runtime::LtcInverse& inverse) {
  const LtcShape shape = shape_of(inverse);
  const Errors errors = fit_errors(lobe, samples, LtcMatrix(shape));
  return {inverse, shape, errors.cubed, errors.absolute};
}

}  // namespace

LtcCellFit evaluate_ltc_cell(const runtime::LtcInverse& inverse, double ndotv, double roughness) {
  const GgxLobe lobe(ndotv, roughness);
  return score_ltc_cell(lobe, make_samples(lobe), inverse);
}

LtcCellFit fit_ltc_to_polygons(const runtime::LtcInverse& start, double ndotv, double roughness,
                               std::span<const LobePolygon> polygons,
                               PolygonSetAggregate aggregate) {
  constexpr std::size_t kMaxRestarts = 8;
  const GgxLobe lobe(ndotv, roughness);
  const FitSamples samples = make_samples(lobe);
  const auto error = [&](const LtcShape& shape) {
    const PolygonSetError e =
        ltc_polygon_set_error(LtcMatrix(shape).normalized_inverse(), polygons);
    return aggregate == PolygonSetAggregate::mean ? e.mean : e.max;
  };
  LtcCellFit best = score_ltc_cell(lobe, samples, start);
  double best_error = error(best.shape);
  // A simplex collapses on the ridges of a largest error: restarting from where it stopped, with
  // fresh steps, goes on along them.
  for (std::size_t restart = 0; restart < kMaxRestarts; ++restart) {
    const LtcCellFit fit = fit_shape(lobe, samples, best.shape, false, error);
    const double fit_error = error(fit.shape);
    if (!(fit_error < best_error * (1.0 - 1e-4))) break;
    best = fit;
    best_error = fit_error;
  }
  return best;
}

double ltc_texel_ndotv(std::size_t x, std::size_t size, runtime::LtcViewAxis axis) {
  return runtime::ltc_ndotv_from_u(static_cast<double>(x) / static_cast<double>(size - 1), axis);
}

double ltc_texel_roughness(std::size_t y, std::size_t size) {
  return static_cast<double>(y) / static_cast<double>(size - 1);
}

LtcCellFit fit_ltc_cell(double ndotv, double roughness, const LtcShape& first_guess, bool isotropic,
                        LtcObjective objective, const LtcPolygonVariant& variant) {
  const GgxLobe lobe(ndotv, roughness);
  const FitSamples samples = make_samples(lobe);
  // The densities' distance: l3, or l1 (the polygon objective's start).
  const LtcCellFit density_fit =
      fit_shape(lobe, samples, first_guess, isotropic, [&](const LtcShape& shape) {
        const Errors errors = fit_errors(lobe, samples, LtcMatrix(shape));
        return objective == LtcObjective::l3 ? errors.cubed : errors.absolute;
      });
  if (objective == LtcObjective::polygons) {
    // From the L1 fit (a shape near the lobe everywhere), the mean error over the training quads.
    const std::size_t count =
        ndotv < kLtcGrazingNdotV ? variant.grazing_polygons : kLtcTrainingPolygons;
    const std::vector<LobePolygon> polygons = lobe_polygons(
        lobe, samples.albedo, lobe_polygon_seed(kTrainingPolygonSeed, ndotv, roughness), count,
        kLtcTrainingPolygonSamples);
    // Where the quads say little (a narrow lobe inside most of them), many shapes fit them: the
    // search stays among shapes whose L1 distance is near the L1 fit's.
    const double l1_bound = kPolygonFitL1Slack * density_fit.l1_distance + 0.01;
    return fit_shape(lobe, samples, density_fit.shape, isotropic, [&](const LtcShape& shape) {
      const LtcMatrix matrix(shape);
      const double l1 = fit_errors(lobe, samples, matrix).absolute;
      const runtime::LtcInverse inverse = matrix.normalized_inverse();
      return ltc_polygon_set_error(inverse, polygons).mean +
             variant.horizon_weight * ltc_mass_below_horizon(inverse) +
             std::max(0.0, l1 - l1_bound);
    });
  }
  return density_fit;
}

LtcTable fit_ltc_table(const LtcFitOptions& options, std::size_t first_row, std::size_t row_count) {
  if (options.size < 2 || options.size > 1024)
    throw std::invalid_argument("LTC table size must be within [2, 1024]");
  const std::size_t size = options.size;
  LtcTable table;
  table.size = size;
  table.view_axis = options.view_axis;
  table.texels.assign(size * size * runtime::kLtcChannels, 0.0f);
  table.cubed_distance.assign(size * size, 0.0);
  table.l1_distance.assign(size * size, 0.0);
  const std::size_t end_row = std::min(size, first_row + std::min(row_count, size));
  const std::size_t rows = first_row < end_row ? end_row - first_row : 0;
  fill_rows_in_parallel(rows, options.threads, [&] {
    return [&](std::size_t row) {
      const std::size_t y = first_row + row;
      const double roughness = ltc_texel_roughness(y, size);
      const double alpha = std::max(roughness * roughness, kMinLobeAlpha);
      // Normal incidence first (a rotationally symmetric lobe), then towards grazing.
      // Each texel starts from the one before with its frame turned as far as the mirror
      // direction turned, so that even a narrow lobe starts where it overlaps the GGX one.
      LtcShape guess{alpha, alpha, 0.0, 0.0};
      double previous_view_angle = 0.0;
      for (std::size_t step = 0; step < size; ++step) {
        const std::size_t x = size - 1 - step;
        const double ndotv = ltc_texel_ndotv(x, size, options.view_axis);
        const double view_angle = std::acos(std::clamp(ndotv, kMinLobeNdotV, 1.0));
        guess.angle -= view_angle - previous_view_angle;
        previous_view_angle = view_angle;
        const LtcCellFit fit =
            fit_ltc_cell(ndotv, roughness, guess, step == 0, options.objective, options.variant);
        guess = fit.shape;
        const std::size_t index = y * size + x;
        float* texel = &table.texels[index * runtime::kLtcChannels];
        texel[0] = static_cast<float>(fit.inverse.a);
        texel[1] = static_cast<float>(fit.inverse.b);
        texel[2] = static_cast<float>(fit.inverse.c);
        texel[3] = static_cast<float>(fit.inverse.d);
        table.cubed_distance[index] = fit.cubed_distance;
        table.l1_distance[index] = fit.l1_distance;
      }
    };
  });
  return table;
}

double ltc_mass_below_horizon(const runtime::LtcInverse& inverse) {
  return 0.5 * (1.0 - inverse.a / std::hypot(inverse.a, inverse.c));
}

std::vector<double> ltc_polygon_errors(const runtime::LtcTableView& table, std::size_t samples,
                                       unsigned threads) {
  const std::size_t size = table.size;
  std::vector<double> errors(size * size, 0.0);
  const FresnelAtCosine one = [](double) { return runtime::Rgb{1.0, 1.0, 1.0}; };
  for_each_texel_lobe(
      size, table.view_axis, threads,
      [&](std::size_t index, std::size_t x, std::size_t y, const GgxLobe& lobe, double, double) {
        const Vec3& v = lobe.view();
        const Vec3 mirror{-v[0], 0.0, v[2]};
        const std::array<Vec3, 3> directions = {
            mirror, Vec3{0.0, 0.0, 1.0}, Vec3{-1.0, 0.0, 0.1}};  // the last crosses the horizon
        const auto texel = table.texel(x, y);
        const runtime::LtcInverse inverse{texel[0], texel[1], texel[2], texel[3]};
        const double albedo = lobe.albedo(kLtcFitSamplesPerAxis);
        double worst = 0.0;
        for (const Vec3& direction : directions) {
          const std::array<Vec3, 4> square = facing_square(direction, 2.0, 0.5);
          const double reference = integrate_polygon_light(lobe, square, one, samples).mean[0];
          const double ltc = runtime::ltc_polygon_integral(inverse, square);
          worst = std::max(worst, std::abs(albedo * ltc - reference) / albedo);
        }
        errors[index] = worst;
      });
  return errors;
}

std::string ltc_table_source(const LtcTable& table) {
  std::string out = fmt::format(
      "// Generated by `matc basis ltc-table` (matc {}). Do not edit: rerun it.\n"
      "// The inverse LTC matrices of GGX, {} x {} texels (a, b, c, d):\n"
      "// M^-1 = [[a, 0, b], [0, 1, 0], [c, 0, d]] at NdotV = 1 - (1 - x / {})^2 and roughness = y "
      "/ {}\n"
      "// (layout: matc/runtime/ltc.h).\n"
      "// clang-format off\n"
      "#include \"matc/runtime/ltc.h\"\n\n"
      "namespace matc::runtime {{\n"
      "namespace {{\n\n"
      "constexpr std::size_t kSize = {};\n",
      kVersion, table.size, table.size, table.size - 1, table.size - 1, table.size);
  formats::append_float_array(out, "constexpr", "kTexels", table.texels, 8);
  out +=
      "}  // namespace\n\n"
      "LtcTableView shipped_ltc_table() {\n"
      "  return {kSize, kTexels};\n"
      "}\n\n"
      "}  // namespace matc::runtime\n";
  return out;
}

std::string_view ltc_objective_name(LtcObjective objective) {
  switch (objective) {
    case LtcObjective::l3:
      return "l3";
    case LtcObjective::polygons:
      return "polygons";
    case LtcObjective::l1:
      break;
  }
  return "l1";
}

}  // namespace matc
