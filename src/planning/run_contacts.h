#pragma once
// Contacts of a planning or practice run: the sac surface is a wall the coil
// presses on (wall_contact), the loops of a coil push each other apart
// (self_contact), and coils placed before are obstacles for the next one
// (rod_contact). A case scene need not list any of this: the planning layer
// adds what is missing, so every plan and practice run measures wall forces
// from the contact layer instead of letting the coil pass through the wall.
#include "physics/deployment.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/sac_geometry.h"

namespace coilsim::planning {

// The contact effects a run switches on when its scene does not name them.
inline constexpr const char* kRunContactEffects[] = {"wall_contact", "self_contact", "rod_contact"};

// Adds the sac surface as a wall obstacle unless the scene already has a
// wall that takes part in contact (a phantom or patient mesh listed under
// "obstacles"), and each of kRunContactEffects the scene does not list, at
// its registered defaults: the same contact law and parameters as a window or
// headless run of a scene that lists them, so a run's wall load does not
// depend on who runs it (docs/contact.md, "The wall load"). An effect the scene lists, even switched off,
// keeps the scene's settings: a run without wall contact then reports wall
// forces as unavailable. Throws std::invalid_argument if the sac has no mesh.
void addRunContacts(ModelDef& def, const Sac& sac);

// The rigid catheter tip is not simulated (the coil inside it is not
// either); its rod is only drawn. As a rod it would take part in
// rod_contact as a solid capsule, and the detached coil's proximal end,
// which sits on the catheter's axis at the tip, would be inside it the step
// after detach and be thrown out (an axial strain blow-up at detach in every
// plan). So runs take the drawn rigid catheter out of the step (inactive)
// and put it back for pictures. A flexible catheter is simulated and stays.
void setDrawnCatheterActive(const Deployment& dep, State& state, bool active);

// The drawn rigid catheter as a tube, for windows drawing a state where it is
// inactive (nothing when it is active or flexible: then the state draws it).
void appendInactiveCatheter(const Model& model, const State& state, const Deployment& dep, DrawData& out);

}  // namespace coilsim::planning
