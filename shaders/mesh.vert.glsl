#version 330 core
// Triangles of tubes, spheres, arrows and meshes; lighting happens in eye
// space (the camera carries the lights, as in most viewers).
layout(location = 0) in vec3 aPosition;  // m, world
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColour;    // linear RGBA

uniform mat4 uView;        // world to eye, a rigid motion
uniform mat4 uProjection;

out vec3 vEyePosition;
out vec3 vEyeNormal;
out vec4 vColour;

void main() {
  vec4 p = uView * vec4(aPosition, 1.0);
  vEyePosition = p.xyz;
  vEyeNormal = mat3(uView) * aNormal;
  vColour = aColour;
  gl_Position = uProjection * p;
}
