// Ctrl-C (SIGINT) and SIGTERM while rendering: the first asks the render to stop after
// the passes in flight, so the samples taken are kept and written; a second signal ends
// the process at once (the default action) after removing the staged temporary outputs,
// leaving existing outputs untouched.
#pragma once

namespace pathcl::cli {

// Installs the handlers (idempotent).
void catch_interrupts();
// Whether a stop was asked for, and by which signal (0: none).
bool interrupted();
int interrupt_signal();
// The exit code after an interrupted render: 128 + the signal (130 for SIGINT).
int interrupted_exit_code();

} // namespace pathcl::cli
