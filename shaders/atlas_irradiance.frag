//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::Optics
in vec3 positionVSOutput;
in vec3 normalVSOutput;
in float areaVSOutput;
uniform vec3 towardLight;        // unit, world
uniform vec3 lightIrradiance;    // per channel, on a surface facing the light
uniform float eta;
uniform mat4 worldToLight;       // the transform stage 0 used
uniform sampler2D lightDepth;
uniform float shadowBias;        // in light-depth units
void main()
{
  vec3 n = normalize(normalVSOutput);
  float cosN = dot(n, towardLight);
  vec3 e = vec3(0.0);
  if (cosN > 0.0)
  {
    vec4 p = worldToLight * vec4(positionVSOutput, 1.0);
    vec3 q = p.xyz / p.w * 0.5 + 0.5;
    float slope = min(sqrt(max(1.0 - cosN * cosN, 0.0)) / cosN, 10.0);
    float visible = q.z <= texture(lightDepth, q.xy).r + shadowBias * (1.0 + slope) ? 1.0 : 0.0;
    // Eq. 4 for a directional light: E = E_light Ft(eta, w) (n . w), shadowed.
    e = lightIrradiance * (visible * cosN * lucentFresnelTransmittance(cosN, eta));
  }
  vec3 power = e * areaVSOutput;  // E' times the texel area (Eq. 7)
  gl_FragData[0] = vec4(power, power.r + power.g + power.b);
  gl_FragData[1] = vec4(positionVSOutput, 1.0);
}
