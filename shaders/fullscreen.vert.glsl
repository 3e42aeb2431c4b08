#version 330 core
// One triangle covering the viewport, from gl_VertexID alone (no buffers).
out vec2 vUv;  // 0-1 across the viewport

void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  vUv = p;
  gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
