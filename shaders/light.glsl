// The light as a surface point receives it (Chang et al. 2008 Eq. 4): irradiance E =
// E_light Ft(eta, w) (n . w), Fresnel-transmitted into the medium, zero in the light's shadow (the
// depth map of stage 0, orthographic for a directional light, perspective for a point; its bias
// growing with the slope). Needs //LUCENT::Optics before it and comes after light_source.glsl
// (the pass pastes both); positions in world coordinates.
uniform float eta;
uniform mat4 worldToLight;       // the transform stage 0 used
uniform sampler2D lightDepth;
uniform float shadowBias;        // in light-depth units

vec3 lucentTransmittedIrradiance(vec3 position, vec3 n)
{
  float cosN = dot(n, lucentTowardLight(position));
  if (cosN <= 0.0) return vec3(0.0);
  vec4 p = worldToLight * vec4(position, 1.0);
  vec3 q = p.xyz / p.w * 0.5 + 0.5;
  float slope = min(sqrt(max(1.0 - cosN * cosN, 0.0)) / cosN, 10.0);
  float visible = q.z <= texture(lightDepth, q.xy).r + shadowBias * (1.0 + slope) ? 1.0 : 0.0;
  return lucentIrradianceFacing(position) * (visible * cosN * lucentFresnelTransmittance(cosN, eta));
}
