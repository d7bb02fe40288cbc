#version 330 core
// Meshes, skinned in the vertex shader (glTF: v = sum w_i * world(joint_i) * IBM_i * v).
// Per joint, texture buffer uJoints holds kJointTexels RGBA32F texels (written by
// render/mesh_renderer.cpp): the skinning matrix M (4 columns), the upper 3x3 of its inverse
// transpose (3), the rigid part as a unit dual quaternion (real, dual) and the remaining
// scale/shear S = rigid^-1 * M (3 columns). Hundreds of joints
// fit (a texture buffer holds at least 64k texels). The same program writes world positions
// and normals through transform feedback, which is how tests compare it with the CPU.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexcoord;
layout(location = 3) in uvec4 aJoints0;   // influences 0..3, largest weight first
layout(location = 4) in uvec4 aJoints1;   // influences 4..7
layout(location = 5) in vec4 aWeights0;
layout(location = 6) in vec4 aWeights1;

uniform samplerBuffer uJoints;
uniform int uJointOffset;             // the instance's skin starts at this joint slot
uniform int uSkinning;                 // 0: rigid (uModel), 1: linear blend, 2: dual quaternion
uniform mat4 uModel;                   // unskinned instances: the joint's world matrix
uniform mat3 uModelNormal;             // its inverse transpose
// Morph targets: uMorphDeltas holds target k's position delta of vertex v at texel
// k * uVertexCount + v, normal deltas after all position deltas (uMorphHasNormals).
uniform samplerBuffer uMorphDeltas;
uniform int uMorphCount;
uniform int uVertexCount;
uniform bool uMorphHasNormals;
uniform float uMorphWeights[32];
uniform int uWeightJoint;              // heat colours: this skin joint's weight; -1 = off
uniform mat4 uViewProjection;
uniform mat4 uView;
// Barr's bend / twist / taper (deform/axis_deformers.h, issue 22) after skinning, in world
// space, for instances whose whole stack is such deformers (MeshFrame::gpuDeformers): each
// is taken into its own space (uAxisToLocal), deformed by the closed forms the CPU uses and
// brought back (uAxisToWorld). Normals: the deformed cross product of two tangents, by
// central differences of the same map (the CPU recomputes area-weighted ones instead).
const int kMaxAxisDeformers = 4;
uniform int uAxisCount;                         // 0: no deformers
uniform ivec2 uAxisKind[kMaxAxisDeformers];     // x: 0 bend, 1 twist, 2 taper; y: axis 0 X, 1 Y, 2 Z
uniform vec3 uAxisOrigin[kMaxAxisDeformers];
uniform vec3 uAxisRange[kMaxAxisDeformers];     // low, high, amount
uniform mat4 uAxisToLocal[kMaxAxisDeformers];
uniform mat4 uAxisToWorld[kMaxAxisDeformers];

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec3 vNormalView;
out vec2 vTexcoord;
out float vHeat;

const int kJointTexels = 12;

vec4 texel(int joint, int k) { return texelFetch(uJoints, (uJointOffset + joint) * kJointTexels + k); }

mat4 skinMatrix(int j) { return mat4(texel(j, 0), texel(j, 1), texel(j, 2), texel(j, 3)); }
mat3 skinNormalMatrix(int j) { return mat3(texel(j, 4).xyz, texel(j, 5).xyz, texel(j, 6).xyz); }
mat3 scaleMatrix(int j) { return mat3(texel(j, 9).xyz, texel(j, 10).xyz, texel(j, 11).xyz); }

vec3 rotateByQuat(vec4 q, vec3 v) { return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v); }

vec3 axisDeform(int i, vec3 p) {
  int ia = uAxisKind[i].y, ib = (ia + 1) % 3, ic = (ia + 2) % 3;
  vec3 q = p - uAxisOrigin[i];
  float a = q[ia], b = q[ib], c = q[ic];
  float low = uAxisRange[i].x, range = uAxisRange[i].y - uAxisRange[i].x, amount = uAxisRange[i].z;
  float h = clamp(a - low, 0.0, range);
  float f = h / range;
  float a2 = a, b2 = b, c2 = c;
  if (uAxisKind[i].x == 1) {  // twist: b turns towards c
    float angle = amount * f;
    float cs = cos(angle), sn = sin(angle);
    b2 = cs * b - sn * c;
    c2 = sn * b + cs * c;
  } else if (uAxisKind[i].x == 2) {  // taper
    float scale = 1.0 + (amount - 1.0) * f;
    b2 = b * scale;
    c2 = c * scale;
  } else if (a > low) {  // bend: an arc of curvature amount / range, the rest along its end tangent
    float k = amount / range;
    float theta = k * h;
    float cs = cos(theta), sn = sin(theta);
    float sinOverK = abs(theta) < 1e-4 ? h * (1.0 - theta * theta / 6.0) : sn / k;
    float halfSin = sin(0.5 * theta);
    float versOverK = abs(theta) < 1e-4 ? h * theta * 0.5 : 2.0 * halfSin * halfSin / k;
    float beyond = a - low - h;
    a2 = low + sinOverK - b * sn + beyond * cs;
    b2 = versOverK + b * cs + beyond * sn;
  }
  vec3 out3;
  out3[ia] = a2;
  out3[ib] = b2;
  out3[ic] = c2;
  return out3 + uAxisOrigin[i];
}

