#version 330 core
// One triangle over the whole frame: FXAA's post pass (fxaa.frag).
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(p, 0.0, 1.0);
}
