#version 450
// The sky: one triangle over the whole screen, made from the vertex index alone, at depth 0 (the
// infinitely far plane of aerial's reversed-Z projection).
void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
