// Build.compile_batch: `matc -o DIR FILES...` through the library's pipeline (compile_batch), with
// the GIL released while it runs and Python's progress callback and Ctrl-C honoured between
// materials.
#include "matc/pipeline/compile_batch.h"

#include <map>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "errors.h"

namespace py = pybind11;

namespace matc::python {
namespace {

struct BatchResultObject {
  BatchCounts counts;
  std::size_t failed_checks = 0;
  bool cancelled = false;
  Diagnostics diagnostics;
  std::optional<std::map<std::string, std::string>> files;  // for an output in memory
};

// What the batch's events leave for the Python side: diagnostics in input order, and the first
// exception the progress callback raised (which cancels the batch).
struct EventRecord {
  Diagnostics diagnostics;
  std::optional<py::error_already_set> raised;
  std::stop_source cancel;
};

BatchEvents recording_events(EventRecord& record, const py::object& progress) {
  BatchEvents events;
  events.diagnostics = [&record](const Diagnostics& diagnostics) {
    record.diagnostics.append(diagnostics);
  };
  events.error = [&record](const std::string& where, const std::string& message) {
    record.diagnostics.error({where, 0, 0}, "", message);
  };
  events.progress = [&record, progress](const BatchProgress& step) {
    const py::gil_scoped_acquire acquire;
    if (record.raised) return;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none()) progress(step.done, step.total, std::string(step.name));
    } catch (py::error_already_set& error) {
      record.raised.emplace(std::move(error));
      record.cancel.request_stop();
    }
  };
  return events;
}

std::vector<MaterialSource> material_sources(
    const std::vector<std::pair<std::string, std::optional<std::string>>>& sources) {
  std::vector<MaterialSource> out;
  out.reserve(sources.size());
  for (const auto& [path, text] : sources)
    out.push_back(text ? MaterialSource::in_memory(path, *text) : MaterialSource::file(path));
  return out;
}

py::object run_batch(const Build& build,
                     const std::vector<std::pair<std::string, std::optional<std::string>>>& sources,
                     const std::optional<std::string>& output_directory, unsigned jobs,
                     bool keep_going, bool no_shared, bool shared_only,
                     const std::optional<std::string>& depfile,
                     const std::vector<std::string>& extra_dependencies,
                     const py::object& progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: must be callable as progress(done, total, name)");
  const std::vector<MaterialSource> inputs = material_sources(sources);
  CompileBatchOptions options;
  options.jobs = jobs;
  options.keep_going = keep_going;
  options.no_shared = no_shared;
  options.shared_only = shared_only;
  if (depfile) options.depfile = *depfile;
  for (const std::string& dependency : extra_dependencies)
    options.extra_dependencies.emplace_back(dependency);

  EventRecord record;
  options.cancel = record.cancel.get_token();
  const BatchEvents events = recording_events(record, progress);
  auto result = std::make_unique<BatchResultObject>();
  std::optional<MemoryOutput> memory;
  std::optional<DirectoryOutput> directory;
  OutputSink& output = output_directory
                           ? static_cast<OutputSink&>(directory.emplace(*output_directory))
                           : static_cast<OutputSink&>(memory.emplace());
  CompileBatchResult outcome;
  {
    py::gil_scoped_release release;
    outcome = compile_batch(build, inputs, output, options, events);
  }
  if (record.raised) throw std::move(*record.raised);
  result->counts = outcome.counts;
  result->failed_checks = outcome.failed_checks;
  result->cancelled = outcome.cancelled;
  result->diagnostics = std::move(record.diagnostics);
  if (memory) result->files = memory->files();
  const bool failed = result->counts.failed > 0 || result->diagnostics.has_errors();
  const Diagnostics diagnostics = result->diagnostics;
  py::object object = py::cast(std::move(result));
  if (failed) raise_batch_error(diagnostics, object);
  return object;
}

}  // namespace

void register_batch(py::module_& module) {
  py::class_<BatchResultObject>(module, "BatchResult", "What a batch compile did")
      .def_property_readonly(
          "done", [](const BatchResultObject& r) { return r.counts.done; }, "Materials compiled")
      .def_property_readonly(
          "written", [](const BatchResultObject& r) { return r.counts.written; },
          "Files written (new or changed)")
      .def_property_readonly(
          "unchanged", [](const BatchResultObject& r) { return r.counts.unchanged; },
          "Files whose bytes were already there (left untouched)")
      .def_property_readonly("failed", [](const BatchResultObject& r) { return r.counts.failed; })
      .def_property_readonly("not_attempted",
                             [](const BatchResultObject& r) { return r.counts.not_attempted; })
      .def_readonly("cancelled", &BatchResultObject::cancelled)
      .def_property_readonly(
          "diagnostics", [](const BatchResultObject& r) { return diagnostic_list(r.diagnostics); },
          "Every input's errors, warnings and notes, in input order")
      .def_property_readonly(
          "files",
          [](const BatchResultObject& r) -> py::object {
            if (!r.files) return py::none();
            py::dict out;
            for (const auto& [name, bytes] : *r.files)
              out[py::str(name)] = py::bytes(bytes);
            return out;
          },
          "Name to bytes for a batch compiled into memory (output=None); None for a directory")
      .def("__repr__", [](const BatchResultObject& r) {
        return fmt::format("<matc.BatchResult done={} written={} unchanged={} failed={}>",
                           r.counts.done, r.counts.written, r.counts.unchanged, r.counts.failed);
      });

  module.def("_compile_batch", &run_batch, py::arg("build"), py::arg("sources"), py::arg("output"),
             py::arg("jobs"), py::arg("keep_going"), py::arg("no_shared"), py::arg("shared_only"),
             py::arg("depfile"), py::arg("extra_dependencies"), py::arg("progress"));
}

}  // namespace matc::python
