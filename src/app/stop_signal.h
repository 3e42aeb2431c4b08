#pragma once
// Ctrl-C (SIGINT) and SIGTERM ask a long command to stop after its current
// step, so it can still write valid files of what it reached. A second
// signal ends the process at once (the default action).
namespace coilsim::app {

// Installs the handlers; done once by the command line before a command runs.
void installStopHandlers();

// True once SIGINT or SIGTERM arrived.
bool stopRequested();

// 128 + the signal that asked to stop (130 for SIGINT, 143 for SIGTERM);
// 0 when none did.
int stopExitCode();

// "interrupted (SIGINT)" or "terminated (SIGTERM)", for messages.
const char* stopReason();

}  // namespace coilsim::app
