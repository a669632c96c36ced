#pragma once

namespace debrisflow::app {

// Requests to end a run early (Ctrl-C, `kill`): the time loop stops at the end of the current
// step with InterruptedError and the output so far (probes, frames, summary.json) is kept.
// A second signal ends the process at once (the default action).
void install_stop_handlers(); // SIGINT and SIGTERM
int stop_signal();            // the signal that asked for a stop, 0 while none has

} // namespace debrisflow::app
