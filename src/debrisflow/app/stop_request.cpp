#include "debrisflow/app/stop_request.hpp"
#include <atomic>
#include <csignal>

namespace debrisflow::app {

namespace {

std::atomic<int> requested{0}; // the signal number, 0 while none has come
static_assert(std::atomic<int>::is_always_lock_free, "used from a signal handler");

extern "C" void on_stop_signal(int sig) {
    requested.store(sig);
    std::signal(sig, SIG_DFL); // a second Ctrl-C kills
}

} // namespace

void install_stop_handlers() {
    for (int sig : {SIGINT, SIGTERM})
        if (std::signal(sig, on_stop_signal) == SIG_IGN)
            std::signal(sig, SIG_IGN); // keep ignoring (a background job's SIGINT)
}

int stop_signal() {
    return requested.load();
}

} // namespace debrisflow::app
