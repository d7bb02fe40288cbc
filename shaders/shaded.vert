#version 330 core
// Instanced solid shapes (bone octahedra, joint spheres): one model matrix and colour per instance.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in mat4 aModel;   // locations 2..5
layout(location = 6) in vec4 aColor;

uniform mat4 uViewProjection;
uniform mat4 uView;

out vec3 vNormalView;
out vec4 vColor;

void main() {
  // Instance matrices are rotation * uniform scale, so mat3(model) keeps normals perpendicular.
  vNormalView = mat3(uView) * (mat3(aModel) * aNormal);
  vColor = aColor;
  gl_Position = uViewProjection * aModel * vec4(aPosition, 1.0);
}
