#include "pipeline/compile_batch.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "batch_reporter.h"
#include "emit/manifest_writer.h"
#include "in_order.h"
#include "material/document_import.h"
#include "material/material_input.h"
#include "material/parse.h"
#include "pipeline/inputs_in_output_directory.h"
#include "pipeline/unique_names.h"

namespace matc {
namespace {

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

// Every file a material of this name may write, whatever the build emits.
std::vector<fs::path> possible_outputs(const fs::path& directory, const std::string& name) {
  std::vector<fs::path> paths;
  for (const std::string& file : material_file_names(all_output_kinds(), name))
    paths.push_back(directory / file);
  return paths;
}

MaterialInput read_source(const MaterialSource& source) {
  return source.text ? parse_material_input(*source.text, source.path)
                     : read_material_input(source.path);
}

// What a worker's compile of one job leaves for the batch until the job is retired.
struct CompileOutcome {
  bool compiled = false;  // every output written
  bool failed_check = false;
  std::size_t written = 0;
  std::size_t unchanged = 0;
  std::string manifest_entry;  // ManifestWriter::format_entry's text, when a manifest is written
};

// One material (or one input's diagnostics) through the batch: parsed and checked in order, then
// compiled by any worker. A batch of any size keeps little per job after its retirement.
struct Job {
  std::size_t input = 0;  // index in the sources
  // Checked and admitted to the batch. A material file's material is parsed again by the worker
  // that compiles it, so that a batch holds no parsed materials; a MaterialX document's materials
  // are kept (re-importing a document per material would cost more).
  bool admitted = false;
  std::unique_ptr<Material> material;
  Diagnostics diagnostics;
  std::unique_ptr<CompileOutcome> outcome;  // from the worker, released on retirement
  // For the depfile:
  std::string spectral_file;               // a spectral file the material names
  std::vector<std::string> written_files;  // names in the output directory
};

// Reads and checks every source in order: name rules need all names, and a batch without
// keep_going compiles nothing when an input is invalid.
std::vector<Job> parse_jobs(std::span<const MaterialSource> sources, const fs::path* directory) {
  std::optional<InputsInOutputDirectory> inputs;
  if (directory) {
    inputs.emplace(*directory);
    for (const MaterialSource& source : sources)
      if (!source.text) inputs->add(source.path, source.path);
  }
  UniqueNames names;
  // Name rules, then the job: a material with an error is kept for its diagnostics only.
  const auto admit = [&](Job& job, Material material, bool keep) {
    const std::optional<std::string> overwritten =
        inputs ? inputs->overwrite_problem(possible_outputs(*directory, material.name))
               : std::nullopt;
    if (reserved_names().contains(material_name_key(material.name))) {
      job.diagnostics.error(material.name_location, "name",
                            fmt::format("'{}' names a file every build writes", material.name),
                            fmt::format("a name other than {} (ignoring case)",
                                        fmt::join(shared_file_stems(), ", ")));
    } else if (!names.claim(material, "a build", job.diagnostics)) {
      // claim() reported the clash.
    } else if (overwritten) {
      job.diagnostics.error(material.name_location, "name", *overwritten, kOutputDirectoryRule);
    }
    if (job.diagnostics.has_errors()) return;
    if (const auto* spectral = std::get_if<SpectralInput>(&material.model))
      job.spectral_file = spectral->resolved_file;
    job.admitted = true;
    if (keep) job.material = std::make_unique<Material>(std::move(material));
  };
  std::vector<Job> jobs;
  jobs.reserve(sources.size());
  for (std::size_t input = 0; input < sources.size(); ++input) {
    // One job per material; the input's own diagnostics go with the first.
    MaterialInput read = read_source(sources[input]);
    Job first;
    first.input = input;
    first.diagnostics = std::move(read.diagnostics);
    if (read.materials.empty()) {
      jobs.push_back(std::move(first));
      continue;
    }
    const bool keep = is_document_path(sources[input].path);
    for (std::size_t i = 0; i < read.materials.size(); ++i) {
      Job job = i == 0 ? std::move(first) : Job{};
      job.input = input;
      admit(job, std::move(read.materials[i]), keep);
      jobs.push_back(std::move(job));
    }
  }
  return jobs;
}

void check_options(std::span<const MaterialSource> sources, const OutputSink& output,
                   const CompileBatchOptions& options) {
  if (options.shared_only && !sources.empty())
    throw std::invalid_argument("compile_batch: shared_only with material sources");
  if (options.shared_only && options.no_shared)
    throw std::invalid_argument("compile_batch: shared_only with no_shared");
  if (!options.depfile.empty() && !output.directory())
    throw std::invalid_argument("compile_batch: a depfile needs an output directory");
}

}  // namespace

CompileBatchResult compile_batch(const Build& build, std::span<const MaterialSource> sources,
                                 OutputSink& output, const CompileBatchOptions& options,
                                 const BatchEvents& events) {
  check_options(sources, output, options);
  // The manifest lists every file of a batch, so only a batch (not a split layout) writes it.
  const bool writes_manifest =
      !options.no_shared && !options.shared_only && build.options().emit.contains(OutputKind::json);
  const fs::path* directory = output.directory();
  const fs::path output_label = output_name(output);
  std::vector<Job> jobs = parse_jobs(sources, directory);
  const bool inputs_valid =
      std::all_of(jobs.begin(), jobs.end(), [](const Job& job) { return job.admitted; });

  // Workers take the next valid job; without keep_going the first failure stops new ones, and an
  // invalid input stops all.
  const auto queued = [&](const Job& job) {
    return job.admitted && (inputs_valid || options.keep_going);
  };
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (queued(jobs[i])) queue.push_back(i);

  BatchReporter reporter(events);
  std::mutex check_mutex;  // checks one at a time, and never while diagnostics are reported
  CompileBatchResult result;
  BatchCounts& summary = result.counts;
  ManifestWriter manifest(directory ? *directory : fs::path());
  std::optional<std::string> manifest_error;
  // Each job is reported, counted and released in input order as soon as every earlier job is
  // done, so a batch holds little more per material than its file name.
  InOrder in_order(jobs.size(), [&](std::size_t index) {
    Job& job = jobs[index];
    if (!job.diagnostics.items().empty()) {
      std::unique_lock<std::mutex> no_check;
      if (options.check_material) no_check = std::unique_lock(check_mutex);
      reporter.diagnostics(job.diagnostics);
    }
    const std::unique_ptr<CompileOutcome> outcome = std::move(job.outcome);
    if (outcome) {
      summary.written += outcome->written;
      summary.unchanged += outcome->unchanged;
      if (outcome->failed_check) ++result.failed_checks;
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
  std::atomic<std::size_t> finished{0};
  std::atomic<bool> stop{false};
  const auto work = [&] {
    for (std::size_t slot = next++;
         slot < queue.size() && !stop && !options.cancel.stop_requested(); slot = next++) {
      Job& job = jobs[queue[slot]];
      const MaterialSource& source = sources[job.input];
      job.outcome = std::make_unique<CompileOutcome>();
      CompileOutcome& outcome = *job.outcome;
      std::string name;
      try {
        // Every byte is generated before the first file is written: a failure leaves no
        // partial set of outputs for this material.
        std::unique_ptr<Material> material = std::move(job.material);
        if (!material) {
          MaterialInput again = read_source(source);
          if (again.materials.size() != 1)
            throw std::runtime_error("the file changed while matc ran");
          material = std::make_unique<Material>(std::move(again.materials.front()));
        }
        name = material->name;
        const CompiledMaterial compiled =
            compile_material(*material, build.basis_for(*material), build.options().color);
        warn_if_poor_fit(compiled, job.diagnostics);
        note_if_out_of_unit_range(compiled, job.diagnostics);
        MaterialOutputs outputs = build.material_outputs(compiled);
        bool passed_check = true;
        if (options.check_material) {
          const std::lock_guard lock(check_mutex);
          passed_check = options.check_material(compiled);
        }
        if (!passed_check) {
          outcome.failed_check = true;
          job.diagnostics.error({source.path, 0, 0}, "",
                                "its shaders differ from the CPU runtime on the Vulkan device "
                                "(lines above); nothing written for it");
        } else {
          for (const WriteOutcome written : output.write_all(outputs.files))
            ++(written == WriteOutcome::written ? outcome.written : outcome.unchanged);
          outcome.compiled = true;
          if (writes_manifest) outcome.manifest_entry = ManifestWriter::format_entry(outputs);
          if (!options.depfile.empty()) {
            for (const OutputFile& file : outputs.files)
              job.written_files.push_back(file.name);
          }
        }
      } catch (const std::exception& error) {
        job.diagnostics.error({source.path, 0, 0}, "", error.what(),
                              "a writable output directory (-o)");
      }
      if (job.diagnostics.has_errors() && !options.keep_going) stop = true;
      reporter.progress({++finished, queue.size(), name});
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
  in_order.finish();  // the jobs a failure or a cancellation left unattempted
  result.cancelled = options.cancel.stop_requested();
  if (result.cancelled) return result;
  if (manifest_error) {
    reporter.error(output_label.string(), *manifest_error);
    ++summary.failed;
  }

  if (summary.failed == 0 || options.keep_going) {
    try {
      std::vector<fs::path> targets;
      std::vector<OutputFile> shared;
      if (!options.no_shared) shared = build.shared_outputs();
      for (const OutputFile& file : shared) {
        summary.count(output.write(file.name, file.bytes));
        targets.push_back(output_label / file.name);
      }
      if (writes_manifest && !manifest_error) {
        summary.count(output.write(std::string(manifest_file_name()),
                                   [&](std::ostream& out) { manifest.write(out, build, shared); }));
        targets.push_back(output_label / std::string(manifest_file_name()));
      }
      if (!options.depfile.empty() && summary.failed == 0) {
        std::vector<fs::path> dependencies;
        for (const Job& job : jobs) {
          for (const std::string& file : job.written_files)
            targets.push_back(output_label / file);
          if (!sources[job.input].text) dependencies.push_back(sources[job.input].path);
          if (!job.spectral_file.empty()) dependencies.push_back(job.spectral_file);
        }
        if (!write_batch_depfile(options.depfile, targets, std::move(dependencies),
                                 options.extra_dependencies, reporter))
          ++summary.failed;
      }
    } catch (const std::exception& error) {
      reporter.error(output_label.string(), error.what());
      ++summary.failed;
    }
  }
  return result;
}

}  // namespace matc
