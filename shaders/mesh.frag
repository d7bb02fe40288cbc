#version 330 core
// Meshes lit like Blender's solid mode: a key light from the camera's side (upper left,
// fixed to the view) plus hemispheric ambient (sky above, ground below, in world space),
// base colour factor times texture, both faces lit. Or heat colours of a joint's weights.
// Or an onion-skin ghost: a flat tint, lit a little, more opaque towards the silhouette
// (a fresnel rim), so the shape reads without hiding what is behind it.
in vec3 vWorldNormal;
in vec3 vNormalView;
in vec2 vTexcoord;
in float vHeat;
out vec4 fragColor;

uniform vec4 uBaseColor;
uniform bool uHasTexture;
uniform sampler2D uBaseColorTexture;
uniform bool uShowWeights;
uniform bool uGhost;
uniform vec4 uGhostColor;  // rgb tint, alpha = the ghost's opacity

// Blue (0) -> cyan -> green -> yellow -> red (1), as weight painting shows it.
vec3 heatColor(float w) {
  w = clamp(w, 0.0, 1.0);
  return clamp(vec3(4.0 * w - 2.0, 2.0 - abs(4.0 * w - 2.0), 2.0 - 4.0 * w), 0.0, 1.0);
}

void main() {
  vec3 n = normalize(vNormalView);
  vec3 worldN = normalize(vWorldNormal);
  if (!gl_FrontFacing) {
    n = -n;
    worldN = -worldN;
  }
  if (uGhost) {
    float rim = 1.0 - abs(n.z);  // 0 facing the camera, 1 at the silhouette
    float lit = 0.65 + 0.35 * max(dot(n, normalize(vec3(-0.4, 0.6, 0.7))), 0.0);
    fragColor = vec4(uGhostColor.rgb * lit + vec3(0.3) * rim * rim, uGhostColor.a * mix(0.85, 1.0, rim));
    return;
  }
  vec4 base = uBaseColor;
  if (uHasTexture) base *= texture(uBaseColorTexture, vTexcoord);
  if (uShowWeights) base = vec4(heatColor(vHeat), 1.0);
  vec3 key = normalize(vec3(-0.4, 0.6, 0.7));
  float diffuse = max(dot(n, key), 0.0);
  float hemisphere = 0.5 + 0.5 * worldN.y;  // 1 facing up, 0 facing down
  vec3 ambient = mix(vec3(0.22, 0.21, 0.20), vec3(0.42, 0.44, 0.48), hemisphere);
  vec3 specular = vec3(0.08) * pow(max(dot(n, normalize(key + vec3(0, 0, 1))), 0.0), 24.0);
  fragColor = vec4(base.rgb * (ambient + 0.75 * diffuse) + specular, 1.0);
}
