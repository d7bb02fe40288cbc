#version 330 core
// The sphere behind an impostor card (sphere_impostor.vert): the view ray through this pixel
// (from the eye, or straight along -z for an orthographic camera) meets it or the pixel is
// left alone; where it does, the depth is the sphere's and the light is shaded.frag's.
in vec3 vViewPosition;
flat in vec3 vCenter;
flat in float vRadius;
flat in vec4 vColor;
out vec4 fragColor;

uniform mat4 uProjection;
uniform bool uOrthographic;

void main() {
  vec3 origin = uOrthographic ? vec3(vViewPosition.xy, 0.0) : vec3(0.0);
  vec3 dir = uOrthographic ? vec3(0.0, 0.0, -1.0) : normalize(vViewPosition);
  // |origin + t dir - centre| = radius, the nearer root.
  vec3 oc = origin - vCenter;
  float b = dot(oc, dir);
  float c = dot(oc, oc) - vRadius * vRadius;
  float h = b * b - c;
  if (h < 0.0) discard;
  float t = -b - sqrt(h);
  vec3 hit = origin + t * dir;
  vec4 clip = uProjection * vec4(hit, 1.0);
  gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;  // the default depth range [0, 1]
  vec3 n = (hit - vCenter) / vRadius;
  vec3 key = normalize(vec3(-0.4, 0.6, 0.7));
  vec3 fill = normalize(vec3(0.6, -0.2, 0.5));
  float light = 0.35 + 0.6 * max(dot(n, key), 0.0) + 0.2 * max(dot(n, fill), 0.0);
  fragColor = vec4(vColor.rgb * light, vColor.a);
}
