//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::Optics
//LUCENT::Voxel
// The irradiance map and the voxel-number map of Mochida et al. 2016 Sec. 2.2 in one draw: per
// texel the first hit (mm), 1 + its surface voxel's number (0 = uncovered), and rho = E / |n_geom .
// axis|, E = Ft(eta, w) (n . w) I (Eq. 2) for the directional light (TranslucentShadowMap).
in vec3 positionMmOutput;
in vec3 normalVSOutput;
uniform vec3 towardLight;      // unit
uniform vec3 lightIrradiance;  // per channel, on a surface facing the light
uniform float eta;
uniform float maxObliquity;    // atlas::kMaxObliquity
void main()
{
  vec3 n = normalize(normalVSOutput);
  float cosN = dot(n, towardLight);
  vec3 e = cosN > 0.0 ? lightIrradiance * (cosN * lucentFresnelTransmittance(cosN, eta)) : vec3(0.0);
  vec3 faceNormal = normalize(cross(dFdx(positionMmOutput), dFdy(positionMmOutput)));
  float obliquity = min(maxObliquity, 1.0 / max(abs(dot(faceNormal, towardLight)), 1e-12));
  gl_FragData[0] = vec4(positionMmOutput, 1.0 + float(lucentSurfaceNumber(positionMmOutput)));
  gl_FragData[1] = vec4(e * obliquity, 1.0);
}
