#version 330 core
// Overlay triangles, already in clip space (expanded to pixel widths on the CPU).
layout(location = 0) in vec4 aClip;
layout(location = 1) in vec4 aColor;
out vec4 vColor;
void main() {
  vColor = aColor;
  gl_Position = aClip;
}
