// Build.compile_batch: `matc -o DIR FILES...` through the public API's batch (matc/api/batch.h),
// with the GIL released while it runs and Python's progress callback and Ctrl-C honoured between
// materials.
#include <algorithm>
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
#include "matc/api/batch.h"

namespace py = pybind11;

namespace matc::python {
namespace {

struct BatchResultObject {
  api::BatchResult counts;
  std::vector<api::Diagnostic> diagnostics;
  bool in_memory = false;
};

// What the batch's events leave for the Python side: diagnostics in input order, and the first
// exception the progress callback raised (which cancels the batch).
struct EventRecord {
  std::vector<api::Diagnostic> diagnostics;
  std::optional<py::error_already_set> raised;
  std::stop_source cancel;
};

api::BatchEvents recording_events(EventRecord& record, const py::object& progress) {
  api::BatchEvents events;
  events.diagnostics = [&record](const std::vector<api::Diagnostic>& diagnostics) {
    record.diagnostics.insert(record.diagnostics.end(), diagnostics.begin(), diagnostics.end());
  };
  // The batch's own error (output directory, manifest, depfile), escaped: the line the CLI prints.
  events.error = [&record](const std::string& where, const std::string& message) {
    record.diagnostics.push_back(
        {"error", where, 0, 0, "", message, "", fmt::format("{}: error: {}", where, message)});
  };
  events.progress = [&record, progress](const api::BatchProgress& step) {
    const py::gil_scoped_acquire acquire;
    if (record.raised) return;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none()) progress(step.done, step.total, python_text(step.name));
    } catch (py::error_already_set& error) {
      record.raised.emplace(std::move(error));
      record.cancel.request_stop();
    }
  };
  return events;
}

py::object run_batch(const api::Build& build,
                     const std::vector<std::pair<std::string, std::optional<std::string>>>& sources,
                     const std::optional<std::string>& output_directory, unsigned jobs,
                     bool keep_going, bool no_shared, bool shared_only,
                     const std::optional<std::string>& depfile,
                     const std::vector<std::string>& extra_dependencies,
                     const py::object& progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: must be callable as progress(done, total, name)");
  std::vector<api::BatchSource> inputs;
  inputs.reserve(sources.size());
  for (const auto& [path, text] : sources)
    inputs.push_back({path, text});
  api::BatchOptions options;
  options.in_memory = !output_directory;
  options.output_directory = output_directory.value_or("");
  options.jobs = jobs;
  options.keep_going = keep_going;
  options.no_shared = no_shared;
  options.shared_only = shared_only;
  options.depfile = depfile.value_or("");
  options.extra_dependencies = extra_dependencies;

  EventRecord record;
  const api::BatchEvents events = recording_events(record, progress);
  auto result = std::make_unique<BatchResultObject>();
  {
    const py::gil_scoped_release release;
    result->counts = api::compile_batch(build, inputs, options, events, record.cancel.get_token());
  }
  if (record.raised) throw std::move(*record.raised);
  result->in_memory = options.in_memory;
  const bool failed = result->counts.failed > 0 ||
                      std::any_of(record.diagnostics.begin(), record.diagnostics.end(),
                                  [](const api::Diagnostic& d) { return d.severity == "error"; });
  result->diagnostics = std::move(record.diagnostics);
  const std::vector<api::Diagnostic> diagnostics = result->diagnostics;
  py::object object = py::cast(std::move(result));
  if (failed) raise_batch_error(diagnostics, object);
  return object;
}

}  // namespace

void register_batch(py::module_& module) {
  py::class_<BatchResultObject>(module, "BatchResult", "What a batch compile did")
      .def_property_readonly(
          "done", [](const BatchResultObject& r) { return r.counts.compiled; },
          "Materials compiled")
      .def_property_readonly(
          "written", [](const BatchResultObject& r) { return r.counts.written; },
          "Files written (new or changed)")
      .def_property_readonly(
          "unchanged", [](const BatchResultObject& r) { return r.counts.unchanged; },
          "Files whose bytes were already there (left untouched)")
      .def_property_readonly("failed", [](const BatchResultObject& r) { return r.counts.failed; })
      .def_property_readonly("not_attempted",
                             [](const BatchResultObject& r) { return r.counts.not_attempted; })
      .def_property_readonly("cancelled",
                             [](const BatchResultObject& r) { return r.counts.cancelled; })
      .def_property_readonly(
          "diagnostics", [](const BatchResultObject& r) { return diagnostic_list(r.diagnostics); },
          "Every input's errors, warnings and notes, in input order")
      .def_property_readonly(
          "files",
          [](const BatchResultObject& r) -> py::object {
            if (!r.in_memory) return py::none();
            py::dict out;
            for (const auto& [name, bytes] : r.counts.files)
              out[py::str(name)] = py::bytes(bytes);
            return out;
          },
          "Name to bytes for a batch compiled into memory (output=None); None for a directory")
      .def("__repr__", [](const BatchResultObject& r) {
        return fmt::format("<matc.BatchResult done={} written={} unchanged={} failed={}>",
                           r.counts.compiled, r.counts.written, r.counts.unchanged,
                           r.counts.failed);
      });

  module.def("_compile_batch", &run_batch, py::arg("build"), py::arg("sources"), py::arg("output"),
             py::arg("jobs"), py::arg("keep_going"), py::arg("no_shared"), py::arg("shared_only"),
             py::arg("depfile"), py::arg("extra_dependencies"), py::arg("progress"));
}

}  // namespace matc::python
