#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>

#include <fmt/core.h>
#include <fmt/format.h>

#include "atomic_file.h"
#include "batch_report.h"
#include "color_options.h"
#include "commands.h"
#include "device_validation_report.h"
#include "emit_option.h"
#include "file_list.h"
#include "in_order.h"
#include "lut_options.h"
#include "matc/compile.h"
#include "matc/emit/build.h"
#include "matc/emit/manifest_writer.h"
#include "matc/json_format.h"
#include "matc/material/materialx_import.h"
#include "matc/material/parse.h"
#include "material_inputs.h"
#include "print_diagnostics.h"
#include "progress_line.h"
#include "unique_names.h"

namespace matc::cli {
namespace {

struct CompileOptions {
  std::vector<std::string> files;
  std::string files_from;  // --files-from: a file listing more, one per line
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

inline constexpr const char* kDepfileName = "matc.d";

namespace fs = std::filesystem;

// Stems of the files every build writes once (the output layout's): a material of that name, in
// any case, would overwrite them.
const std::set<std::string>& reserved_names() {
  static const std::set<std::string> names = [] {
    const std::vector<std::string> stems = shared_file_stems();
    return std::set<std::string>(stems.begin(), stems.end());
  }();
  return names;
}

// Every file a material of this name may write, whatever --emit says.
std::vector<fs::path> possible_outputs(const fs::path& directory, const std::string& name) {
  std::vector<fs::path> paths;
  for (const std::string& file : material_file_names(all_output_kinds(), name))
    paths.push_back(directory / file);
  return paths;
}

BuildOptions build_options(const CompileOptions& options) {
  BuildOptions build = table_build_options(options.lut, options.embed_lut, options.embed_lut_size);
  build.emit = emitted_kinds(options.emit);
  build.lut_format = *lut_format_from_name(options.lut_format);
  build.color = color_options_of(options.color);
  return build;
}

// What a worker's compile of one job leaves for the batch until the job is retired.
struct CompileOutcome {
  bool compiled = false;  // every output written
  bool failed_on_device = false;
  std::size_t written = 0;
  std::size_t unchanged = 0;
  std::string manifest_entry;  // ManifestWriter::format_entry's text, when a manifest is written
};

// One material (or one input file's diagnostics) through the batch: parsed and checked in order,
// then compiled by any worker. A batch of any size keeps little per job after its retirement.
struct Job {
  std::size_t input = 0;  // index in CompileOptions::files
  // Checked and admitted to the batch. A JSON material is parsed again by the worker that
  // compiles it, so that a batch holds no parsed materials; a MaterialX document's materials are
  // kept (re-importing a document per material would cost more).
  bool admitted = false;
  std::unique_ptr<Material> material;
  Diagnostics diagnostics;
  std::unique_ptr<CompileOutcome> outcome;  // from the worker, released on retirement
  // For the depfile:
  std::string spectral_file;               // a spectral file the material names
  std::vector<std::string> written_files;  // names in the output directory, kept for a depfile
};

// Reads and checks every file in order: name rules need all names, and a batch without
// --keep-going compiles nothing when an input is invalid.
std::vector<Job> parse_jobs(const CompileOptions& options, const fs::path& output_directory) {
  InputsInOutputDirectory inputs(output_directory);
  for (const std::string& file : options.files)
    inputs.add(file, file);
  UniqueNames names;
  // Name rules, then the job: a material with an error is kept for its diagnostics only.
  const auto admit = [&](Job& job, std::optional<Material> material, bool keep) {
    if (!material) return;
    const std::optional<std::string> overwritten =
        inputs.overwrite_problem(possible_outputs(output_directory, material->name));
    if (reserved_names().contains(material_name_key(material->name))) {
      job.diagnostics.error(material->name_location, "name",
                            fmt::format("'{}' names a file every build writes", material->name),
                            fmt::format("a name other than {} (ignoring case)",
                                        fmt::join(shared_file_stems(), ", ")));
    } else if (!names.claim(*material, "a build", job.diagnostics)) {
      // claim() reported the clash.
    } else if (overwritten) {
      job.diagnostics.error(material->name_location, "name", *overwritten, kOutputDirectoryRule);
    }
    if (job.diagnostics.has_errors()) return;
    if (const auto* spectral = std::get_if<SpectralInput>(&material->model))
      job.spectral_file = spectral->resolved_file;
    job.admitted = true;
    if (keep) job.material = std::make_unique<Material>(std::move(*material));
  };
  std::vector<Job> jobs;
  jobs.reserve(options.files.size());
  for (std::size_t input = 0; input < options.files.size(); ++input) {
    const std::string& file = options.files[input];
    // One job per material; the file's own diagnostics go with the first. A material file's
    // material is read again when it is compiled (a batch of 100,000 keeps none in memory); a
    // document's are kept.
    MaterialInput read = read_material_input(file);
    Job first;
    first.input = input;
    first.diagnostics = std::move(read.diagnostics);
    if (read.materials.empty()) {
      jobs.push_back(std::move(first));
      continue;
    }
    const bool keep = is_materialx_path(file);
    for (std::size_t i = 0; i < read.materials.size(); ++i) {
      Job job = i == 0 ? std::move(first) : Job{};
      job.input = input;
      admit(job, std::move(read.materials[i]), keep);
      jobs.push_back(std::move(job));
    }
  }
  return jobs;
}

int run_compile(const CompileOptions& options) {
  const Build build(build_options(options));
  std::unique_ptr<DeviceValidator> validator;
  if (options.validate) {
    validator = open_device_validator(build, options.device);
    if (!validator) return kExitNoDevice;
    std::vector<std::string> failed_checks;
    if (!validate_shared_files_and_report(*validator, &failed_checks)) {
      fmt::print(stderr,
                 "matc: error: {} differ from the CPU runtime on the Vulkan device (lines "
                 "above); nothing written\n",
                 fmt::join(failed_checks, " and "));
      return kExitValidationFailed;
    }
  }
  const runtime::BasisView basis = build.basis();
  // The manifest lists every file of a batch, so only a batch (not a split layout) writes it.
  const bool writes_manifest =
      !options.no_shared && !options.shared_only && build.options().emit.contains(OutputKind::json);
  const fs::path output_directory(options.output_directory);
  std::vector<Job> jobs = parse_jobs(options, output_directory);
  const bool inputs_valid =
      std::all_of(jobs.begin(), jobs.end(), [](const Job& job) { return job.admitted; });

  // Workers take the next valid job; without --keep-going the first failure stops new ones, and
  // an invalid input stops all.
  const auto queued = [&](const Job& job) {
    return job.admitted && (inputs_valid || options.keep_going);
  };
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (queued(jobs[i])) queue.push_back(i);
  const fs::path depfile =
      depfile_path(options.depfile, options.write_depfile, output_directory, kDepfileName);
  ProgressLine progress(queue.size(), !options.quiet && stderr_is_terminal());

  // Each job is reported, counted and released in input order as soon as every earlier job is
  // done, so a batch holds little more per material than its file name.
  std::mutex device_mutex;  // one Vulkan queue: validations (and their report) one at a time
  BatchCounts summary;
  std::size_t failed_on_device = 0;
  ManifestWriter manifest(output_directory);
  std::optional<std::string> manifest_error;
  InOrder in_order(jobs.size(), [&](std::size_t index) {
    Job& job = jobs[index];
    if (!job.diagnostics.items().empty()) {
      // Not between the lines of a device validation's report.
      std::unique_lock<std::mutex> report;
      if (validator) report = std::unique_lock(device_mutex);
      progress.print_above([&] { print_diagnostics(job.diagnostics); });
    }
    const std::unique_ptr<CompileOutcome> outcome = std::move(job.outcome);
    if (outcome) {
      summary.written += outcome->written;
      summary.unchanged += outcome->unchanged;
      if (outcome->failed_on_device) ++failed_on_device;
    }
    if (job.diagnostics.has_errors()) {
      ++summary.failed;
    } else if (outcome && outcome->compiled) {
      ++summary.done;
      if (writes_manifest && !manifest_error) {
        try {
          manifest.append(outcome->manifest_entry);
        } catch (const std::exception& error) {
          manifest_error = error.what();
        }
      }
    } else {
      ++summary.not_attempted;
    }
    job.diagnostics = Diagnostics();
  });
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (!queued(jobs[i])) in_order.done(i);  // not compiled: only its diagnostics to report

  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  const auto work = [&] {
    for (std::size_t slot = next++; slot < queue.size() && !stop; slot = next++) {
      Job& job = jobs[queue[slot]];
      const std::string& file = options.files[job.input];
      job.outcome = std::make_unique<CompileOutcome>();
      CompileOutcome& outcome = *job.outcome;
      std::string name;
      try {
        // Every byte is generated before the first file is written: a failure leaves no
        // partial set of outputs for this material.
        std::unique_ptr<Material> material = std::move(job.material);
        if (!material) {
          ParseResult again = read_material_file(file);
          if (!again.material) throw std::runtime_error("the file changed while matc ran");
          material = std::make_unique<Material>(std::move(*again.material));
        }
        name = material->name;
        const CompiledMaterial compiled = compile_material(*material, basis, build.options().color);
        warn_if_poor_fit(compiled, job.diagnostics);
        note_if_out_of_unit_range(compiled, job.diagnostics);
        MaterialOutputs outputs = build.material_outputs(compiled);
        bool valid_on_device = true;
        if (validator) {
          const std::lock_guard lock(device_mutex);
          valid_on_device = validate_and_report(*validator, compiled);
        }
        if (!valid_on_device) {
          outcome.failed_on_device = true;
          job.diagnostics.error({file, 0, 0}, "",
                                "its shaders differ from the CPU runtime on the Vulkan device "
                                "(lines above); nothing written for it");
        } else {
          fs::create_directories(output_directory);
          for (const OutputFile& output : outputs.files) {
            const WriteOutcome written =
                write_file_atomically(output_directory / output.name, output.bytes);
            ++(written == WriteOutcome::written ? outcome.written : outcome.unchanged);
          }
          outcome.compiled = true;
          if (writes_manifest) outcome.manifest_entry = ManifestWriter::format_entry(outputs);
          if (!depfile.empty()) {
            for (const OutputFile& output : outputs.files)
              job.written_files.push_back(output.name);
          }
        }
      } catch (const std::exception& error) {
        job.diagnostics.error({file, 0, 0}, "", error.what(), "a writable output directory (-o)");
      }
      if (job.diagnostics.has_errors() && !options.keep_going) stop = true;
      progress.finished(name);
      in_order.done(queue[slot]);
    }
  };
  std::vector<std::thread> workers;
  const unsigned threads = worker_count(options.jobs, queue.size());
  for (unsigned t = 1; t < threads; ++t)
    workers.emplace_back(work);
  work();
  for (std::thread& worker : workers)
    worker.join();
  progress.clear();
  in_order.finish();  // the jobs a failure left unattempted
  if (manifest_error) {
    fmt::print(stderr, "{}: error: {}\n", output_directory.string(), *manifest_error);
    ++summary.failed;
  }

  if (summary.failed == 0 || options.keep_going) {
    try {
      fs::create_directories(output_directory);
      std::vector<fs::path> targets;
      std::vector<OutputFile> shared;
      if (!options.no_shared) shared = build.shared_outputs();
      for (const OutputFile& output : shared) {
        summary.count(write_file_atomically(output_directory / output.name, output.bytes));
        targets.push_back(output_directory / output.name);
      }
      if (writes_manifest && !manifest_error) {
        const fs::path manifest_path = output_directory / manifest_file_name();
        summary.count(write_file_atomically(
            manifest_path, [&](std::ostream& out) { manifest.write(out, build, shared); }));
        targets.push_back(manifest_path);
      }
      if (!depfile.empty() && summary.failed == 0) {
        std::vector<fs::path> dependencies;
        for (const Job& job : jobs) {
          for (const std::string& name : job.written_files)
            targets.push_back(output_directory / name);
          dependencies.push_back(options.files[job.input]);
          if (!job.spectral_file.empty()) dependencies.push_back(job.spectral_file);
        }
        if (!write_depfile(depfile, targets, std::move(dependencies))) ++summary.failed;
      }
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}: error: {}\n", output_directory.string(), error.what());
      ++summary.failed;
    }
  }

