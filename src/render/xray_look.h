#pragma once
// What each kind of matter looks like in the X-ray views, for legends: the
// grey the composite pass (shaders/xray_composite.frag.glsl) gives a coil,
// a catheter, a guide wire and the contrast-filled vessel of a scene. GL-free.
#include "physics/draw_data.h"
#include "render/camera.h"
#include "render/renderer.h"

namespace coilsim::render {

// The grey (0 black, 1 white) of matter that attenuates by `attenuation`
// (mu times the thickness crossed, summed): Beer-Lambert, I0 exp(-a), as the
// composite pass shades it at the image centre, without its grain.
float xrayGrey(const XRaySettings& xray, double attenuation);

// Greys of the scene's matter in the X-ray view from `camera`; a kind the
// scene does not hold is -1. A tube's is the mean grey across its width
// (rays at every offset from its axis cross 2 sqrt(r^2 - y^2) of it); a
// closed mesh's the grey at its mean chord, its volume over its area
// projected along the view (exact for a convex one; contrast attenuates
// little, so the mean grey is nearly that). The thinnest tube of a kind
// stands for it (the coil, not a thick stretch of catheter drawn as coil);
// the largest closed mesh for the vessel (open meshes, a neck plane's
// disc, hold no contrast). Linear in the triangles, no allocation: cheap
// enough for every frame. `vesselEdge` is the vessel's outline, the
// darkest the composite draws its border; `background` what crosses no
// matter (I0).
struct XRayGreys {
  float coil = -1, catheter = -1, wire = -1, vessel = -1, vesselEdge = -1;
  float background = 1;
};
XRayGreys xrayGreys(const DrawData& data, const Camera& camera, const XRaySettings& xray);

}  // namespace coilsim::render
