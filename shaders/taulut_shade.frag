//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::Optics
//LUCENT::Voxel
// The voxel optical-thickness LUT, stage 2, per pixel (Mochida et al. 2016 Eq. 1-3, as
// voxel/tau_lut_radiance.hpp states them): B(x_o) = (sigma_o^2 / 2 pi) sum over the ring filter's
// taps of share M_k rho e^{-tau} / f(r_k), then L = Ft(eta, w_o) B / pi.
in vec3 positionVSOutput;
in vec3 normalVSOutput;
uniform vec3 worldCentre;
uniform float mmPerUnit;
uniform vec3 cameraPosition;
uniform float eta;
uniform sampler2D mapPosition;  // first hit (mm); w: 1 + surface voxel number, 0 = uncovered
uniform sampler2D mapDensity;   // rho per channel
uniform int mapResolution;
uniform vec3 mapCentre;
uniform vec3 mapT;
uniform vec3 mapB;
uniform float mapHalfExtent;
uniform float mapTexel;
const int kMaxStrata = 17;      // the centre and the GPU twin's most rings (taulut's `rings` bound)
uniform int rings;
uniform int perRing;
uniform float ringRadius[kMaxStrata];
uniform vec3 ringMass[kMaxStrata];
uniform vec3 ringProfile[kMaxStrata];
uniform int rotated;

vec3 tapSum(vec2 uv, int k, float share, int outNumber, vec3 xo)
{
  ivec2 c = ivec2(floor((uv + vec2(mapHalfExtent)) / mapTexel));
  if (any(lessThan(c, ivec2(0))) || any(greaterThanEqual(c, ivec2(mapResolution)))) return vec3(0.0);
  vec4 hit = texelFetch(mapPosition, c, 0);
  if (!(hit.w > 0.5)) return vec3(0.0);
  int inNumber = int(hit.w) - 1;
  if (inNumber < 0) return vec3(0.0);
  vec3 tau = lucentOpticalThickness(inNumber, hit.xyz, outNumber, xo);
  vec3 profile = ringProfile[k];
  vec3 weight = mix(vec3(0.0), share * ringMass[k] / max(profile, vec3(1e-37)), greaterThan(profile, vec3(0.0)));
  return weight * texelFetch(mapDensity, c, 0).rgb * exp(-tau);
}

void main()
{
  vec3 xo = (positionVSOutput - worldCentre) * mmPerUnit;
  int outNumber = lucentSurfaceNumber(xo);
  vec3 b = vec3(0.0);
  if (outNumber >= 0)
  {
    vec3 rel = xo - mapCentre;
    vec2 p = vec2(dot(rel, mapT), dot(rel, mapB));
    float turn = rotated != 0 ? lucentTapTurn(xo, mapTexel, perRing) : 0.0;
    b += tapSum(p, 0, 1.0, outNumber, xo);
    for (int k = 1; k <= rings; ++k)
      for (int c = 0; c < perRing; ++c)
      {
        float phi = turn + kGoldenAngle * float(k) + 2.0 * kPi * float(c) / float(perRing);
        b += tapSum(p + ringRadius[k] * vec2(cos(phi), sin(phi)), k, 1.0 / float(perRing), outNumber, xo);
      }
    vec3 sigmaOut = lucentVoxelSigmaT(lucentVoxelOf(lucentSurfaceCentre(outNumber)));
    b *= sigmaOut * sigmaOut / (2.0 * kPi);
  }
  vec3 n = normalize(normalVSOutput);
  float cosOut = dot(n, normalize(cameraPosition - positionVSOutput));
  vec3 radiance = b * (lucentFresnelTransmittance(abs(cosOut), eta) / kPi);
  gl_FragData[0] = vec4(radiance, 1.0);
  gl_FragData[1] = vec4(positionVSOutput, 1.0);
  gl_FragData[2] = vec4(n, cosOut);
}
