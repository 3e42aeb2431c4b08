#pragma once
// Coil and catheter choice in the panel. The ui lists what the app offers
// (catalogue coils with their shape, loop diameter, length and stiffness;
// catheter tip shapes) and asks the app to build the chosen setup; the app
// reads the catalogue and compiles the scene (io, planning), which the ui
// must not know. A failed build keeps the setup that runs.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "physics/model.h"
#include "physics/state.h"
#include "ui/readouts.h"
#include "ui/session.h"

namespace coilsim::ui {

// What the window runs after a choice: model (with its device), state, and
// what goes with them (draw hook, read-outs, input observer).
struct SceneSetup {
  Model model;
  State state;
  DrawDataHook draw;
  ReadoutHook readouts;
  std::shared_ptr<RunObserver> observer;
  std::string loaded;  // said in the panel: what was loaded
};

struct SetupChoices {
  std::vector<std::string> coils;      // one label each: name, shape, loop, length, stiffness
  std::vector<std::string> catheters;  // tip shapes
  int coil = -1, catheter = -1;        // the ones running (-1: the scene's own)
  std::string coilNote, catheterNote;  // shown under a combo (e.g. why it is fixed)
  bool catheterFixed = false;          // the catheter combo is shown but cannot change
  // Builds the setup for the chosen indices. Throws std::exception saying
  // why it cannot (a coil longer than the catheter allows, ...).
  std::function<SceneSetup(int coil, int catheter)> build;
  // Optional (practice): once the running coil has detached, a coil chosen
  // goes in after it instead, the detached ones kept in the sac. Builds
  // that from the session's model and state now (the observer stays and is
  // told by the app). Throws std::exception saying why it cannot.
  std::function<SceneSetup(int coil, const Model& now, const State& state)> follow;
  std::string followNote;  // shown under the coil combo once a coil has detached
  explicit operator bool() const { return bool(build); }
};

// The result of the last choice, for the panel.
struct SetupStatus {
  std::string message;  // "loaded ..." or the reason it failed
  bool failed = false;
};

class Views;
struct PanelContext;

// Builds and loads the chosen setup into the session (reset, paused) and
// the panel (read-outs); on failure keeps everything and says why in
// `status`. Returns true when loaded.
bool applySetup(SetupChoices& choices, int coil, int catheter, Session& session, PanelContext& panel);

// True when a coil chosen now goes in after the running one (`follow`):
// the session's coil has detached.
bool followsNow(const SetupChoices& choices, const Session& session);

// The panel section: the two combos (once the coil has detached, the coil
// combo offers the next coil), what is loaded, the last error.
void drawSetupSection(const SetupChoices& choices, const Session& session, PanelContext& panel);

}  // namespace coilsim::ui
