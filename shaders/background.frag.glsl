#version 330 core
// The 3D view's backdrop: a vertical gradient, lighter behind the scene
// centre, in display (sRGB) colours.
in vec2 vUv;

uniform vec3 uTop;
uniform vec3 uBottom;

out vec4 fragColour;

void main() {
  vec3 c = mix(uBottom, uTop, smoothstep(0.0, 1.0, vUv.y));
  vec2 q = vUv - vec2(0.5, 0.55);
  c += 0.06 * exp(-6.0 * dot(q, q));
  fragColour = vec4(c, 1.0);
}