vec3 axisStack(vec3 world) {
  for (int i = 0; i < uAxisCount && i < kMaxAxisDeformers; ++i)
    world = (uAxisToWorld[i] * vec4(axisDeform(i, (uAxisToLocal[i] * vec4(world, 1.0)).xyz), 1.0)).xyz;
  return world;
}

void main() {
  vec3 position = aPosition;
  vec3 normal = aNormal;
  for (int k = 0; k < uMorphCount; ++k) {
    float w = uMorphWeights[k];
    position += w * texelFetch(uMorphDeltas, k * uVertexCount + gl_VertexID).xyz;
    if (uMorphHasNormals)
      normal += w * texelFetch(uMorphDeltas, (uMorphCount + k) * uVertexCount + gl_VertexID).xyz;
  }

  int joints[8] = int[8](int(aJoints0.x), int(aJoints0.y), int(aJoints0.z), int(aJoints0.w),
                         int(aJoints1.x), int(aJoints1.y), int(aJoints1.z), int(aJoints1.w));
  float weights[8] = float[8](aWeights0.x, aWeights0.y, aWeights0.z, aWeights0.w,
                              aWeights1.x, aWeights1.y, aWeights1.z, aWeights1.w);
  vec3 world;
  vec3 worldNormal;
  float heat = 0.0;
  if (uSkinning == 1) {
    world = vec3(0.0);
    worldNormal = vec3(0.0);
    for (int i = 0; i < 8; ++i) {
      if (weights[i] == 0.0) continue;
      world += weights[i] * (skinMatrix(joints[i]) * vec4(position, 1.0)).xyz;
      worldNormal += weights[i] * (skinNormalMatrix(joints[i]) * normal);
      if (joints[i] == uWeightJoint) heat += weights[i];
    }
  } else if (uSkinning == 2) {
    // Kavan's two phases: blend the scale/shear parts linearly, then the rigid parts as
    // dual quaternions with signs aligned to the first influence (shortest arc).
    vec4 pivot = texel(joints[0], 7);
    vec4 real = vec4(0.0), dual = vec4(0.0);
    mat3 scale = mat3(0.0);
    for (int i = 0; i < 8; ++i) {
      if (weights[i] == 0.0) continue;
      vec4 r = texel(joints[i], 7);
      float w = dot(r, pivot) < 0.0 ? -weights[i] : weights[i];
      real += w * r;
      dual += w * texel(joints[i], 8);
      scale += weights[i] * scaleMatrix(joints[i]);
      if (joints[i] == uWeightJoint) heat += weights[i];
    }
    float len = length(real);
    real /= len;
    dual /= len;
    // Translation of a unit dual quaternion: 2 * dual * conjugate(real).
    vec3 t = 2.0 * (real.w * dual.xyz - dual.w * real.xyz + cross(real.xyz, dual.xyz));
    world = rotateByQuat(real, scale * position) + t;
    // Normals: the inverse transpose of the blended stretch, then the blended rotation.
    worldNormal = rotateByQuat(real, transpose(inverse(scale)) * normal);
  } else {
    world = (uModel * vec4(position, 1.0)).xyz;
    worldNormal = uModelNormal * normal;
    // A skinned primitive deformed on the CPU (drawn rigid, influences still bound) shows its
    // weights; a rigid instance follows one joint: all or nothing.
    if (aWeights0.x > 0.0) {
      for (int i = 0; i < 8; ++i)
        if (joints[i] == uWeightJoint) heat += weights[i];
    } else {
      heat = uWeightJoint >= 0 ? 1.0 : 0.0;
    }
  }
  float nl = length(worldNormal);
  worldNormal = nl > 0.0 ? worldNormal / nl : vec3(0.0);
  if (uAxisCount > 0) {
    // Two tangents t1, t2 with t1 x t2 = n, mapped by central differences (1 mm).
    vec3 t1 = normalize(abs(worldNormal.x) < 0.9 ? cross(worldNormal, vec3(1.0, 0.0, 0.0))
                                                 : cross(worldNormal, vec3(0.0, 1.0, 0.0)));
    vec3 t2 = cross(worldNormal, t1);
    const float e = 1e-3;
    vec3 d1 = axisStack(world + e * t1) - axisStack(world - e * t1);
    vec3 d2 = axisStack(world + e * t2) - axisStack(world - e * t2);
    vec3 n = cross(d1, d2);
    world = axisStack(world);
    worldNormal = length(n) > 0.0 && nl > 0.0 ? normalize(n) : worldNormal;
  }

  vWorldPosition = world;
  vWorldNormal = worldNormal;
  vNormalView = mat3(uView) * worldNormal;
  vTexcoord = aTexcoord;
  vHeat = heat;
  gl_Position = uViewProjection * vec4(world, 1.0);
}
