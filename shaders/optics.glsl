// The optics of the GPU path: the GLSL twins of include/lucent/optics/fresnel.hpp and dipole.hpp.
// The constants (kPi, kFdr*) are generated from include/lucent/optics/constants.hpp at build time;
// tests/gl/test_glsl_agreement.cpp evaluates every function here on the GPU and compares with the C++.

// Unpolarised Fresnel reflectance of a smooth dielectric (fresnelReflectance in fresnel.hpp).
float lucentFresnelReflectance(float cosIncident, float eta)
{
  float cosI = clamp(cosIncident, 0.0, 1.0);
  if (cosI <= 0.0) return 1.0;
  float sin2T = (1.0 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0) return 1.0;
  float cosT = sqrt(1.0 - sin2T);
  float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

// Ft = 1 - Fr (Chang et al. 2008 Eq. 2, 4).
float lucentFresnelTransmittance(float cosIncident, float eta)
{
  return 1.0 - lucentFresnelReflectance(cosIncident, eta);
}

// Diffuse Fresnel reflectance, Jensen et al. 2001 Eq. 5 fit.
float lucentDiffuseFresnelReflectance(float eta)
{
  return kFdrInvEta2 / (eta * eta) + kFdrInvEta / eta + kFdrConst + kFdrEta * eta;
}

// The dipole of three channels, with the derived quantities DipoleChannel::make computes on the CPU
// (uploaded as uniforms, so the derivation has one home).
struct LucentDipole
{
  vec3 sigmaTr;
  vec3 zr;
  vec3 zv;
  vec3 alphaPrime;
};

// z (1 + sigma_tr d) e^{-sigma_tr d} / d^3, d = sqrt(r^2 + z^2) (DipoleChannel::pole).
vec3 lucentDipolePole(vec3 z, float r, vec3 sigmaTr)
{
  vec3 d = sqrt(vec3(r * r) + z * z);
  vec3 sd = sigmaTr * d;
  vec3 e = exp(-sd);
  // e == 0 where sd overflows: keep (1 + sd) e from becoming inf * 0.
  return mix(z * (1.0 + sd) * e / (d * d * d), vec3(0.0), equal(e, vec3(0.0)));
}

// Rd(r) in mm^-2, Table 1 of Chang et al. 2008 (Jensen et al. 2001 Eq. 4).
vec3 lucentDipoleRd(LucentDipole dipole, float r)
{
  return dipole.alphaPrime * (1.0 / (4.0 * kPi)) *
    (lucentDipolePole(dipole.zr, r, dipole.sigmaTr) + lucentDipolePole(dipole.zv, r, dipole.sigmaTr));
}
