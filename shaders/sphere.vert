#version 330 core
// Sphere impostor: one camera-facing quad per particle, just large enough to
// hold the sphere's silhouette; the fragment shader ray-casts the sphere.
// Replaces a tessellated sphere per particle (~300 triangles each). Each
// sphere comes as four vertices with the same attributes (render/sphere_pass.hpp).
layout(location = 0) in vec4 i_sphere;  // centre xyz in model axes, radius w (m)
layout(location = 1) in vec4 i_color;

uniform mat4 u_model_view;  // model axes -> view (rigid)
uniform mat4 u_proj;

out vec3 v_ray;             // view-space point on the quad (the ray through it)
flat out vec4 v_sphere;     // view-space centre, radius
flat out vec4 v_color;

void main() {
  vec3 c = (u_model_view * vec4(i_sphere.xyz, 1.0)).xyz;
  float r = i_sphere.w;
  float d = length(c);
  int k = gl_VertexID & 3;  // which corner of the sphere's quad
  vec2 corner = vec2(float(k & 1), float(k >> 1)) * 2.0 - 1.0;
  // Quad through the centre, perpendicular to the eye->centre axis: the
  // silhouette cone cuts it in a circle of radius r d / sqrt(d^2 - r^2).
  vec3 axis = c / max(d, 1e-20);
  vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 u = normalize(cross(helper, axis));
  vec3 v = cross(axis, u);
  float half_size = d > r * 1.001 ? r * d / sqrt(d * d - r * r) : 0.0;  // eye inside: skip
  // A little extra so the anti-aliased rim is not clipped by the quad.
  half_size *= 1.15;
  vec3 p = c + (u * corner.x + v * corner.y) * half_size;
  v_ray = p;
  v_sphere = vec4(c, r);
  v_color = i_color;
  gl_Position = u_proj * vec4(p, 1.0);
}
