#version 330 core
#extension GL_ARB_gpu_shader5 : enable
// FXAA as a GL pass: the CPU version in src/render/fxaa.cpp (after T. Lottes,
// "FXAA", NVIDIA 2009, the 3.11 quality path) line for line, on whole texels
// (texelFetch) with the same byte luma, thresholds and walk. `precise` (no
// fused multiply-adds, no reordering) matters: the luma are multiples of
// 1/255, the walk's comparisons tie often, and a contracted sum tips them;
// with it llvmpipe gives the CPU's bytes exactly. Rows are GL's (y up).
uniform sampler2D u_frame;  // the drawn frame, RGBA8; alpha < 1 marks text

out vec4 o_color;

const float kSubpix = 0.25;
const int kRel = 169;  // kEdgeThreshold 0.166 * 1024, truncated as fxaa.cpp does
const int kMin = 21;   // kEdgeThresholdMin 0.0833 * 255, truncated
const int kSteps[6] = int[6](1, 1, 2, 2, 4, 8);

ivec2 g_size;

ivec4 px(ivec2 p) {
  return ivec4(round(texelFetch(u_frame, clamp(p, ivec2(0), g_size - 1), 0) * 255.0));
}
int luma_byte(ivec2 p) {
  ivec4 c = px(p);
  return (77 * c.r + 150 * c.g + 29 * c.b + 128) >> 8;  // Rec. 601 weights in 1/256
}
float l(ivec2 p) { return float(luma_byte(p)) * (1.0 / 255.0); }

bool edge(ivec2 p) {
  int m = luma_byte(p), a = luma_byte(p + ivec2(-1, 0)), b = luma_byte(p + ivec2(1, 0));
  int c = luma_byte(p + ivec2(0, 1)), d = luma_byte(p + ivec2(0, -1));
  int hi = max(max(max(m, a), max(b, c)), d), lo = min(min(min(m, a), min(b, c)), d);
  return hi - lo >= max((hi * kRel) >> 10, kMin);
}

bool marked_near(ivec2 p) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (px(p + ivec2(dx, dy)).a != 255) return true;
  return false;
}

// fxaa.cpp's blend(): how far to move towards the neighbour `across`; 0 = keep.
float blend(ivec2 p, out ivec2 across) {
  across = ivec2(0);
  precise float m = l(p), n = l(p + ivec2(0, 1)), s = l(p + ivec2(0, -1)), e = l(p + ivec2(1, 0)), w = l(p + ivec2(-1, 0));
  precise float range = max(max(max(m, n), max(s, e)), w) - min(min(min(m, n), min(s, e)), w);
  if (range <= 0.0 || marked_near(p)) return 0.0;
  precise float nw = l(p + ivec2(-1, 1)), ne = l(p + ivec2(1, 1)), sw = l(p + ivec2(-1, -1)), se = l(p + ivec2(1, -1));
  precise float lowpass = (2.0 * (n + s + e + w) + (nw + ne + sw + se)) / 12.0;
  precise float sub = clamp(abs(lowpass - m) / range, 0.0, 1.0);
  sub = (-2.0 * sub + 3.0) * sub * sub;
  precise float sub_offset = sub * sub * kSubpix;

  precise float edge_h = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
  precise float edge_v = abs(nw + ne - 2.0 * n) + 2.0 * abs(w + e - 2.0 * m) + abs(sw + se - 2.0 * s);
  bool horizontal = edge_h >= edge_v;
  precise float l_neg = horizontal ? s : w, l_pos = horizontal ? n : e;
  precise float g_neg = abs(l_neg - m), g_pos = abs(l_pos - m);
  int sgn = g_pos >= g_neg ? 1 : -1;
  across = horizontal ? ivec2(0, sgn) : ivec2(sgn, 0);
  precise float avg = 0.5 * ((sgn > 0 ? l_pos : l_neg) + m);
  precise float threshold = 0.25 * max(g_neg, g_pos);

  ivec2 along = horizontal ? ivec2(1, 0) : ivec2(0, 1);
  int dist_n = 0, dist_p = 0;
  precise float end_n = 0.0, end_p = 0.0;
  bool done_n = false, done_p = false;
  for (int i = 0; i < 6; ++i) {
    if (!done_n) {
      dist_n += kSteps[i];
      ivec2 q = p - along * dist_n;
      end_n = 0.5 * (l(q) + l(q + across)) - avg;
      done_n = abs(end_n) >= threshold;
    }
    if (!done_p) {
      dist_p += kSteps[i];
      ivec2 q = p + along * dist_p;
      end_p = 0.5 * (l(q) + l(q + across)) - avg;
      done_p = abs(end_p) >= threshold;
    }
    if (done_n && done_p) break;
  }
  bool nearer_n = dist_n < dist_p;
  bool good = ((nearer_n ? end_n : end_p) < 0.0) != (m - avg < 0.0);
  precise float edge_offset = good ? 0.5 - float(min(dist_n, dist_p)) / float(dist_n + dist_p) : 0.0;
  return max(edge_offset, sub_offset);
}

void main() {
  g_size = textureSize(u_frame, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec4 a = px(p);
  vec3 rgb = vec3(a.rgb);
  if (edge(p)) {
    ivec2 across;
    float t = blend(p, across);
    if (t > 0.0) rgb = floor(vec3(a.rgb) + vec3(px(p + across).rgb - a.rgb) * t + 0.5);  // lround
  }
  o_color = vec4(rgb / 255.0, 1.0);
}
