#include "interrupt_cleanup.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <thread>

#include "matc/api/files.h"

namespace matc::cli {

void remove_temporaries_when_interrupted() {
  sigset_t signals;
  sigemptyset(&signals);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP})
    sigaddset(&signals, signal);
  if (pthread_sigmask(SIG_BLOCK, &signals, nullptr) != 0) return;
  // The cleanup runs on an ordinary thread (sigwait), so it may take locks and free memory, which
  // a signal handler may not.
  std::thread([signals] {
    int received = 0;
    if (sigwait(&signals, &received) != 0) return;
    api::remove_temporaries_in_flight();
    ::signal(received, SIG_DFL);
    sigset_t just_this;
    sigemptyset(&just_this);
    sigaddset(&just_this, received);
    pthread_sigmask(SIG_UNBLOCK, &just_this, nullptr);
    ::raise(received);
    ::_exit(128 + received);  // not reached: the default action ends the process
  }).detach();
}

}  // namespace matc::cli
