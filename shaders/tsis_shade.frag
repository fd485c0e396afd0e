//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::ProfileForm
//LUCENT::Optics
#if LUCENT_LOCAL_TERM
//LUCENT::RingFilter
uniform vec3 worldCentre;  // the world point at the millimetre frame's origin
#endif
// Stage 3, per pixel (Chang et al. 2008 Eq. 10-11):
//   L(x_o, w_o) = exitScale Ft(eta, w_o) / pi * sum_i w_i Rd(|x_i - x_o|),
// Rd from the profile's radial table (the paper's 1-D texture), or in closed form for a pole pair
// with rd=exact: the pass compiles one variant each (LUCENT_CLOSED_FORM), since a run-time choice
// inside the loop made llvmpipe evaluate both. exitScale is Profile::exitScale (1 / (1 - 2 C1) for
// the models after the dipole). The hybrid (LUCENT_LOCAL_TERM, Sec. 4) sums Rd Wg over the samples
// and adds the local term B_l of ring_filter.glsl.
in vec3 positionVSOutput;
in vec3 normalVSOutput;
uniform sampler2D samplePosition;  // world, w = 1 for a drawn sample
uniform sampler2D sampleWeight;    // E' / (p N) per channel
uniform int sampleCount;
uniform int samplesPerRow;
uniform float mmPerUnit;
uniform vec3 cameraPosition;
uniform float eta;
uniform float exitScale;
#if LUCENT_CLOSED_FORM
uniform LucentDipole dipole;
vec3 profileRd(float r) { return lucentDipoleRd(dipole, r); }
#else
uniform sampler2D profileTable;
uniform LucentRadialTable profile;
vec3 profileRd(float r) { return lucentRadialTableRd(profileTable, profile, r); }
#endif

void main()
{
  vec3 sum = vec3(0.0);
  for (int i = 0; i < sampleCount; ++i)
  {
    ivec2 c = ivec2(i % samplesPerRow, i / samplesPerRow);
    vec4 xi = texelFetch(samplePosition, c, 0);
    float r = distance(xi.xyz, positionVSOutput) * mmPerUnit;
    sum += texelFetch(sampleWeight, c, 0).rgb * profileRd(r);
  }
#if LUCENT_LOCAL_TERM
  sum += lucentLocalTerm((positionVSOutput - worldCentre) * mmPerUnit);
#endif
  vec3 n = normalize(normalVSOutput);
  float cosOut = dot(n, normalize(cameraPosition - positionVSOutput));
  vec3 radiance = sum * (exitScale * lucentFresnelTransmittance(abs(cosOut), eta) / kPi);
  gl_FragData[0] = vec4(radiance, 1.0);
  gl_FragData[1] = vec4(positionVSOutput, 1.0);
  gl_FragData[2] = vec4(n, cosOut);
}
