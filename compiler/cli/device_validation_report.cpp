#include "device_validation_report.h"

#include <fmt/core.h>

namespace matc::cli {

void add_device_options(CLI::App& command, DeviceCliOptions& device) {
  command.add_flag("--vk-validation", device.layers,
                   "Enable the Khronos validation layer; any message it reports fails");
  command.add_option("--device", device.name,
                     "Use the Vulkan device whose name contains this (default: a GPU if any, "
                     "else lavapipe)");
}

namespace {

std::string describe(const char* label, const Discrepancy& found, double tolerance, bool direct) {
  if (found.max_abs <= tolerance) return fmt::format("  {} {:.2e}", label, found.max_abs);
  const std::string where = direct ? fmt::format("mu {:.4f}", found.where.mu)
                                   : fmt::format("NdotV {:.4f}, roughness {:.4f}",
                                                 found.where.ndotv, found.where.roughness);
  return fmt::format("  {} {:.2e} > {:.0e} at {}", label, found.max_abs, tolerance, where);
}

}  // namespace

std::unique_ptr<DeviceValidator> open_device_validator(const Build& build,
                                                       const DeviceCliOptions& options) {
  try {
    auto validator = std::make_unique<DeviceValidator>(
        build, vulkan::ContextOptions{options.layers, options.name});
    const ValidationTolerance& tolerance = validator->tolerance();
    fmt::print(
        "matc: validating on {}{}; tolerances F {:.0e}, Fbar {:.0e}, closed-form Fbar {:.0e}{}\n",
        validator->device_name(), options.layers ? " with the validation layer" : "",
        tolerance.fresnel, tolerance.preintegrated, tolerance.analytic,
        build.embedded_lut() ? fmt::format(", embedded Fbar {:.0e}", tolerance.embedded) : "");
    return validator;
  } catch (const vulkan::VulkanError& error) {
    fmt::print(stderr, "matc: error: cannot validate on a Vulkan device: {}\n", error.what());
    return nullptr;
  }
}

namespace {

// Prints the validation layer's messages since `messages_before`; false when there were any.
bool report_layer_messages(const DeviceValidator& validator, std::size_t messages_before,
                           std::string_view subject) {
  const std::vector<std::string> messages = validator.layer_messages();
  for (std::size_t i = messages_before; i < messages.size(); ++i)
    fmt::print(stderr, "{}: validation layer: {}\n", subject, messages[i]);
  return messages.size() == messages_before;
}

std::string describe_table(const char* label, const TableDiscrepancy& found, double tolerance,
                           const std::vector<TableQuery>& queries, bool from_ior) {
  if (found.max_abs <= tolerance) return fmt::format("  {} {:.2e}", label, found.max_abs);
  const TableQuery& q = queries[found.query];
  const auto& first = from_ior ? q.n : q.reflectivity;
  const auto& second = from_ior ? q.k : q.edge_tint;
  return fmt::format(
      "  {} {:.2e} > {:.0e} at {} ({:.4f}, {:.4f}, {:.4f}), {} ({:.4f}, {:.4f}, "
      "{:.4f}), mu {:.4f}, NdotV {:.4f}, roughness {:.4f}",
      label, found.max_abs, tolerance, from_ior ? "n" : "r", first[0], first[1], first[2],
      from_ior ? "k" : "g", second[0], second[1], second[2], q.mu, q.ndotv, q.roughness);
}

}  // namespace

bool validate_coefficient_table_and_report(const DeviceValidator& validator) {
  const std::size_t messages_before = validator.layer_messages().size();
  const TableValidation result = validator.validate_coefficient_table();
  const std::vector<TableQuery> queries = table_validation_queries();
  const double tolerance = validator.tolerance().preintegrated;
  for (const TablePathValidation& path : result.paths) {
    std::string line = fmt::format("{:<20} {}", "coefficient table",
                                   path.language == ShaderLanguage::glsl ? "GLSL" : "HLSL");
    line += describe_table("F(r, g)", path.fresnel, tolerance, queries, false);
    line += describe_table("Fbar(r, g)", path.preintegrated, tolerance, queries, false);
    line += describe_table("F(n, k)", path.from_ior, tolerance, queries, true);
    line += describe_table("F(baked)", path.baked, tolerance, queries, false);
    fmt::print("{}  {}\n", line, path.passed ? "ok" : "FAILED");
  }
  return report_layer_messages(validator, messages_before, "coefficient table") && result.passed();
}

namespace {

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

}  // namespace

bool validate_area_lights_and_report(const DeviceValidator& validator) {
  const std::size_t messages_before = validator.layer_messages().size();
  const AreaLightValidation result = validator.validate_area_lights();
  const std::vector<AreaLightQuery> queries = area_light_validation_queries();
  const double tolerance = validator.tolerance().preintegrated;
  const auto describe = [&](const char* label, const TableDiscrepancy& found) {
    if (found.max_abs <= tolerance) return fmt::format("  {} {:.2e}", label, found.max_abs);
    const AreaLightQuery& q = queries[found.query];
    return fmt::format("  {} {:.2e} > {:.0e} at light {} (a {}), NdotV {:.4f}, roughness {:.4f}",
                       label, found.max_abs, tolerance, found.query, kind_name(q.kind), q.ndotv,
                       q.roughness);
  };
  for (const AreaLightPathValidation& path : result.paths) {
    std::string line = fmt::format("{:<20} {}", "area lights (LTC)",
                                   path.language == ShaderLanguage::glsl ? "GLSL" : "HLSL");
    line += describe("L", path.radiance);
    line += describe("I_ltc", path.integral);
    fmt::print("{}  {}\n", line, path.passed ? "ok" : "FAILED");
  }
  return report_layer_messages(validator, messages_before, "area lights") && result.passed();
}

bool validate_and_report(const DeviceValidator& validator, const CompiledMaterial& compiled) {
  const std::size_t messages_before = validator.layer_messages().size();
  const MaterialValidation result = validator.validate(compiled);
  const ValidationTolerance& tolerance = validator.tolerance();
  for (const PathValidation& path : result.paths) {
    std::string line = fmt::format("{:<20} {}", result.name,
                                   path.language == ShaderLanguage::glsl ? "GLSL" : "HLSL");
    line += describe("F", path.fresnel, tolerance.fresnel, true);
    line += describe("Fbar", path.preintegrated, tolerance.preintegrated, false);
    if (path.embedded) line += describe("embedded Fbar", *path.embedded, tolerance.embedded, false);
    line += describe("closed-form Fbar", path.analytic, tolerance.analytic, false);
    fmt::print("{}  {}\n", line, path.passed ? "ok" : "FAILED");
  }
  return report_layer_messages(validator, messages_before, result.name) && result.passed();
}

}  // namespace matc::cli
