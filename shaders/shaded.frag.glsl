#version 330 core
// The 3D view: two lights fixed to the camera, Blinn-Phong highlights (bright
// and tight for platinum, soft for polymer), a cool rim light that separates
// the coil from the vessel behind it. Transparent meshes turn more opaque
// towards their silhouettes, so a vessel reads as a glass shell.
in vec3 vEyePosition;
in vec3 vEyeNormal;
in vec4 vColour;

uniform float uSpecular;     // highlight strength, 0-1
uniform float uShininess;    // Blinn-Phong exponent
uniform float uOpacity;      // multiplies the vertex alpha
uniform int uSilhouetteAlpha;

out vec4 fragColour;

vec3 toDisplay(vec3 linear) { return pow(clamp(linear, 0.0, 1.0), vec3(1.0 / 2.2)); }

void main() {
  vec3 n = normalize(vEyeNormal);
  vec3 v = normalize(-vEyePosition);
  if (!gl_FrontFacing) n = -n;  // inner walls of open or transparent meshes
  const vec3 key = normalize(vec3(-0.45, 0.65, 0.6));
  const vec3 fill = normalize(vec3(0.6, -0.25, 0.45));
  float diffuse = 0.72 * max(dot(n, key), 0.0) + 0.28 * max(dot(n, fill), 0.0);
  float highlight = pow(max(dot(n, normalize(key + v)), 0.0), uShininess)
                  + 0.35 * pow(max(dot(n, normalize(fill + v)), 0.0), uShininess);
  float facing = max(dot(n, v), 0.0);
  float rim = pow(1.0 - facing, 3.0);
  vec3 base = vColour.rgb;
  vec3 colour = base * (0.16 + 0.84 * diffuse) + uSpecular * highlight + 0.18 * rim * vec3(0.55, 0.7, 1.0);
  float alpha = vColour.a * uOpacity;
  if (uSilhouetteAlpha != 0) alpha = mix(alpha, min(1.0, 3.0 * alpha + 0.15), rim);
  fragColour = vec4(toDisplay(colour), alpha);
}
