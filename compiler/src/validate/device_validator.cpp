#include <cstdint>
#include <optional>
#include <span>

#include "fit/coefficient_table.h"
#include "lut/preintegrate.h"
#include "matc/runtime/film_table.h"
#include "matc/runtime/ltc.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/compute_kernel.h"
#include "matc/vulkan/context.h"
#include "matc/vulkan/image.h"
#include "matc/vulkan/sampler.h"
#include "validate/device_validator.h"

namespace matc {
namespace {

constexpr std::size_t kWorkgroupSize = 64;  // every validation kernel's local size

}  // namespace

// The build's tables on the device, uploaded once for every check.
struct DeviceValidator::Device {
  vulkan::Context context;
  vulkan::Image lut;
  vulkan::Image coefficient_table;
  vulkan::Image ltc;
  vulkan::LutSampler sampler;

  // `table`: every layer of the preintegrated table, as the file holds them.
  Device(const vulkan::ContextOptions& options, const LutAtlas& table,
         const CoefficientTable& coefficients)
      : context(options),
        lut(context, static_cast<std::uint32_t>(table.width()),
            static_cast<std::uint32_t>(table.size), table.texels),
        coefficient_table(context, static_cast<std::uint32_t>(coefficients.size()),
                          static_cast<std::uint32_t>(coefficients.size()),
                          rgba_texels(coefficients)),
        ltc(context, static_cast<std::uint32_t>(runtime::shipped_ltc_table().size),
            static_cast<std::uint32_t>(runtime::shipped_ltc_table().size),
            runtime::shipped_ltc_table().texels),
        sampler(context) {}

  // One kernel over `packed` queries (whole workgroups: the padding queries are zeros, computed
  // but not read back), its results read back.
  std::vector<float> run(const SpirvWords& module, std::vector<float> packed,
                         std::size_t query_count, std::size_t result_vec4s_per_query,
                         const KernelTables& tables) const {
    const std::size_t groups = (query_count + kWorkgroupSize - 1) / kWorkgroupSize;
    const std::size_t padded = groups * kWorkgroupSize;
    packed.resize(packed.size() / query_count * padded, 0.0f);
    vulkan::Buffer query_buffer(context, packed.size() * sizeof(float),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    query_buffer.write<float>(packed);
    vulkan::Buffer result_buffer(context, padded * result_vec4s_per_query * 4 * sizeof(float),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::vector<vulkan::Binding> bindings = {vulkan::Binding::storage_buffer(0, query_buffer),
                                             vulkan::Binding::storage_buffer(1, result_buffer),
                                             vulkan::Binding::sampled_image(2, lut),
                                             vulkan::Binding::separate_sampler(3, sampler)};
    if (tables.coefficient_table)
      bindings.push_back(vulkan::Binding::sampled_image(4, coefficient_table));
    if (tables.ltc) bindings.push_back(vulkan::Binding::sampled_image(5, ltc));
    std::optional<vulkan::Image> film;
    if (!tables.film.empty()) {
      // 18 rows a slice: a thickness per pixel's stack is as tall as its slices make it.
      const std::size_t height = tables.film.size() / (4 * runtime::FilmTable::kWidth);
      film.emplace(context, static_cast<std::uint32_t>(runtime::FilmTable::kWidth),
                   static_cast<std::uint32_t>(height), tables.film);
      bindings.push_back(vulkan::Binding::sampled_image(6, *film));
    }
    const vulkan::ComputeKernel kernel(context, module, bindings);
    kernel.dispatch(static_cast<std::uint32_t>(groups));
    return result_buffer.read<float>(query_count * result_vec4s_per_query * 4);
  }
};

DeviceValidator::DeviceValidator(const Build& build, const vulkan::ContextOptions& device,
                                 ValidationTolerance tolerance)
    : build_(build),
      tolerance_(tolerance),
      device_(std::make_unique<Device>(device, build.stored_atlas(),
                                       build.stored_coefficient_table())) {}

DeviceValidator::~DeviceValidator() = default;

std::string DeviceValidator::device_name() const {
  return device_->context.device_name();
}

std::vector<std::string> DeviceValidator::layer_messages() const {
  return device_->context.validation_messages();
}

CheckResult DeviceValidator::run(const DeviceCheck& check) const {
  CheckResult result{check.subject(), {}};
  const std::vector<float> queries = check.packed_queries();
  for (const ShaderLanguage language : {ShaderLanguage::glsl, ShaderLanguage::hlsl}) {
    const std::vector<float> results =
        device_->run(check.kernel(language), queries, check.query_count(),
                     check.result_vec4s_per_query(), check.tables());
    result.paths.push_back({language, check.compare(results)});
  }
  return result;
}

CheckResult DeviceValidator::validate(const CompiledMaterial& compiled) const {
  return run(*material_check(build_, compiled, tolerance_));
}

std::vector<std::unique_ptr<DeviceCheck>> DeviceValidator::shared_file_checks() const {
  return matc::shared_file_checks(build_, tolerance_);
}

}  // namespace matc
