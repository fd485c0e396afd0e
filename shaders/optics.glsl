// The optics of the GPU path: the GLSL twins of include/lucent/optics/fresnel.hpp, dipole.hpp and
// dipole_lut.hpp.
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

// The pole pair of three channels (the classic dipole or d'Eon's better dipole), with the derived
// quantities DipoleChannel::make / makeBetter compute on the CPU (uploaded as uniforms, so the
// derivation has one home).
struct LucentDipole
{
  vec3 sigmaTr;
  vec3 zr;
  vec3 zv;
  vec3 alphaPrime;
  vec3 fluxWeight;     // C_E (classic dipole: 1)
  vec3 fluenceWeight;  // C_phi / D in mm^-1 (classic dipole: 0)
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

// e^x - 1 without cancellation near 0 (GLSL has no expm1): the cubic Taylor polynomial below
// |x| = 1e-2 (truncation x^4 / 24, 4e-8 relative), exp(x) - 1 above (a few ulp of exp over
// |x| >= 1e-2: at most 2e-5 relative, the GL agreement test's tolerance).
vec3 lucentExpm1(vec3 x)
{
  return mix(exp(x) - 1.0, x * (1.0 + x * (0.5 + x * (1.0 / 6.0))), lessThan(abs(x), vec3(1e-2)));
}

// e^{-s d_r} / d_r - e^{-s d_v} / d_v as e^{-s d_r} (D - d_r expm1(-s D)) / (d_r d_v) with
// D = (z_v^2 - z_r^2) / (d_v + d_r): no cancellation far away (DipoleChannel::fluenceDifference).
vec3 lucentFluenceDifference(LucentDipole dipole, float r)
{
  vec3 dr = sqrt(vec3(r * r) + dipole.zr * dipole.zr);
  vec3 dv = sqrt(vec3(r * r) + dipole.zv * dipole.zv);
  vec3 gap = (dipole.zv - dipole.zr) * (dipole.zv + dipole.zr) / (dv + dr);
  vec3 near = exp(-dipole.sigmaTr * dr);
  vec3 value = near * (gap - dr * lucentExpm1(-dipole.sigmaTr * gap)) / (dr * dv);
  return mix(value, vec3(0.0), equal(near, vec3(0.0)));
}

// Rd(r) in mm^-2: Table 1 of Chang et al. 2008 (Jensen et al. 2001 Eq. 4), with the fluence term of
// d'Eon 2012 Eq. 9 where fluenceWeight is not 0 (DipoleChannel::rd).
vec3 lucentDipoleRd(LucentDipole dipole, float r)
{
  vec3 flux = dipole.fluxWeight *
    (lucentDipolePole(dipole.zr, r, dipole.sigmaTr) + lucentDipolePole(dipole.zv, r, dipole.sigmaTr));
  vec3 fluence = dipole.fluenceWeight * lucentFluenceDifference(dipole, r);
  flux += mix(fluence, vec3(0.0), equal(dipole.fluenceWeight, vec3(0.0)));
  return dipole.alphaPrime * (1.0 / (4.0 * kPi)) * flux;
}

// Any profile as its radial table (RadialTable in optics/dipole_lut.hpp, the 1-D texture of Chang
// et al. 2008 Sec. 3): nodes at r_i = rMax (i / (n - 1))^2, linear in u = sqrt(r / rMax), 0 beyond
// rMax. The nodes lie row by row in a 2-D texture, perRow to a row (a 1-D texture is too short).
struct LucentRadialTable
{
  int nodes;
  int perRow;
  float rMax;
};

vec3 lucentTableNode(sampler2D table, LucentRadialTable t, int i)
{
  return texelFetch(table, ivec2(i % t.perRow, i / t.perRow), 0).rgb;
}

vec3 lucentRadialTableRd(sampler2D table, LucentRadialTable t, float r)
{
  if (!(r >= 0.0) || r > t.rMax) return vec3(0.0);
  float u = sqrt(r / t.rMax) * float(t.nodes - 1);
  int i = min(int(u), t.nodes - 2);
  float f = u - float(i);
  return lucentTableNode(table, t, i) * (1.0 - f) + lucentTableNode(table, t, i + 1) * f;
}
