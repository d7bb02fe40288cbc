#version 330 core
// Studio-style lighting fixed to the camera (like Blender's solid mode): a key light from
// the upper left, a dimmer fill, and ambient, so shapes read the same from every angle.
in vec3 vNormalView;
in vec4 vColor;
out vec4 fragColor;

void main() {
  vec3 n = normalize(vNormalView);
  if (!gl_FrontFacing) n = -n;
  vec3 key = normalize(vec3(-0.4, 0.6, 0.7));
  vec3 fill = normalize(vec3(0.6, -0.2, 0.5));
  float light = 0.35 + 0.6 * max(dot(n, key), 0.0) + 0.2 * max(dot(n, fill), 0.0);
  fragColor = vec4(vColor.rgb * light, vColor.a);
}
