#include "batch_events.h"

#include "base/echoed_text.h"
#include "public_diagnostics.h"

namespace matc::api {

matc::BatchEvents library_events(const BatchEvents& events) {
  matc::BatchEvents out;
  if (events.diagnostics) {
    out.diagnostics = [&events](const Diagnostics& diagnostics) {
      events.diagnostics(public_diagnostics(diagnostics));
    };
  }
  if (events.progress) {
    out.progress = [&events](const matc::BatchProgress& progress) {
      events.progress({progress.done, progress.total, std::string(progress.name)});
    };
  }
  if (events.error) {
    out.error = [&events](const std::string& where, const std::string& message) {
      events.error(printable(where), printable(message));
    };
  }
  return out;
}

BatchResult public_result(const BatchCounts& counts, bool cancelled) {
  BatchResult out;
  out.compiled = counts.done;
  out.written = counts.written;
  out.unchanged = counts.unchanged;
  out.failed = counts.failed;
  out.not_attempted = counts.not_attempted;
  out.cancelled = cancelled;
  return out;
}

}  // namespace matc::api
