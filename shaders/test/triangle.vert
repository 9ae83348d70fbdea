#version 450
// Test shader: passes clip-space positions and colors through.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 color;
layout(location = 0) out vec4 vertex_color;

void main() {
  gl_Position = position;
  vertex_color = color;
}
