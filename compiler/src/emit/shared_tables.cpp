#include "emit/shared_tables.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "base/content_hash.h"
#include "base/json_format.h"
#include "ltc/ltc_table_files.h"
#include "lut/coefficient_table_files.h"
#include "lut/default_lut_hashes.h"
#include "lut/preintegrate.h"
#include "matc/runtime/ltc.h"

namespace matc {

SharedTables::SharedTables(const SharedTableOptions& options)
    : options_(options),
      stored_coefficient_table_(matc::stored_coefficient_table(
          options.layers.front(), options.coefficient_table_precision)),
      coefficient_table_file_bytes_(encode_coefficient_table(
          stored_coefficient_table_, options.format, options.coefficient_table_precision)),
      ltc_file_bytes_(encode_ltc_table(runtime::shipped_ltc_table(), options.format)) {
  if (options_.embedded_lut_size != 0) {
    // Every layer's copy over one set of GGX samples, as the full-size table is baked.
    for (BakedLut& layer :
         bake_luts(options_.layers, {options_.embedded_lut_size, options_.lut.samples}))
      embedded_luts_.push_back(std::move(layer.lut));
  }
}

const SharedTables::Baked& SharedTables::baked() const {
  std::call_once(lazy_->once, [this] {
    Baked baked;
    baked.layers = bake_luts(options_.layers, options_.lut);
    for (const BakedLut& layer : baked.layers)
      baked.stored.push_back(stored_as(layer.lut, options_.lut_precision));
    baked.atlas = side_by_side(baked.stored);
    baked.file_bytes =
        options_.layers.size() == 1
            ? encode_lut(baked.layers.front(), options_.format, options_.lut_precision)
            : encode_layered_lut(baked.layers, baked.atlas, options_.format,
                                 options_.lut_precision);
    baked.hash = hash_of_bytes(baked.file_bytes);  // once: headers and the manifest name it
    lazy_->baked = std::move(baked);
  });
  return *lazy_->baked;
}

std::size_t SharedTables::layer_of(runtime::BasisKind basis) const {
  const auto layer = std::find(options_.layers.begin(), options_.layers.end(), basis);
  if (layer == options_.layers.end()) {
    throw std::invalid_argument(
        fmt::format("this build's table holds no layer of the {} basis", basis_name(basis)));
  }
  return static_cast<std::size_t>(layer - options_.layers.begin());
}

const Lut& SharedTables::stored_lut(runtime::BasisKind basis) const {
  return baked().stored[layer_of(basis)];
}

const Lut* SharedTables::embedded_lut(runtime::BasisKind basis) const {
  return embedded_luts_.empty() ? nullptr : &embedded_luts_[layer_of(basis)];
}

LutReference SharedTables::lut_reference() const {
  const bool layered = options_.layers.size() > 1;
  const auto known = default_lut_hash(options_.layers.front(), options_.format,
                                      options_.lut_precision, options_.lut, layered);
  return {shared_file_name(OutputKind::lut, options_.format), options_.lut.size,
          known ? std::string(*known) : baked().hash,
          layered ? std::string("auto") : std::string(runtime::basis_name(options_.layers.front())),
          options_.lut_precision};
}

std::vector<OutputFile> SharedTables::files(const std::set<OutputKind>& emit) const {
  std::vector<OutputFile> files;
  const auto add = [&](OutputKind kind, std::string bytes, std::string manifest) {
    const std::string name = shared_file_name(kind, options_.format);
    files.push_back({name, std::move(bytes)});
    files.push_back({name + ".json", std::move(manifest)});
  };
  if (emit.contains(OutputKind::lut) && options_.layers.size() > 1) {
    add(OutputKind::lut, baked().file_bytes,
        format_json(layered_lut_manifest(baked().layers, baked().atlas, options_.format,
                                         options_.lut_precision)));
  } else if (emit.contains(OutputKind::lut)) {
    add(OutputKind::lut, baked().file_bytes,
        format_json(lut_manifest(lut(), options_.format, options_.lut_precision)));
  }
  if (emit.contains(OutputKind::coefficient_table)) {
    add(OutputKind::coefficient_table, coefficient_table_file_bytes_,
        format_json(coefficient_table_manifest(stored_coefficient_table_, options_.format,
                                               options_.coefficient_table_precision)));
  }
  if (emit.contains(OutputKind::ltc)) {
    add(OutputKind::ltc, ltc_file_bytes_,
        format_json(ltc_table_manifest(runtime::shipped_ltc_table(), options_.format)));
  }
  return files;
}

void SharedTables::describe(nlohmann::ordered_json& description) const {
  const LutReference reference = lut_reference();
  description["lut"] = {{"file", reference.file},
                        {"size", options_.lut.size},
                        {"samples_per_texel", options_.lut.samples},
                        {"precision", lut_precision_name(options_.lut_precision)},
                        {"hash", reference.hash},
                        {"embedded_size", options_.embedded_lut_size}};
  description["coefficient_table"] = {
      {"file", shared_file_name(OutputKind::coefficient_table, options_.format)},
      {"size", stored_coefficient_table_.size()},
      {"precision", lut_precision_name(options_.coefficient_table_precision)},
      {"hash", hash_of_bytes(coefficient_table_file_bytes_)}};
  description["ltc_table"] = {{"file", shared_file_name(OutputKind::ltc, options_.format)},
                              {"size", runtime::shipped_ltc_table().size},
                              {"precision", "f32"},
                              {"hash", hash_of_bytes(ltc_file_bytes_)}};
}

}  // namespace matc
