// The area-light check: the LTC quad, disk and sphere lights (radiance and the LTC integral, and
// the quality level's radiance, shape and Fresnel following the light) against the CPU runtime.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "emit/validation_kernel.h"
#include "largest_difference.h"
#include "ltc/polygon_light.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/ltc_following.h"
#include "matc/runtime/lut.h"
#include "validate/device_validator.h"

namespace matc {
namespace {

constexpr std::size_t kAreaLightQueries = 2048;

using runtime::cross;
using runtime::dot;
using runtime::normalize;
using runtime::Vec3;

Vec3 as_vec3(const std::array<float, 3>& v) {
  return {v[0], v[1], v[2]};
}

std::array<float, 3> as_float3(const Vec3& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// The shading frame the shaders build from (N, V): T1 towards V, T2 = N x T1.
struct ShadingFrame {
  Vec3 t1, t2, n;
  ShadingFrame(const Vec3& normal, const Vec3& view) : n(normalize(normal)) {
    const double along = dot(n, view);
    t1 = normalize({view[0] - n[0] * along, view[1] - n[1] * along, view[2] - n[2] * along});
    t2 = cross(n, t1);
  }
  Vec3 local(const Vec3& w) const { return {dot(t1, w), dot(t2, w), dot(n, w)}; }
};

// A unit vector from two numbers in [0, 1).
Vec3 direction(double u1, double u2) {
  const double z = 2.0 * u1 - 1.0;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * std::numbers::pi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

const char* kind_name(AreaLightQuery::Kind kind) {
  switch (kind) {
    case AreaLightQuery::Kind::quad:
      return "quad";
    case AreaLightQuery::Kind::disk:
      return "disk";
    case AreaLightQuery::Kind::sphere:
      return "sphere";
  }
  return "";
}

class AreaLightCheck final : public DeviceCheck {
 public:
  AreaLightCheck(const Build& build, const ValidationTolerance& tolerance)
      : build_(build),
        tolerance_(tolerance.preintegrated),
        queries_(area_light_validation_queries()) {}

  std::string subject() const override { return "area lights (LTC)"; }
  SpirvWords kernel(ShaderLanguage language) const override {
    return area_light_validation_module(build_, language);
  }
  KernelTables tables() const override { return {true, true, {}}; }
  std::size_t query_count() const override { return queries_.size(); }

  std::vector<float> packed_queries() const override {
    std::vector<float> packed;
    packed.reserve(queries_.size() * kAreaLightQueryVectors * 4);
    for (const AreaLightQuery& q : queries_) {
      const auto& r = q.reflectivity;
      const auto& g = q.edge_tint;
      packed.insert(packed.end(), {r[0], r[1], r[2], q.ndotv, g[0], g[1], g[2], q.roughness});
      packed.insert(packed.end(),
                    {q.normal[0], q.normal[1], q.normal[2], static_cast<float>(q.kind)});
      packed.insert(packed.end(), {q.view[0], q.view[1], q.view[2], q.radius});
      for (const auto& p : q.points)
        packed.insert(packed.end(), {p[0], p[1], p[2], 0.0f});
    }
    return packed;
  }

  std::size_t result_vec4s_per_query() const override { return 2; }

  std::vector<CheckedQuantity> compare(std::span<const float> results) const override {
    const runtime::CoefficientTableView table = build_.stored_coefficient_table().view();
    const runtime::LutView lut = build_.stored_lut().view();
    const runtime::LtcTableView ltc = runtime::shipped_ltc_table();
    // The LTC matrix and Fbar both come through the sampler: the preintegrated tolerance.
    CheckedQuantity radiance{"L", tolerance_};
    CheckedQuantity integral{"I_ltc", tolerance_};
    CheckedQuantity following{"L_following", tolerance_};
    const runtime::ShaderBasis& basis = runtime::shipped_shader_basis(build_.options().basis);
    for (std::size_t i = 0; i < queries_.size(); ++i) {
      const AreaLightQuery& q = queries_[i];
      const ShadingFrame frame(as_vec3(q.normal), as_vec3(q.view));
      std::vector<Vec3> local;
      if (q.kind == AreaLightQuery::Kind::disk) {
        for (const Vec3& p :
             runtime::disk_light_polygon(as_vec3(q.points[0]), as_vec3(q.points[1]), q.radius))
          local.push_back(frame.local(p));
      } else if (q.kind == AreaLightQuery::Kind::sphere) {
        for (const Vec3& p :
             runtime::sphere_light_polygon({0.0, 0.0, 0.0}, as_vec3(q.points[0]), q.radius))
          local.push_back(frame.local(p));
      } else {
        for (const auto& p : q.points)
          local.push_back(frame.local(as_vec3(p)));
      }
      const runtime::Coefficients coefficients =
          runtime::coefficients_from_table(table, as_vec3(q.reflectivity), as_vec3(q.edge_tint));
      const float* result = &results[8 * i];
      record_largest(
          radiance, runtime::polygon_light_ltc(coefficients, lut, ltc, q.ndotv, q.roughness, local),
          result, i);
      const double expected =
          runtime::ltc_polygon_integral(runtime::sample_ltc(ltc, q.ndotv, q.roughness), local);
      const float integral_result[3] = {result[3], result[3], result[3]};
      record_largest(integral, {expected, expected, expected}, integral_result, i);
      record_largest(following,
                     runtime::polygon_light_ltc_following(coefficients, lut, basis, ltc, q.ndotv,
                                                          q.roughness, local),
                     result + 4, i);
    }
    return {radiance, integral, following};
  }

  std::string describe_query(std::size_t index, std::string_view) const override {
    const AreaLightQuery& q = queries_[index];
    return fmt::format("light {} (a {}), NdotV {:.4f}, roughness {:.4f}", index, kind_name(q.kind),
                       q.ndotv, q.roughness);
  }

 private:
  const Build& build_;
  double tolerance_;
  std::vector<AreaLightQuery> queries_;
};

}  // namespace

std::vector<AreaLightQuery> area_light_validation_queries() {
  // Fixed-seed draws (mt19937_64's output is specified by the standard).
  std::mt19937_64 generator(16);
  const auto unit = [&] { return static_cast<double>(generator() >> 11) * 0x1p-53; };
  std::vector<AreaLightQuery> queries;
  queries.reserve(kAreaLightQueries);
  while (queries.size() < kAreaLightQueries) {
    AreaLightQuery q;
    for (std::size_t c = 0; c < 3; ++c) {
      q.reflectivity[c] = static_cast<float>(unit());
      q.edge_tint[c] = static_cast<float>(unit());
    }
    q.ndotv = static_cast<float>(unit());
    q.roughness = static_cast<float>(unit());
    // The shading frame turned at random: N, and V at the query's angle to it.
    const Vec3 n = direction(unit(), unit());
    const Vec3 helper = normalize(cross(n, direction(unit(), unit())));
    const double sine = std::sqrt(1.0 - static_cast<double>(q.ndotv) * q.ndotv);
    Vec3 v{};
    for (std::size_t k = 0; k < 3; ++k)
      v[k] = static_cast<double>(q.ndotv) * n[k] + sine * helper[k];
    q.normal = as_float3(n);
    q.view = as_float3(v);
    // The light: its centre at 0.5-3 units in a random direction, a third of them across or
    // below the horizon, facing a random way.
    const Vec3 toward = direction(0.2 + 0.8 * unit(), unit());  // local z in [-0.6, 1]
    const double distance = 0.5 + 2.5 * unit();
    // From the shading frame (T1 = helper, T2 = N x T1, N) to the world.
    const Vec3 local_centre{distance * toward[0], distance * toward[1], distance * toward[2]};
    const Vec3 side = cross(n, helper);
    Vec3 centre{};
    for (std::size_t k = 0; k < 3; ++k)
      centre[k] = local_centre[0] * helper[k] + local_centre[1] * side[k] + local_centre[2] * n[k];
    const Vec3 facing = direction(unit(), unit());
    // Six quads, then a disk and a sphere, in every eight lights.
    const std::size_t slot = queries.size() % 8;
    q.kind = slot == 6   ? AreaLightQuery::Kind::disk
             : slot == 7 ? AreaLightQuery::Kind::sphere
                         : AreaLightQuery::Kind::quad;
    if (q.kind != AreaLightQuery::Kind::quad) {
      // A sphere stays clear of the shading point: its radius under 0.8 of the distance.
      q.radius = static_cast<float>(std::min(0.05 + 0.95 * unit(), 0.8 * distance));
      q.points[0] = as_float3(centre);
      q.points[1] = as_float3(facing);
    } else {
      // A parallelogram in the plane through the centre across `facing`.
      const Vec3 u = normalize(cross(facing, direction(unit(), unit())));
      const Vec3 w = cross(facing, u);
      const double a = 0.05 + 1.5 * unit(), b = 0.05 + 1.5 * unit(), shear = unit() - 0.5;
      const std::array<std::array<double, 2>, 4> corners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
      for (std::size_t i = 0; i < 4; ++i) {
        Vec3 p{};
        for (std::size_t k = 0; k < 3; ++k)
          p[k] = centre[k] + a * (corners[i][0] + shear * corners[i][1]) * u[k] +
                 b * corners[i][1] * w[k];
        q.points[i] = as_float3(p);
      }
    }
    // Only lights the tools accept (above the horizon in part, not edge-on, convex).
    if (q.kind == AreaLightQuery::Kind::quad) {
      const ShadingFrame frame(as_vec3(q.normal), as_vec3(q.view));
      std::array<Vec3, 4> local{};
      for (std::size_t i = 0; i < 4; ++i)
        local[i] = frame.local(as_vec3(q.points[i]));
      if (!check_polygon_light(local).empty()) continue;
    }
    queries.push_back(q);
  }
  return queries;
}

std::unique_ptr<DeviceCheck> area_light_check(const Build& build,
                                              const ValidationTolerance& tolerance) {
  return std::make_unique<AreaLightCheck>(build, tolerance);
}

}  // namespace matc
