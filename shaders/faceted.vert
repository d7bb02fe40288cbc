#version 330 core
// Instanced flat-faced shapes (bone octahedra: one normal per triangle, shape_meshes.h):
// shaded.frag's light is the same at every pixel of such a face, so it is found here, for
// the face seen from the front and from the back, and handed on flat (nothing to interpolate:
// llvmpipe sets up and blends these faces for less per pixel).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in mat4 aModel;   // locations 2..5
layout(location = 6) in vec4 aColor;

uniform mat4 uViewProjection;
uniform mat4 uView;

flat out vec4 vFront;  // the colour lit as shaded.frag lights a front face
flat out vec4 vBack;   // and a back face (its normal turned round)

float light(vec3 n) {  // shaded.frag's studio light
  vec3 key = normalize(vec3(-0.4, 0.6, 0.7));
  vec3 fill = normalize(vec3(0.6, -0.2, 0.5));
  return 0.35 + 0.6 * max(dot(n, key), 0.0) + 0.2 * max(dot(n, fill), 0.0);
}

void main() {
  // Instance matrices are rotation * uniform scale, so mat3(model) keeps normals perpendicular.
  vec3 n = normalize(mat3(uView) * (mat3(aModel) * aNormal));
  vFront = vec4(aColor.rgb * light(n), aColor.a);
  vBack = vec4(aColor.rgb * light(-n), aColor.a);
  gl_Position = uViewProjection * aModel * vec4(aPosition, 1.0);
}
