#version 330 core
// Lambert + ambient + a little Blinn-Phong specular, light fixed to the
// camera so every view is lit the same way regardless of where it looks from.
in vec3 v_normal;
in vec3 v_position;
in vec4 v_color;

uniform vec3 u_light_dir;  // view space, unit, pointing towards the light
uniform float u_specular;

out vec4 o_color;

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;  // back faces of translucent boxes are seen too
  vec3 to_eye = normalize(-v_position);
  float diffuse = max(dot(n, u_light_dir), 0.0);
  float fill = 0.18 * max(dot(n, -u_light_dir), 0.0);  // soft bounce light
  float spec = pow(max(dot(n, normalize(u_light_dir + to_eye)), 0.0), 40.0);
  vec3 rgb = v_color.rgb * (0.32 + 0.62 * diffuse + fill) + vec3(u_specular * spec);
  o_color = vec4(min(rgb, vec3(1.0)), v_color.a);
}
