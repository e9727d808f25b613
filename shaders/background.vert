#version 330 core
// A quad over the upper part of the viewport, from height u_flat to the top;
// below it the frame keeps its clear colour, so no vertex buffer is needed
// and the flat lower part costs no fill.
uniform float u_flat;

out float v_height;  // 0 at the bottom edge of the viewport, 1 at the top

void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  v_height = mix(u_flat, 1.0, corner.y);
  gl_Position = vec4(corner.x * 2.0 - 1.0, v_height * 2.0 - 1.0, 0.0, 1.0);
}
