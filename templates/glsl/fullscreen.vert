#version 450
// matc {{version}}: one triangle that covers the viewport, from gl_VertexIndex alone (no vertex
// buffer). Used by the comparison renders and the full-screen cost benchmark.
void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
