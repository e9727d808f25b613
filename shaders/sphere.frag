#version 330 core
// Ray-cast sphere with the same lighting as mesh.frag and true depth, so the
// spheres intersect arrows and each other as tessellated ones would. With
// MSAA the rim goes out as alpha-to-coverage (blending off), else a hard edge.
in vec3 v_ray;
flat in vec4 v_sphere;
flat in vec4 v_color;

uniform mat4 u_proj;
uniform vec3 u_light_dir;  // view space, unit, pointing towards the light
uniform float u_specular;
uniform bool u_coverage;   // true: alpha is the rim coverage (alpha-to-coverage)

out vec4 o_color;

void main() {
  vec3 dir = normalize(v_ray);
  vec3 c = v_sphere.xyz;
  float r = v_sphere.w;
  float t_mid = dot(c, dir);
  vec3 closest = dir * t_mid;
  float miss = length(c - closest);  // ray's distance from the centre
  // Coverage of the rim, from how fast `miss` changes per pixel.
  float px = max(fwidth(miss), 1e-12);
  float coverage = clamp((r - miss) / px + 0.5, 0.0, 1.0);
  if (u_coverage ? coverage <= 0.0 : miss > r) discard;
  float m = min(miss, r);
  vec3 hit = dir * (t_mid - sqrt(max(r * r - m * m, 0.0)));
  vec3 n = normalize(hit - c);

  vec3 to_eye = normalize(-hit);
  float diffuse = max(dot(n, u_light_dir), 0.0);
  float fill = 0.18 * max(dot(n, -u_light_dir), 0.0);  // soft bounce light
  float spec = pow(max(dot(n, normalize(u_light_dir + to_eye)), 0.0), 40.0);
  vec3 rgb = v_color.rgb * (0.32 + 0.62 * diffuse + fill) + vec3(u_specular * spec);
  o_color = vec4(min(rgb, vec3(1.0)), u_coverage ? coverage : 1.0);

  vec4 clip = u_proj * vec4(hit, 1.0);
  gl_FragDepth = (clip.z / clip.w) * 0.5 + 0.5;  // default depth range [0, 1]
}
