#version 450
// One triangle that covers the screen (clip-space positions from the vertex buffer).
layout(location = 0) in vec4 position;

void main() { gl_Position = position; }
