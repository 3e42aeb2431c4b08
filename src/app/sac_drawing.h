#pragma once
// What the pictures of a sac draw besides the model (the practice window,
// its screenshots, plan pictures): the neck plane where it cuts the sac's
// surface, so that the ostium can be judged in X-ray too, and a legend that
// says what each colour is and whether the case has a parent vessel.
#include <vector>

#include "physics/draw_data.h"
#include "planning/sac_geometry.h"
#include "ui/scene_legend.h"

namespace coilsim::app {

// The neck plane's disc over the ostium: the points where the plane cuts
// the sac's surface nearest the neck point (within 2.5x the nearest; a
// vessel cut further away is left out), fanned around their centre. Empty
// (no triangles) when the plane does not cut the surface.
DrawMesh neckDisc(const planning::Sac& sac);

// Whether the surface holds a parent vessel beyond the neck plane: more
// volume there than half the sac's. A bare sphere cut by its neck plane has
// only a cap beyond it (a 7 mm sphere cut 1 mm above its bottom: 6 %).
bool hasParentVessel(const planning::Sac& sac);

// Coil, catheter, sac wall (and vessel), the neck plane; a case without a
// vessel says which side of the plane stands for it.
std::vector<ui::LegendEntry> sacLegend(const planning::Sac& sac);

}  // namespace coilsim::app
