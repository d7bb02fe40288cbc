#version 330 core
// Joint spheres while the view moves, as Blender's overlay draws them: each instance is the
// box around its unit sphere (rotation * uniform scale, as shaded.vert's instances), drawn
// with back faces culled, and sphere_impostor.frag finds the sphere inside it per pixel. A
// box is 12 triangles against the tessellated sphere's 288 (llvmpipe sets each one up).
layout(location = 0) in vec3 aPosition;  // a corner of the box [-1, 1]^3
layout(location = 2) in mat4 aModel;     // locations 2..5
layout(location = 6) in vec4 aColor;

uniform mat4 uViewProjection;
uniform mat4 uView;

out vec3 vViewPosition;         // the box surface point, view space
flat out vec3 vCenter;          // the sphere's centre, view space
flat out float vRadius;         // its radius (the instance's uniform scale)
flat out vec4 vColor;

void main() {
  vec4 world = aModel * vec4(aPosition, 1.0);
  vViewPosition = vec3(uView * world);
  vCenter = vec3(uView * aModel[3]);
  vRadius = length(vec3(aModel[0]));
  vColor = aColor;
  gl_Position = uViewProjection * world;
}
