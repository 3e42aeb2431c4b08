#version 330 core
// X-ray pass 2: Beer-Lambert, I = I0 exp(-sum mu t), shown as fluoroscopy:
// dark where radio-opaque. A small blur stands in for the focal spot, the
// contrast channel's gradient draws the vessel's roadmap outline, the
// intensifier darkens towards the edge and quantum noise (deterministic
// per pixel, so screenshots are reproducible) adds grain.
uniform sampler2D uAccum;
uniform vec4 uViewport;     // x, y, width, height in pixels
uniform vec3 uWeight;       // display weight of metal, catheter, contrast
uniform float uOutline;     // weight of the vessel outline
uniform float uBrightness;  // I0
uniform float uNoise;       // grain amplitude
uniform float uVignette;

out vec4 fragColour;

float hash(vec2 p) {
  vec3 q = fract(vec3(p.xyx) * 0.1031);
  q += dot(q, q.yzx + 33.33);
  return fract((q.x + q.y) * q.z);
}

// A bilinear tap at `offset` pixels from this pixel's centre, kept inside
// the viewport so that biplane images do not bleed into each other.
vec4 tap(vec2 offset) {
  vec2 lo = uViewport.xy + 0.5, hi = uViewport.xy + uViewport.zw - 0.5;
  return texture(uAccum, clamp(gl_FragCoord.xy + offset, lo, hi) / vec2(textureSize(uAccum, 0)));
}

void main() {
  // Four bilinear taps at the pixel corners average to the 3x3 binomial
  // blur; their differences give the (equally smoothed) gradient.
  vec4 a = tap(vec2(0.5, 0.5)), b = tap(vec2(-0.5, 0.5)), c = tap(vec2(0.5, -0.5)), d = tap(vec2(-0.5, -0.5));
  vec4 mean = 0.25 * (a + b + c + d);
  // Winding-independent thicknesses; tiny negative sums are round-off.
  vec3 t = vec3(max(mean.r, 0.0), max(mean.g, 0.0), abs(mean.b));
  vec2 g = vec2(abs(a.b + c.b) - abs(b.b + d.b), abs(a.b + b.b) - abs(c.b + d.b));
  float edge = min(length(g), 1.5);
  float attenuation = dot(uWeight, t) + uOutline * edge;
  vec2 q = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw * 2.0 - 1.0;
  float intensity = uBrightness * exp(-attenuation) * (1.0 - uVignette * 0.25 * dot(q, q));
  intensity += uNoise * (hash(gl_FragCoord.xy) - 0.5);
  fragColour = vec4(vec3(clamp(intensity, 0.0, 1.0)), 1.0);
}
