#version 330 core
// Soft sky: the exact background colour at u_flat (so the lower part, left
// at the clear colour, stays a predictable reference), easing into a
// slightly cooler tint at the top.
in float v_height;

uniform float u_flat;
uniform vec3 u_bottom;
uniform vec3 u_top;

out vec4 o_color;

void main() {
  o_color = vec4(mix(u_bottom, u_top, smoothstep(u_flat, 1.0, v_height)), 1.0);
}
