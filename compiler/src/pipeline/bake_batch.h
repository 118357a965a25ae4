// The batch bake: what `matc bake -o DIR ASSETS...` does. Every asset is read and its name and
// outputs checked first (names unique within the batch, no output overwriting an input); then
// each is baked in turn on all threads, and all its bytes exist before its first file is written.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "bake/bake_asset.h"
#include "bake/baked_texture_files.h"
#include "bake/coefficient_textures.h"
#include "pipeline/batch.h"
#include "pipeline/output_sink.h"

namespace matc {

// One asset of a batch: an asset file to read, or an asset described in memory (with what was
// found wrong in its description, reported at its place in the batch).
struct BakeSource {
  std::string label;  // the asset file; for an asset in memory, what name-clash errors call it
  std::optional<BakeAssetResult> described;  // empty: read the file `label`

  static BakeSource file(std::string path) { return {std::move(path), std::nullopt}; }
  static BakeSource in_memory(BakeAssetResult asset, std::string label) {
    return {std::move(label), std::move(asset)};
  }
};

struct BakeBatchOptions {
  BakeOptions bake;  // its threads: the per-texel solve's
  BakeFileOptions files;
  bool keep_going = false;  // bake the others after one fails
  // Make-syntax dependencies of every output (DirectoryOutput only); empty: none.
  std::filesystem::path depfile;
  std::vector<std::filesystem::path> extra_dependencies;  // after the assets and maps
  std::stop_token cancel;  // once requested, no new asset starts and no depfile is written
};

struct BakeBatchResult {
  BatchCounts counts;
  bool cancelled = false;
};

// Throws std::invalid_argument for a depfile with an output that is not a directory.
BakeBatchResult bake_batch(std::span<const BakeSource> sources, OutputSink& output,
                           const BakeBatchOptions& options = {}, const BatchEvents& events = {});

}  // namespace matc
