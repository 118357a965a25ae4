// The files `matc bake` writes for one asset (docs/baking.md): NAME_c2 and NAME_c3 (RGBA float
// textures with full mip chains, KTX2 or DDS), NAME_f0 (linear F0 with the same mips) and
// NAME_error.png (level 0's error, for artists) when the bake computed them (BakeOptions::f0,
// ::error_map), and NAME_bake.json (what was baked, from which inputs, with content hashes).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "bake/bake_asset.h"
#include "bake/coefficient_textures.h"
#include "base/output_file.h"
#include "lut/lut_files.h"

namespace matc {

struct BakeFileOptions {
  LutFormat format = LutFormat::ktx2;  // ktx2 or dds
  LutPrecision precision = LutPrecision::f16;
};

// The error map's scale: a texel of 255 has an error of this or more (linear in between).
inline constexpr double kErrorMapFullScale = 0.01;

// Every file name an asset of this name may write, whatever the options.
std::vector<std::string> possible_bake_outputs(std::string_view name);

// All files, bytes generated in memory (nothing is written here). `asset` and `inputs` give the
// manifest its inputs and their hashes.
std::vector<OutputFile> baked_texture_files(const BakeAsset& asset, const BakeInputs& inputs,
                                            const BakedCoefficients& baked,
                                            const BakeFileOptions& options);

}  // namespace matc
