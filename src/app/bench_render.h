#pragma once
// The render part of `coilsim bench` (only in binaries built with the ui
// layer): frames per second of the 3D, X-ray and biplane views at 1280x720
// off-screen (OSMesa) for scenes/default.json, and how a real-time frame
// divides between physics and drawing while the coil is pushed.
#include <filesystem>
#include <functional>
#include <string>

namespace coilsim {

// Reports figures through `set` (render_fps_3d, render_fps_xray, ...,
// frame_physics_share, frame_render_share); prints a short table on stdout
// unless `json`. When the scene or an OpenGL 3.3 context is missing it says
// so on stderr and reports nothing: a bench without graphics still runs.
void benchRenderFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json);

// The practice window with four coils of the 7 mm case detached in the sac
// and a fifth pushed at 5 mm/s (bench_practice.cpp): physics against real
// time, with the fifth coil alone as the baseline, and drawing milliseconds
// per frame in 3D, X-ray and biplane. Reports through `set`
// (practice4_physics_realtime, practice4_ms_3d, ...) as benchRenderFigures does.
void benchPracticeWindowFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json);

// `rel` under the working directory, else under the source tree the binary
// was built in; empty when neither has it.
std::filesystem::path findSourceFile(const std::filesystem::path& rel);

}  // namespace coilsim
