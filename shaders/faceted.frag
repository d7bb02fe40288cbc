#version 330 core
// faceted.vert's colours: the front one, or the back one where a thin shape is seen from behind.
flat in vec4 vFront;
flat in vec4 vBack;
out vec4 fragColor;

void main() { fragColor = gl_FrontFacing ? vFront : vBack; }
