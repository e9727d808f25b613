#version 330 core
// Instanced lit mesh: unit shape scaled/rotated/placed by a per-instance model
// matrix, so one cylinder/cone/sphere/cube mesh serves every item.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 i_model;  // locations 2..5
layout(location = 6) in vec4 i_color;

uniform mat4 u_view;
uniform mat4 u_proj;

out vec3 v_normal;    // view space
out vec3 v_position;  // view space
out vec4 v_color;

void main() {
  mat4 model_view = u_view * i_model;
  vec4 p = model_view * vec4(a_position, 1.0);
  v_position = p.xyz;
  // Inverse-transpose keeps normals right under the non-uniform box/shaft scale.
  v_normal = transpose(inverse(mat3(model_view))) * a_normal;
  v_color = i_color;
  gl_Position = u_proj * p;
}
