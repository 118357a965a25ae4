// Ctrl-C and kill(1) during a run: matc removes the temporaries it created (and nothing else),
// then dies of the signal as if it had none of its own handling.
#pragma once

namespace matc::cli {

// Call first in main, before any thread starts: blocks SIGINT, SIGTERM and SIGHUP in every thread
// and waits for them on a thread of its own.
void remove_temporaries_when_interrupted();

}  // namespace matc::cli
