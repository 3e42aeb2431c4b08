#pragma once
// Help texts and the bash completion, generated from the command table
// (app/commands.h): nothing here names an option by hand.
#include <cstdio>
#include <string>

#include "app/commands.h"

namespace coilsim::app {

// `coilsim help`: every command with its usage and options, and the effects
// a scene can switch on (from the effect registry).
void printMainHelp(std::FILE* to);

// `coilsim CMD --help` and `coilsim help CMD`: that command's full usage.
void printCommandHelp(const CommandSpec& command, std::FILE* to);

// `coilsim completion bash`: a bash completion script for commands,
// options, their choices, scene and mesh files and catalogue coils (asked of
// `coilsim completion coils` while completing).
std::string bashCompletion();

}  // namespace coilsim::app
