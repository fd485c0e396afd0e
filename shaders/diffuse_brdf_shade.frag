//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::Optics
//LUCENT::Light
// diffuse-brdf's twin, per pixel: subsurface scattering as a diffuse BRDF whose albedo is the
// profile's total diffuse reflectance (Jensen et al. 2001's BRDF approximation),
//   L(x_o, w_o) = exitScale Ft(eta, w_o) / pi * Rd_total E(x_o),
// the dipole sum's limit when E is constant over Rd's reach. Rd_total and exitScale come from the
// C++ profile (optics/profile.hpp), so the two sides share one formula.
in vec3 positionVSOutput;
in vec3 normalVSOutput;
uniform vec3 cameraPosition;
uniform vec3 totalDiffuseReflectance;
uniform float exitScale;

void main()
{
  vec3 n = normalize(normalVSOutput);
  vec3 b = totalDiffuseReflectance * lucentTransmittedIrradiance(positionVSOutput, n);
  float cosOut = dot(n, normalize(cameraPosition - positionVSOutput));
  vec3 radiance = b * (exitScale * lucentFresnelTransmittance(abs(cosOut), eta) / kPi);
  gl_FragData[0] = vec4(radiance, 1.0);
  gl_FragData[1] = vec4(positionVSOutput, 1.0);
  gl_FragData[2] = vec4(n, cosOut);
}
