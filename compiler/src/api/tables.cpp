#include "matc/api/tables.h"

#include <map>
#include <mutex>
#include <tuple>

#include "checked_options.h"
#include "checked_values.h"
#include "fit/coefficient_table.h"
#include "lut/coefficient_table_files.h"
#include "lut/lut_files.h"
#include "lut/preintegrate.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/lut.h"

namespace matc::api {

static_assert(kDefaultLutSize == matc::kDefaultLutSize &&
              kDefaultLutSamples == matc::kDefaultLutSamples && kMinLutSize == matc::kMinLutSize &&
              kMaxLutSize == matc::kMaxLutSize && kMaxLutSamples == matc::kMaxLutSamples);

PreintegratedTable::PreintegratedTable(std::shared_ptr<const matc::Lut> lut, std::string basis,
                                       std::string precision)
    : lut_(std::move(lut)), basis_(std::move(basis)), precision_(std::move(precision)) {}

std::size_t PreintegratedTable::size() const {
  return lut_->size;
}
std::size_t PreintegratedTable::samples() const {
  return lut_->samples;
}
std::span<const float> PreintegratedTable::texels() const {
  return lut_->texels;
}

std::vector<double> PreintegratedTable::sample(std::span<const double> ndotv,
                                               std::span<const double> roughness) const {
  check_ndotv_roughness(ndotv, roughness);
  const runtime::LutView view = lut_->view();
  std::vector<double> values(runtime::kBasisSize * ndotv.size());
  for (std::size_t i = 0; i < ndotv.size(); ++i) {
    const auto bbar = runtime::sample_lut(view, ndotv[i], roughness[i]);
    for (std::size_t b = 0; b < runtime::kBasisSize; ++b)
      values[runtime::kBasisSize * i + b] = bbar[b];
  }
  return values;
}

PreintegratedTable preintegrated_table(const PreintegratedTableOptions& options) {
  const runtime::BasisKind basis = basis_of({options.basis, {}, {}});
  const std::size_t size = checked_count("size", options.size, kMinLutSize, kMaxLutSize);
  const std::size_t samples = checked_count("samples", options.samples, 1, kMaxLutSamples);
  const LutPrecision precision = checked_option_value<LutPrecision>("precision", options.precision);
  using Key = std::tuple<runtime::BasisKind, std::size_t, std::size_t, LutPrecision>;
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const matc::Lut>> tables;
  const std::lock_guard lock(mutex);
  std::shared_ptr<const matc::Lut>& table = tables[{basis, size, samples, precision}];
  if (!table) {
    LutOptions lut;
    lut.size = size;
    lut.samples = samples;
    table = std::make_shared<const matc::Lut>(
        stored_as(preintegrate_lut(runtime::shipped_basis(basis), lut), precision));
  }
  return {table, std::string(runtime::basis_name(basis)),
          std::string(lut_precision_name(precision))};
}

std::vector<OutputFile> lut_files(const PreintegratedTableOptions& options, std::string_view format,
                                  std::string_view file_name) {
  const runtime::BasisKind basis = basis_of({options.basis, {}, {}});
  LutOptions lut;
  lut.size = checked_count("size", options.size, kMinLutSize, kMaxLutSize);
  lut.samples = checked_count("samples", options.samples, 1, kMaxLutSamples);
  const LutPrecision precision = checked_option_value<LutPrecision>("precision", options.precision);
  const LutFormat chosen = checked_option_value<LutFormat>("format", format);
  const BakedLut baked = bake_lut(runtime::shipped_basis(basis), lut);
  std::vector<OutputFile> files;
  for (matc::OutputFile& file : lut_output_files(baked, chosen, precision, file_name))
    files.push_back({std::move(file.name), std::move(file.bytes)});
  return files;
}

std::optional<std::string> lut_format_of_extension(std::string_view extension) {
  const std::optional<LutFormat> format = lut_format_from_extension(extension);
  if (!format) return std::nullopt;
  return std::string(lut_format_name(*format));
}

CoefficientTable::CoefficientTable(std::shared_ptr<const matc::CoefficientTable> table,
                                   std::string precision)
    : table_(std::move(table)),
      basis_(runtime::basis_name(table_->basis)),
      precision_(std::move(precision)) {}

std::size_t CoefficientTable::size() const {
  return table_->size();
}
std::span<const float> CoefficientTable::texels() const {
  return table_->texels;
}

CoefficientRows CoefficientTable::coefficients(const Rgb& reflectivity,
                                               const Rgb& edge_tint) const {
  check_unit_interval("reflectivity", reflectivity);
  check_unit_interval("edge_tint", edge_tint);
  return runtime::coefficients_from_table(table_->view(), reflectivity, edge_tint);
}

CoefficientTable coefficient_table(std::string_view basis, std::string_view precision) {
  const runtime::BasisKind kind = basis_of({std::string(basis), {}, {}});
  const LutPrecision stored = checked_option_value<LutPrecision>("precision", precision);
  return {std::make_shared<const matc::CoefficientTable>(stored_coefficient_table(kind, stored)),
          std::string(lut_precision_name(stored))};
}

}  // namespace matc::api
