// The matc sub-commands. Each returns the process exit code (see kExit* below).
#pragma once

#include <string>
#include <vector>

#include "channel_list.h"  // split_list
#include "color_options.h"
#include "lut_options.h"

namespace matc::cli {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitInputError = 1;  // a material or data file is invalid
inline constexpr int kExitUsageError = 2;  // the command line is invalid
inline constexpr int kExitInternalError = 3;
inline constexpr int kExitValidationFailed = 4;  // device results differ from the CPU runtime's
inline constexpr int kExitNoDevice = 5;          // no usable Vulkan driver or device

// Where `matc validate` and `matc --validate` run the generated shaders.
struct DeviceCliOptions {
  bool layers = false;  // --vk-validation: Khronos validation layer on, any message fails
  std::string name;     // --device: a substring of the device's name
};

struct CompileOptions {
  std::vector<std::string> files;
  std::string output_directory = "matc-out";
  bool keep_going = false;
  bool quiet = false;
  unsigned jobs = 0;           // -j: materials compiled at once; 0: one per hardware thread
  std::string depfile;         // --depfile FILE: Make-syntax dependencies of every output
  bool write_depfile = false;  // -MD: the same, as <output directory>/matc.d
  std::string emit;            // comma-separated output kinds; empty: all
  bool no_shared = false;      // --no-shared: only each material's own files
  bool shared_only = false;    // --shared-only: only the shared files (no material given)
  std::string lut_format = "ktx2";
  LutCliOptions lut;
  bool embed_lut = false;
  std::size_t embed_lut_size = 32;
  bool validate = false;  // run each material's shaders on a device before writing its files
  DeviceCliOptions device;
  ColorCliOptions color;
};
int run_compile(const CompileOptions& options);

inline constexpr const char* kDepfileName = "matc.d";

struct ValidateOptions {
  std::vector<std::string> files;
  LutCliOptions lut;
  bool embed_lut = false;
  std::size_t embed_lut_size = 32;
  DeviceCliOptions device;
  ColorCliOptions color;
};
int run_validate(const ValidateOptions& options);

struct EvalOptions {
  std::string file;          // a material file or MaterialX document, or:
  std::string material;      // --material: which of a document's materials
  std::string reflectivity;  // --reflectivity and --edge-tint: the coefficient-table path
  std::string edge_tint;
  std::vector<double> mu;
  std::vector<double> ndotv;
  std::vector<double> roughness;
  std::string quad_light;  // "x,y,z;x,y,z;x,y,z;x,y,z" in the shading frame: area-light radiance
  std::size_t light_samples = 0;  // reference samples for --quad-light
  bool no_reference = false;      // --no-reference: no split-sum integral per (NdotV, roughness)
  LutCliOptions lut;
  ColorCliOptions color;
};
int run_eval(const EvalOptions& options);

struct BasisOptions {
  bool json = false;
  std::string basis{runtime::basis_name(runtime::kDefaultBasis)};
};
int run_basis(const BasisOptions& options);

struct BasisFitOptions {
  std::string output;  // empty: standard output
  std::string basis{runtime::basis_name(runtime::kDefaultBasis)};
};
int run_basis_fit(const BasisFitOptions& options);
int run_basis_lut_hashes(const BasisFitOptions& options);
int run_basis_analytic_lut(const BasisFitOptions& options);
int run_basis_material_modules(const BasisFitOptions& options);

// `matc basis coefficient-table`: refits the shipped coefficient table and writes its C++ source.
int run_basis_coefficient_table(const BasisFitOptions& options);

// `matc basis ltc-table`: refits the shipped LTC table, writes its C++ source and, on request,
// each texel's fit quality as CSV.
struct LtcTableOptions {
  std::string output;
  std::string quality;
  std::size_t quality_samples = 1u << 14;
  unsigned jobs = 0;
  std::string objective = "l1";  // "l1" or "l3" (Heitz et al.'s)
};
int run_basis_ltc_table(const LtcTableOptions& options);

struct ReportOptions {
  std::vector<std::string> files;
  std::string output_directory = "matc-report";
  std::string basis{runtime::basis_name(runtime::kDefaultBasis)};
  ColorCliOptions color;
};
int run_report(const ReportOptions& options);

// `matc bake`: asset files, and/or one asset from the map options.
struct BakeCommandOptions {
  std::vector<std::string> files;  // asset JSON files
  std::string reflectivity;        // a map file or constant values, for a command-line asset
  std::string edge_tint;
  std::string n;
  std::string k;
  std::string name;     // its name (default: the first map file's stem)
  bool linear = false;  // its 8- and 16-bit map files hold linear values, not sRGB
  std::string output_directory = "matc-bake";
  std::string format = "ktx2";
  std::string precision = "f16";
  std::string basis{runtime::basis_name(runtime::kDefaultBasis)};
  bool f0 = false;
  bool error_map = false;
  bool keep_going = false;
  bool quiet = false;
  unsigned jobs = 0;  // threads; 0: one per hardware thread
  std::string depfile;
  bool write_depfile = false;
};
int run_bake(const BakeCommandOptions& options);

// `matc import`: MaterialX documents to matc material files.
struct ImportOptions {
  std::vector<std::string> files;
  std::string output_directory = "matc-import";
  bool keep_going = false;
  bool quiet = false;
};
int run_import(const ImportOptions& options);

struct LutCommandOptions {
  std::string output;
  std::string format;  // empty: from the output's extension
  LutCliOptions lut;
};
int run_lut(const LutCommandOptions& options);

}  // namespace matc::cli