  print_batch_summary({"matc", "compiled"}, summary, options.quiet);
  if (failed_on_device > 0) return kExitValidationFailed;
  return summary.failed > 0 ? kExitInputError : kExitSuccess;
}

// The command line's checks that need every file: then the batch.
int run_compile_command(CompileOptions options) {
  if (!options.files_from.empty()) {
    const std::optional<std::vector<std::string>> listed = read_file_list(options.files_from);
    if (!listed) {
      fmt::print(stderr, "{}: error: --files-from: cannot read the list\n", options.files_from);
      return kExitUsageError;
    }
    options.files.insert(options.files.end(), listed->begin(), listed->end());
  }
  if (options.shared_only && !options.files.empty()) {
    fmt::print(stderr,
               "matc: error: --shared-only writes no material's files; give no material file "
               "(compile materials with --no-shared in their own runs)\n");
    return kExitUsageError;
  }
  if (options.files.empty() && !options.shared_only) {
    fmt::print(stderr,
               "matc: error: no material files given; usage: matc [-o DIR] FILES... "
               "(see matc --help)\n");
    return kExitUsageError;
  }
  return run_compile(options);
}

}  // namespace

Command register_compile(CLI::App& app) {
  auto options = std::make_shared<CompileOptions>();
  app.add_option("files", options->files,
                 "Material files (.json) and MaterialX documents (.mtlx) to compile");
  app.add_option("--files-from", options->files_from,
                 "Also compile the files listed in FILE, one path per line (- for standard input): "
                 "for lists longer than a command line holds");
  app.add_option("-o,--output", options->output_directory, "Output directory (created if missing)")
      ->capture_default_str();
  add_keep_going_and_quiet(app, options->keep_going, options->quiet,
                           "Compile the remaining files after one fails",
                           "progress and summary lines");
  app.add_option("-j,--jobs", options->jobs,
                 "Materials compiled at once (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  add_depfile_options(app, options->depfile, options->write_depfile,
                      "inputs, spectral files, the matc binary", kDepfileName);
  add_emit_option(app, options->emit,
                  "Outputs to write, comma-separated (default: all): shader snippets, SPIR-V, "
                  "C headers, JSON manifests, the LUT, the coefficient table of textured metals, "
                  "the LTC table of area lights");
  CLI::Option* no_shared_option = app.add_flag(
      "--no-shared", options->no_shared,
      "Write only each material's own files (<name>.*), not the shared library, tables and "
      "manifest: one build action per material (docs/scaling.md)");
  app.add_flag("--shared-only", options->shared_only,
               "Write only the shared files (matc_fresnel.*, the tables), from no material file: "
               "the one shared action beside per-material --no-shared actions")
      ->excludes(no_shared_option);
  app.add_option(
         "--lut", options->lut_format,
         "File format of the tables DIR/matc_lut.<ext>, DIR/matc_coefficient_table.<ext> and "
         "DIR/matc_ltc.<ext>")
      ->capture_default_str()
      ->check(CLI::IsMember(matc::lut_format_names()));
  app.add_flag("--embed-lut", options->embed_lut,
               "Also embed a small table in matc_fresnel.glsl/.hlsl as a constant array");
  app.add_option("--embed-lut-size", options->embed_lut_size, "Width and height of that table")
      ->capture_default_str()
      ->check(CLI::Range(matc::kMinLutSize, matc::kMaxEmbeddedLutSize));
  add_lut_options(app, options->lut, "lut-");
  add_color_options(app, options->color);
  add_coefficient_table_option(app, options->lut);
  app.add_flag("--validate", options->validate,
               "Run each material's GLSL and HLSL shaders on a Vulkan device (lavapipe) against "
               "the CPU runtime before writing its files");
  add_device_options(app, options->device);
  return {&app, [options] { return run_compile_command(*options); }, true};
}

}  // namespace matc::cli
