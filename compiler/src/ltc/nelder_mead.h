// Nelder-Mead's downhill simplex (reflection 1, expansion 2, contraction 1/2, shrink 1/2) over N
// parameters: derivative-free, and deterministic for a deterministic objective.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace matc {

template <std::size_t N, typename Objective>
std::array<double, N> nelder_mead_minimum(const std::array<double, N>& start,
                                          const std::array<double, N>& steps,
                                          const Objective& objective, std::size_t max_iterations,
                                          double relative_tolerance) {
  using Point = std::array<double, N>;
  std::array<Point, N + 1> simplex{};
  std::array<double, N + 1> values{};
  for (std::size_t i = 0; i <= N; ++i) {
    simplex[i] = start;
    if (i > 0) simplex[i][i - 1] += steps[i - 1];
    values[i] = objective(simplex[i]);
  }
  const auto along = [](const Point& from, const Point& to, double t) {
    Point p{};
    for (std::size_t k = 0; k < N; ++k)
      p[k] = from[k] + t * (to[k] - from[k]);
    return p;
  };
  for (std::size_t iteration = 0; iteration < max_iterations; ++iteration) {
    std::array<std::size_t, N + 1> order{};
    for (std::size_t i = 0; i <= N; ++i)
      order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    const std::size_t best = order[0], worst = order[N], second_worst = order[N - 1];
    if (values[worst] - values[best] <= relative_tolerance * std::abs(values[best])) break;
    Point centroid{};
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t k = 0; k < N; ++k)
        centroid[k] += simplex[order[i]][k] / static_cast<double>(N);

    const Point reflected = along(simplex[worst], centroid, 2.0);
    const double reflected_value = objective(reflected);
    if (reflected_value < values[best]) {
      const Point expanded = along(simplex[worst], centroid, 3.0);
      const double expanded_value = objective(expanded);
      const bool expand = expanded_value < reflected_value;
      simplex[worst] = expand ? expanded : reflected;
      values[worst] = expand ? expanded_value : reflected_value;
    } else if (reflected_value < values[second_worst]) {
      simplex[worst] = reflected;
      values[worst] = reflected_value;
    } else {
      const bool outside = reflected_value < values[worst];
      const Point contracted =
          outside ? along(centroid, reflected, 0.5) : along(centroid, simplex[worst], 0.5);
      const double contracted_value = objective(contracted);
      if (contracted_value < std::min(values[worst], reflected_value)) {
        simplex[worst] = contracted;
        values[worst] = contracted_value;
      } else {
        for (std::size_t i = 1; i <= N; ++i) {
          simplex[order[i]] = along(simplex[best], simplex[order[i]], 0.5);
          values[order[i]] = objective(simplex[order[i]]);
        }
      }
    }
  }
  std::size_t best = 0;
  for (std::size_t i = 1; i <= N; ++i)
    if (values[i] < values[best]) best = i;
  return simplex[best];
}

}  // namespace matc
