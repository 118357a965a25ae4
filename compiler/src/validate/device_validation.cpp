#include "matc/validate/device_validation.h"

#include <algorithm>
#include <cmath>

#include "matc/emit/validation_kernel.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "matc/vulkan/compute_kernel.h"
#include "validator_device.h"

namespace matc {
namespace {

constexpr std::size_t kGridSteps = 40;  // 41 points per axis

void record(Discrepancy& discrepancy, const runtime::Rgb& expected, const float* actual,
            const ValidationQuery& query) {
  record_largest(discrepancy.max_abs, discrepancy.where, expected, actual, query);
}

}  // namespace

std::vector<ValidationQuery> validation_queries() {
  constexpr std::size_t kCount = (kGridSteps + 1) * (kGridSteps + 1);
  std::vector<ValidationQuery> queries;
  queries.reserve(kCount);
  for (std::size_t row = 0; row <= kGridSteps; ++row) {
    for (std::size_t column = 0; column <= kGridSteps; ++column) {
      const std::size_t index = queries.size();
      queries.push_back({static_cast<float>(static_cast<double>(index) / (kCount - 1)),
                         static_cast<float>(static_cast<double>(column) / kGridSteps),
                         static_cast<float>(static_cast<double>(row) / kGridSteps)});
    }
  }
  return queries;
}

bool MaterialValidation::passed() const {
  return !paths.empty() &&
         std::all_of(paths.begin(), paths.end(), [](const PathValidation& p) { return p.passed; });
}

DeviceValidator::DeviceValidator(const Build& build, const vulkan::ContextOptions& device,
                                 ValidationTolerance tolerance)
    : build_(build), tolerance_(tolerance), queries_(validation_queries()) {
  // Whole workgroups: the padding queries (zeros) are computed but not compared.
  const std::size_t padded =
      (queries_.size() + kWorkgroupSize - 1) / kWorkgroupSize * kWorkgroupSize;
  device_ = std::make_unique<Device>(device, build.stored_lut(), build.stored_coefficient_table(),
                                     padded);
  std::vector<float> packed(padded * 4, 0.0f);
  for (std::size_t i = 0; i < queries_.size(); ++i) {
    packed[4 * i] = queries_[i].mu;
    packed[4 * i + 1] = queries_[i].ndotv;
    packed[4 * i + 2] = queries_[i].roughness;
  }
  device_->queries.write<float>(packed);
}

DeviceValidator::~DeviceValidator() = default;

std::string DeviceValidator::device_name() const {
  return device_->context.device_name();
}

std::vector<std::string> DeviceValidator::layer_messages() const {
  return device_->context.validation_messages();
}

MaterialValidation DeviceValidator::validate(const CompiledMaterial& compiled) const {
  MaterialValidation validation{compiled.material.name, {}};
  for (const ShaderLanguage language : {ShaderLanguage::glsl, ShaderLanguage::hlsl})
    validation.paths.push_back(run(language, compiled));
  return validation;
}

PathValidation DeviceValidator::run(ShaderLanguage language,
                                    const CompiledMaterial& compiled) const {
  const SpirvWords module = build_.validation_module(language, compiled);
  const std::array bindings = {
      vulkan::Binding::storage_buffer(0, device_->queries),
      vulkan::Binding::storage_buffer(1, device_->results),
      vulkan::Binding::sampled_image(2, device_->lut),
      vulkan::Binding::separate_sampler(3, device_->sampler),
  };
  const vulkan::ComputeKernel kernel(device_->context, module, bindings);
  const auto groups =
      static_cast<std::uint32_t>(device_->queries.size() / (4 * sizeof(float) * kWorkgroupSize));
  kernel.dispatch(groups);
  const std::vector<float> results =
      device_->results.read<float>(queries_.size() * kValidationResultsPerQuery * 4);

  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(build_.options().basis);
  const runtime::LutView table = build_.stored_lut().view();
  const Lut* embedded = build_.embedded_lut();
  const runtime::AnalyticLutCoefficients& analytic =
      runtime::shipped_analytic_lut(build_.options().basis);
  PathValidation path;
  path.language = language;
  if (embedded) path.embedded = Discrepancy{};
  for (std::size_t i = 0; i < queries_.size(); ++i) {
    const ValidationQuery& query = queries_[i];
    const float* result = &results[i * kValidationResultsPerQuery * 4];
    record(path.fresnel, runtime::evaluate_fresnel(compiled.coefficients, shader_basis, query.mu),
           result, query);
    record(path.preintegrated,
           runtime::evaluate_fbar(compiled.coefficients, table, query.ndotv, query.roughness),
           result + 4, query);
    if (embedded) {
      record(*path.embedded,
             runtime::evaluate_fbar(compiled.coefficients, embedded->view(), query.ndotv,
                                    query.roughness),
             result + 8, query);
    }
    record(path.analytic,
           runtime::evaluate_fbar_analytic(compiled.coefficients, analytic, query.ndotv,
                                           query.roughness),
           result + 12, query);
  }
  path.passed = path.fresnel.max_abs <= tolerance_.fresnel &&
                path.preintegrated.max_abs <= tolerance_.preintegrated &&
                (!path.embedded || path.embedded->max_abs <= tolerance_.embedded) &&
                path.analytic.max_abs <= tolerance_.analytic;
  return path;
}

}  // namespace matc
