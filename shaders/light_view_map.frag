//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::MapVariant
//LUCENT::Optics
// The object seen from the light, one draw: per texel the first hit (mm), a tag (0 = uncovered)
// and rho = E / |n_geom . axis|, E = Ft(eta, w) (n . w) E_light, the light's uniforms in
// millimetres (light_source.glsl; TranslucentShadowMap does the same on the CPU).
// The hybrid's translucent shadow map tags a covered texel 1 (Chang et al. 2008 Sec. 4.2); taulut's
// voxel-number map tags it 1 + its surface voxel's number (Mochida et al. 2016 Sec. 2.2, Eq. 2).
#if LUCENT_VOXEL_NUMBER
//LUCENT::Voxel
float lucentMapTag(vec3 p) { return 1.0 + float(lucentSurfaceNumber(p)); }
#else
float lucentMapTag(vec3 p) { return 1.0; }
#endif
//LUCENT::LightSource
in vec3 positionMmOutput;
in vec3 normalVSOutput;
uniform vec3 mapAxis;          // from the light into the object
uniform float eta;
uniform float maxObliquity;    // atlas::kMaxObliquity
void main()
{
  vec3 n = normalize(normalVSOutput);
  float cosN = dot(n, lucentTowardLight(positionMmOutput));
  vec3 e = cosN > 0.0 ? lucentIrradianceFacing(positionMmOutput) *
                            (cosN * lucentFresnelTransmittance(cosN, eta))
                      : vec3(0.0);
  vec3 faceNormal = normalize(cross(dFdx(positionMmOutput), dFdy(positionMmOutput)));
  float obliquity = min(maxObliquity, 1.0 / max(abs(dot(faceNormal, mapAxis)), 1e-12));
  gl_FragData[0] = vec4(positionMmOutput, lucentMapTag(positionMmOutput));
  gl_FragData[1] = vec4(e * obliquity, 1.0);
}
