#pragma once
namespace coilsim {
// Parses the command line and runs the sub-command; returns the exit code.
int runCli(int argc, char** argv);
}
