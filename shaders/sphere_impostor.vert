#version 330 core
// Joint spheres while the view moves, as Blender's overlay draws them: each instance is a
// square card facing the eye through the sphere's centre, just large enough to hold its
// outline, and sphere_impostor.frag finds the sphere behind each pixel. Two triangles
// against the tessellated sphere's 288 (llvmpipe sets each one up).
layout(location = 0) in vec3 aPosition;  // a corner of the square [-1, 1]^2 (z = 0)
layout(location = 2) in mat4 aModel;     // locations 2..5: rotation * uniform scale, as shaded.vert's
layout(location = 6) in vec4 aColor;

uniform mat4 uProjection;
uniform mat4 uView;
uniform bool uOrthographic;

out vec3 vViewPosition;  // the card's point, view space
flat out vec3 vCenter;   // the sphere's centre, view space
flat out float vRadius;  // its radius (the instance's scale)
flat out vec4 vColor;

void main() {
  vec3 c = vec3(uView * aModel[3]);
  float r = length(vec3(aModel[0]));
  vec3 u = vec3(1.0, 0.0, 0.0), v = vec3(0.0, 1.0, 0.0);
  float extent = r;  // orthographic: the outline is the sphere's own circle
  if (!uOrthographic) {
    // Across the line of sight to the centre, the cone of rays touching the sphere is a
    // circle of radius r d / sqrt(d^2 - r^2) at the centre's distance d.
    float d = length(c);
    vec3 w = c / d;
    u = normalize(cross(w, abs(w.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    v = cross(u, w);
    extent = r * d / sqrt(max(d * d - r * r, 1e-12));
  }
  vec3 p = c + (aPosition.x * u + aPosition.y * v) * extent;
  vViewPosition = p;
  vCenter = c;
  vRadius = r;
  vColor = aColor;
  gl_Position = uProjection * vec4(p, 1.0);
}
