// The tables a renderer samples (docs/lut.md, docs/coefficient-table.md): the preintegrated
// table bbar_0..bbar_3 (NdotV, roughness) of a basis, and the coefficient table (c_2, c_3 of one
// channel over Gulbrandsen's r, g), as matc's files store them, sampled as a GPU sampler reads
// them. Native builds only.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "matc/api/compiled_material.h"
#include "matc/api/files.h"

namespace matc {
struct Lut;
struct CoefficientTable;
}  // namespace matc

namespace matc::api {

// The preintegrated table's limits and defaults (`matc --lut-size`, `--lut-samples`).
inline constexpr std::size_t kDefaultLutSize = 128;
inline constexpr std::size_t kDefaultLutSamples = 1024;
inline constexpr std::size_t kMinLutSize = 2;
inline constexpr std::size_t kMaxLutSize = 4096;
inline constexpr std::size_t kMaxLutSamples = std::size_t{1} << 20;

struct PreintegratedTableOptions {
  std::string basis;  // by --basis's names; empty: the default
  std::size_t size = kDefaultLutSize;
  std::size_t samples = kDefaultLutSamples;  // GGX samples per texel
  std::string precision = "f32";             // "f16": rounded as a half-float file stores it
};

// Immutable and cheap to copy (shared).
class PreintegratedTable {
 public:
  std::size_t size() const;
  std::size_t samples() const;
  const std::string& basis() const { return basis_; }
  const std::string& precision() const { return precision_; }
  // size * size * 4 floats: texel (x, y) holds bbar_0..bbar_3 at NdotV = (x / (size - 1))^2 and
  // perceptual roughness y / (size - 1), rows by roughness (docs/lut.md).
  std::span<const float> texels() const;
  // bbar_0..bbar_3 at pairs (NdotV, roughness), both in [0, 1] and of one length, bilinearly
  // filtered as a GPU sampler reads the table: 4 values per pair.
  std::vector<double> sample(std::span<const double> ndotv,
                             std::span<const double> roughness) const;

  // The library's own value, for the library's implementation.
  const matc::Lut& value() const { return *lut_; }
  PreintegratedTable(std::shared_ptr<const matc::Lut> lut, std::string basis,
                     std::string precision);

 private:
  std::shared_ptr<const matc::Lut> lut_;
  std::string basis_;
  std::string precision_;
};

// The table as `matc` writes it with these options, baked once per set of options and kept for
// the process (a batch of plots pays once). Throws std::invalid_argument naming an option out of
// range or outside its names.
PreintegratedTable preintegrated_table(const PreintegratedTableOptions& options = {});

// The table baked with `options` as `matc lut -o FILE` writes it: `file_name` in `format` ("ktx2",
// "dds", "raw" or "header") and its description `file_name`.json. Not kept: each call bakes.
std::vector<OutputFile> lut_files(const PreintegratedTableOptions& options, std::string_view format,
                                  std::string_view file_name);
// The format a file name's extension stands for (.ktx2, .dds, .bin, .h), if any.
std::optional<std::string> lut_format_of_extension(std::string_view extension);

// Immutable and cheap to copy (shared).
class CoefficientTable {
 public:
  std::size_t size() const;
  const std::string& basis() const { return basis_; }
  const std::string& precision() const { return precision_; }
  // size * size * 2 floats: (c_2, c_3) of one channel, rows by edge tint
  // (docs/coefficient-table.md).
  std::span<const float> texels() const;
  // c_0..c_3 per channel from the table, as the shaders' matc_coefficients_from_table computes
  // them; every reflectivity and edge tint in [0, 1] (std::invalid_argument otherwise).
  CoefficientRows coefficients(const Rgb& reflectivity, const Rgb& edge_tint) const;

  const matc::CoefficientTable& value() const { return *table_; }
  CoefficientTable(std::shared_ptr<const matc::CoefficientTable> table, std::string precision);

 private:
  std::shared_ptr<const matc::CoefficientTable> table_;
  std::string basis_;
  std::string precision_;
};

// The basis' coefficient table as matc_coefficient_table.* stores it ("f16" by default).
CoefficientTable coefficient_table(std::string_view basis = {}, std::string_view precision = "f16");

}  // namespace matc::api
