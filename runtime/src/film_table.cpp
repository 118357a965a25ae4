#include "matc/runtime/film_table.h"

#include <algorithm>
#include <cmath>

#include "texel_axis.h"

namespace matc::runtime {
namespace {

// The rows of Fbar as sample_bilinear reads a table.
struct PreintegratedRows {
  const std::vector<Rgb>& nodes;
  const Rgb& texel(std::size_t x, std::size_t y) const {
    return nodes[y * FilmTable::kViewNodes + x];
  }
};

// a + weight (b - a), channel by channel: how a sampler blends two texels.
Rgb mix(const Rgb& a, const Rgb& b, double weight) {
  return {a[0] + weight * (b[0] - a[0]), a[1] + weight * (b[1] - a[1]),
          a[2] + weight * (b[2] - a[2])};
}

double squared_node(std::size_t i, std::size_t nodes) {
  const double u = static_cast<double>(i) / static_cast<double>(nodes - 1);
  return u * u;
}

}  // namespace

double film_table_cosine(std::size_t i) {
  return squared_node(i, FilmTable::kCosineNodes);
}

double film_table_view_cosine(std::size_t i) {
  return squared_node(i, FilmTable::kViewNodes);
}

double film_table_roughness(std::size_t j) {
  return FilmTable::kMinRoughness +
         (1.0 - FilmTable::kMinRoughness) * squared_node(j, FilmTable::kRoughnessNodes);
}

double film_cosine_coordinate(double mu) {
  return std::sqrt(unit_clamp(mu));
}

// Uniform in sqrt(roughness - 0.05): denser towards a mirror, where the lobe's average of F
// leaves F(NdotV) fastest.
double film_roughness_coordinate(double roughness) {
  const double above = roughness - FilmTable::kMinRoughness;
  return std::sqrt(unit_clamp(above / (1.0 - FilmTable::kMinRoughness)));
}

std::vector<float> film_table_texels(const FilmTable& table) {
  std::vector<float> texels;
  texels.reserve(FilmTable::kWidth * FilmTable::kHeight * 4);
  const auto append = [&texels](const Rgb& value) {
    texels.insert(texels.end(), {static_cast<float>(value[0]), static_cast<float>(value[1]),
                                 static_cast<float>(value[2]), 1.0f});
  };
  for (const Rgb& node : table.fresnel)
    append(node);
  for (const Rgb& node : table.preintegrated)
    append(node);
  return texels;
}

FilmNodePosition film_cosine_position(double mu) {
  const auto [left, weight] =
      texel_axis_position(film_cosine_coordinate(mu), FilmTable::kCosineNodes);
  return {left, weight};
}

Rgb film_fresnel(const FilmTable& table, double mu) {
  const auto [left, weight] = film_cosine_position(mu);
  return mix(table.fresnel[left], table.fresnel[left + 1], weight);
}

Rgb film_preintegrated(const FilmTable& table, double ndotv, double roughness) {
  return sample_bilinear<3>(PreintegratedRows{table.preintegrated}, FilmTable::kViewNodes,
                            FilmTable::kRoughnessNodes, film_cosine_coordinate(ndotv),
                            film_roughness_coordinate(roughness));
}

namespace {

// The slice below thickness coordinate t and the weight of the one above, for N >= 2 slices. The
// position is held kFilmStackInset of a slice inside the end slices, as the shaders hold it: in a
// texture thousands of rows tall a float texcoord on the last slice's texel centre can land a
// few ten-thousandths of a texel past it, into the next block's rows (another roughness node).
std::pair<std::size_t, double> slice_position(const FilmStack& stack, double thickness) {
  const double last = static_cast<double>(stack.slices.size() - 1);
  const double position =
      std::clamp(unit_clamp(thickness) * last, kFilmStackInset, last - kFilmStackInset);
  const auto lower = static_cast<std::size_t>(position);
  return {lower, position - static_cast<double>(lower)};
}

template <typename Read>
Rgb between_slices(const FilmStack& stack, double thickness, const Read& read) {
  if (stack.slices.size() == 1) return read(stack.slices.front());
  const auto [lower, weight] = slice_position(stack, thickness);
  return mix(read(stack.slices[lower]), read(stack.slices[lower + 1]), weight);
}

}  // namespace

std::size_t film_stack_height(const FilmStack& stack) {
  return FilmTable::kHeight * stack.slices.size();
}

std::vector<float> film_stack_texels(const FilmStack& stack) {
  std::vector<float> texels;
  texels.reserve(FilmTable::kWidth * film_stack_height(stack) * 4);
  const auto append = [&texels](const Rgb& value) {
    texels.insert(texels.end(), {static_cast<float>(value[0]), static_cast<float>(value[1]),
                                 static_cast<float>(value[2]), 1.0f});
  };
  for (const FilmTable& slice : stack.slices) {
    for (const Rgb& node : slice.fresnel)
      append(node);
  }
  for (std::size_t j = 0; j < FilmTable::kRoughnessNodes; ++j) {
    for (const FilmTable& slice : stack.slices) {
      for (std::size_t i = 0; i < FilmTable::kViewNodes; ++i)
        append(slice.preintegrated[j * FilmTable::kViewNodes + i]);
    }
  }
  return texels;
}

double film_stack_thickness(const FilmStack& stack, std::size_t s) {
  if (stack.slices.size() < 2) return stack.maximum_nm;
  const double t = static_cast<double>(s) / static_cast<double>(stack.slices.size() - 1);
  return stack.minimum_nm + t * (stack.maximum_nm - stack.minimum_nm);
}

FilmTable film_stack_table_at(const FilmStack& stack, double thickness) {
  if (stack.slices.size() == 1) return stack.slices.front();
  const auto [lower, weight] = slice_position(stack, thickness);
  const FilmTable& a = stack.slices[lower];
  const FilmTable& b = stack.slices[lower + 1];
  FilmTable table;
  for (std::size_t i = 0; i < table.fresnel.size(); ++i)
    table.fresnel[i] = mix(a.fresnel[i], b.fresnel[i], weight);
  table.preintegrated.reserve(a.preintegrated.size());
  for (std::size_t i = 0; i < a.preintegrated.size(); ++i)
    table.preintegrated.push_back(mix(a.preintegrated[i], b.preintegrated[i], weight));
  return table;
}

Rgb film_stack_fresnel(const FilmStack& stack, double mu, double thickness) {
  return between_slices(stack, thickness,
                        [mu](const FilmTable& slice) { return film_fresnel(slice, mu); });
}

Rgb film_stack_preintegrated(const FilmStack& stack, double ndotv, double roughness,
                             double thickness) {
  return between_slices(stack, thickness, [ndotv, roughness](const FilmTable& slice) {
    return film_preintegrated(slice, ndotv, roughness);
  });
}

}  // namespace matc::runtime
