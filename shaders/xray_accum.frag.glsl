#version 330 core
// X-ray pass 1: line integrals of attenuation. Along a view ray a closed
// surface is entered at front faces and left at back faces, so adding
// -distance at front faces and +distance at back faces (additive blending
// into a float target) leaves the thickness crossed, whatever the order.
// Each channel collects mu * thickness of one kind of matter:
// r = metal (coil, wire), g = catheter, b = contrast-filled vessel.
in vec3 vEyePosition;
in vec3 vEyeNormal;
in vec4 vColour;

uniform vec4 uMu;             // 1/m per channel
uniform float uReference;     // m, subtracted from distances to keep float sums exact

out vec4 fragColour;

void main() {
  float d = length(vEyePosition) - uReference;
  fragColour = uMu * (gl_FrontFacing ? -d : d);
}
