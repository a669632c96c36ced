#pragma once

namespace debrisflow::app {

// Requests to end a run early (Ctrl-C, `kill`): the time loop stops at the end of the current
// step with InterruptedError and the output so far (probes, frames, summary.json) is kept.
// A second signal ends the process at once (the default action).
void install_stop_handlers(); // SIGINT and SIGTERM
void request_stop();          // what the handlers do (also for tests)
void clear_stop_request();
bool stop_requested();
int stop_signal(); // the signal that asked, 0 for request_stop()

} // namespace debrisflow::app
