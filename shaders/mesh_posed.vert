#version 330 core
// Meshes already morphed, skinned and deformed on the CPU (the software rasteriser path,
// MeshRenderer::cpuDeformation): world-space positions and normals in, the same outputs as
// mesh.vert with no skinning, an identity model and no morphs or deformers. A software
// rasteriser runs every branch of mesh.vert for every vertex (its skinning, morph and
// deformer code cost more than the rest of the frame's mesh pass); this runs none of them.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexcoord;

uniform mat4 uViewProjection;
uniform mat4 uView;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec3 vNormalView;
out vec2 vTexcoord;
out float vHeat;

void main() {
  float nl = length(aNormal);
  vec3 worldNormal = nl > 0.0 ? aNormal / nl : vec3(0.0);
  vWorldPosition = aPosition;
  vWorldNormal = worldNormal;
  vNormalView = mat3(uView) * worldNormal;
  vTexcoord = aTexcoord;
  vHeat = 0.0;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
