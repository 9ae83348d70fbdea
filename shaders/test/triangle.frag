#version 450
// Test shader: writes the interpolated color, premultiplied by its alpha.
layout(location = 0) in vec4 vertex_color;
layout(location = 0) out vec4 color;

void main() { color = vec4(vertex_color.rgb * vertex_color.a, vertex_color.a); }
