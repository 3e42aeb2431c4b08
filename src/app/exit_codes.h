#pragma once
// Process exit codes of every coilsim command.
namespace coilsim::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the simulation failed (step refused, static not converged) or rendering did
inline constexpr int kExitUsage = 2;    // bad command line or bad input file

}  // namespace coilsim::app
