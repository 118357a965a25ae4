// The tables every build writes once beside its shaders: the preintegrated table (baked on first
// use: a run that writes nothing naming it never pays for the bake), an embedded copy for
// --embed-lut, the coefficient table of textured metals and the LTC table of area lights, each as
// its file stores it, with the files and the manifest entries that describe them.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/output_file.h"
#include "emit/c_header.h"
#include "emit/output_layout.h"
#include "fit/coefficient_table.h"
#include "lut/lut_files.h"
#include "matc/runtime/basis.h"

namespace matc {

// What decides the tables' bytes (a build's options, less those of the shaders).
struct SharedTableOptions {
  // The preintegrated table's bases: one, or a layer each side by side (--basis auto). The
  // coefficient table is the first's; the embedded table has a copy of each layer.
  std::vector<runtime::BasisKind> layers = {runtime::kDefaultBasis};
  LutOptions lut;
  LutFormat format = LutFormat::ktx2;
  LutPrecision lut_precision = LutPrecision::f32;
  LutPrecision coefficient_table_precision = LutPrecision::f16;
  std::size_t embedded_lut_size = 0;  // 0: none
};

class SharedTables {
 public:
  explicit SharedTables(const SharedTableOptions& options);

  // The first layer's table.
  const BakedLut& lut() const { return baked().layers.front(); }
  // The table as the written file stores it (f16 rounding), what a renderer samples: the first
  // layer's, or `basis`' layer (one the table holds).
  const Lut& stored_lut() const { return baked().stored.front(); }
  const Lut& stored_lut(runtime::BasisKind basis) const;
  // Every layer side by side as stored: the texture the file holds.
  const LutAtlas& stored_atlas() const { return baked().atlas; }
  const std::vector<runtime::BasisKind>& layers() const { return options_.layers; }
  // Where `basis` is among them (std::invalid_argument if the table holds none of it).
  std::size_t layer_of(runtime::BasisKind basis) const;
  // --embed-lut's tables, one per layer (empty without it), and `basis`' of them (null without).
  std::span<const Lut> embedded_luts() const { return embedded_luts_; }
  const Lut* embedded_lut(runtime::BasisKind basis) const;
  const CoefficientTable& stored_coefficient_table() const { return stored_coefficient_table_; }
  // The preintegrated table's file name and hash, as headers and the manifest name it (the
  // default table's hash is checked in: naming it needs no bake).
  LutReference lut_reference() const;

  // The files of the table kinds in `emit` (each table and its .json), in the layout's order.
  std::vector<OutputFile> files(const std::set<OutputKind>& emit) const;
  // The manifest's "lut", "coefficient_table" and "ltc_table" members.
  void describe(nlohmann::ordered_json& description) const;

 private:
  struct Baked {
    std::vector<BakedLut> layers;
    std::vector<Lut> stored;
    LutAtlas atlas;
    std::string file_bytes;
    std::string hash;
  };
  struct LazyBake {
    std::once_flag once;
    std::optional<Baked> baked;
  };
  const Baked& baked() const;

  SharedTableOptions options_;
  std::vector<Lut> embedded_luts_;
  std::shared_ptr<LazyBake> lazy_ = std::make_shared<LazyBake>();
  CoefficientTable stored_coefficient_table_;
  std::string coefficient_table_file_bytes_;
  std::string ltc_file_bytes_;
};

}  // namespace matc
