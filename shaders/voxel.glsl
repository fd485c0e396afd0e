// The voxel optical-thickness LUT on the GPU (Mochida et al. 2016): the twins of
// include/lucent/voxel/surface_voxel_lookup.hpp (numberOf), grid_traversal.hpp (traverse with
// addPathLengths), surface_paths.hpp (lengths) and tau_lut_radiance.hpp (opticalThickness, turnOf).
// tau is summed per channel as the walk goes (sum_m sigma_t[m] length[m], Eq. 4), so no per-medium
// array is needed. Lengths are millimetres; every position here is in the object's millimetres.
uniform sampler3D voxelMedium;   // r: medium index (0 = none), g: density
uniform sampler3D voxelNumber;   // r: the voxel's surface number or -1, g: the flood fill's nearest
uniform sampler2D surfaceVoxel;  // per surface voxel: centre (mm); w: its cluster (hierarchical)
uniform sampler2D mediumSigmaT;  // texel m of row 0: sigma_t of medium m (0 for none), mm^-1
uniform sampler2D pathLengths;   // packed pairs (a <= b) times media, in units of lengthUnit mm
uniform sampler2D clusterCell;   // hierarchical, per cluster: its cell; w: unused
uniform sampler2D clusterPoint;  // hierarchical, per cluster: the representative's centre (mm)
uniform vec3 gridSize;  // voxels per axis (vtkShaderProgram has no ivec3 setter)
#define gridDims ivec3(gridSize)
uniform vec3 gridOrigin;
uniform vec3 gridSpacing;
uniform int rowTexels;     // texels per row of the tables laid out in 2-D
uniform int storage;       // 0 lut, 1 march, 2 hierarchical (voxel::Storage)
uniform int media;         // media 1..media have lengths stored
uniform float lengthUnit;  // mm per stored unit (fp16: the largest voxel edge; fp32: 1)

ivec2 lucentRowTexel(uint i) { return ivec2(int(i % uint(rowTexels)), int(i / uint(rowTexels))); }
vec3 lucentSurfaceCentre(int n) { return texelFetch(surfaceVoxel, lucentRowTexel(uint(n)), 0).xyz; }

ivec3 lucentVoxelOf(vec3 p)
{
  return ivec3(clamp(floor((p - gridOrigin) / gridSpacing), vec3(-1.0), vec3(gridDims)));
}
bool lucentInGrid(ivec3 v)
{
  return all(greaterThanEqual(v, ivec3(0))) && all(lessThan(v, gridDims));
}
// sigma_t at a voxel: its medium's at its density.
vec3 lucentVoxelSigmaT(ivec3 v)
{
  vec2 md = texelFetch(voxelMedium, v, 0).rg;
  return texelFetch(mediumSigmaT, ivec2(int(md.r), 0), 0).rgb * md.g;
}

// The surface voxel with the nearest centre among the 3 x 3 x 3 around p, else the flood fill's.
int lucentSurfaceNumber(vec3 p)
{
  ivec3 home = clamp(lucentVoxelOf(p), ivec3(0), gridDims - 1);
  int best = -1;
  float bestD = 3.0e38;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x)
      {
        ivec3 v = home + ivec3(x, y, z);
        if (!lucentInGrid(v)) continue;
        int n = int(texelFetch(voxelNumber, v, 0).r);
        if (n < 0) continue;
        vec3 d = lucentSurfaceCentre(n) - p;
        if (dot(d, d) < bestD)
        {
          bestD = dot(d, d);
          best = n;
        }
      }
  return best >= 0 ? best : int(texelFetch(voxelNumber, home, 0).g);
}

// tau along a -> b by the exact walk (Amanatides and Woo 1987): per voxel crossed, its length times
// its sigma_t.
vec3 lucentMarchTau(vec3 a, vec3 b)
{
  vec3 d = b - a;
  if (all(equal(d, vec3(0.0)))) return vec3(0.0);
  vec3 lo = gridOrigin, hi = gridOrigin + vec3(gridDims) * gridSpacing;
  float t = 0.0, tEnd = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0.0)
    {
      if (a[k] < lo[k] || a[k] > hi[k]) return vec3(0.0);
      continue;
    }
    float enter = (lo[k] - a[k]) / d[k], leave = (hi[k] - a[k]) / d[k];
    t = max(t, min(enter, leave));
    tEnd = min(tEnd, max(enter, leave));
  }
  if (!(t < tEnd)) return vec3(0.0);
  ivec3 v = clamp(lucentVoxelOf(a + d * t), ivec3(0), gridDims - 1);
  ivec3 stepDir = ivec3(sign(d));
  vec3 tNext = vec3(3.0e38);
  for (int k = 0; k < 3; ++k)
    if (d[k] != 0.0)
      tNext[k] = (gridOrigin[k] + float(v[k] + (stepDir[k] > 0 ? 1 : 0)) * gridSpacing[k] - a[k]) / d[k];
  float total = length(d);
  vec3 tau = vec3(0.0);
  int maxSteps = 4 + gridDims.x + gridDims.y + gridDims.z;
  for (int i = 0; i < maxSteps && t < tEnd; ++i)
  {
    int axis = tNext.x <= tNext.y ? (tNext.x <= tNext.z ? 0 : 2) : (tNext.y <= tNext.z ? 1 : 2);
    float leave = min(tNext[axis], tEnd);
    if (leave > t) tau += lucentVoxelSigmaT(v) * ((leave - t) * total);
    t = max(t, leave);
    v[axis] += stepDir[axis];
    tNext[axis] =
      (gridOrigin[axis] + float(v[axis] + (stepDir[axis] > 0 ? 1 : 0)) * gridSpacing[axis] - a[axis]) / d[axis];
    if (!lucentInGrid(v)) break;
  }
  return tau;
}

// tau between table endpoints a and b: sum over media of sigma_t times the stored length
// (path_length_table.hpp's pairIndex, b (b + 1) / 2 + a for a <= b, kept inside 32 bits).
vec3 lucentTableTau(int a, int b)
{
  uint lo = uint(min(a, b)), hi = uint(max(a, b));
  uint triangle = hi % 2u == 0u ? (hi / 2u) * (hi + 1u) : hi * ((hi + 1u) / 2u);
  uint base = (triangle + lo) * uint(media);
  vec3 tau = vec3(0.0);
  for (int m = 0; m < media; ++m)
  {
    float l = texelFetch(pathLengths, lucentRowTexel(base + uint(m)), 0).r * lengthUnit;
    tau += texelFetch(mediumSigmaT, ivec2(m + 1, 0), 0).rgb * l;
  }
  return tau;
}

// tau between surface voxels a != b, centre to centre, as the storage holds it (SurfacePaths::lengths).
vec3 lucentCentreTau(int a, int b)
{
  if (storage == 0) return lucentTableTau(a, b);
  if (storage == 2)
  {
    int ca = int(texelFetch(surfaceVoxel, lucentRowTexel(uint(a)), 0).w);
    int cb = int(texelFetch(surfaceVoxel, lucentRowTexel(uint(b)), 0).w);
    vec3 gap = abs(texelFetch(clusterCell, lucentRowTexel(uint(ca)), 0).xyz -
                   texelFetch(clusterCell, lucentRowTexel(uint(cb)), 0).xyz);
    if (max(gap.x, max(gap.y, gap.z)) > 1.0)
    {
      float own = distance(lucentSurfaceCentre(a), lucentSurfaceCentre(b));
      float reps = distance(texelFetch(clusterPoint, lucentRowTexel(uint(ca)), 0).xyz,
                            texelFetch(clusterPoint, lucentRowTexel(uint(cb)), 0).xyz);
      return lucentTableTau(ca, cb) * (own / reps);
    }
  }
  return lucentMarchTau(lucentSurfaceCentre(a), lucentSurfaceCentre(b));
}

// tau from point xa (surface voxel a) to xb (surface voxel b), scaled from the centres' distance to
// the points' own; two points in one voxel take its medium along their chord.
vec3 lucentOpticalThickness(int a, vec3 xa, int b, vec3 xb)
{
  float chord = distance(xa, xb);
  if (a == b) return lucentVoxelSigmaT(lucentVoxelOf(lucentSurfaceCentre(a))) * chord;
  vec3 ca = lucentSurfaceCentre(a), cb = lucentSurfaceCentre(b);
  return lucentCentreTau(a, b) * (chord / distance(ca, cb));
}

// The per-point turn of the tap pattern in [0, 2 pi / perRing): a hash of x_o quantised to a
// quarter texel (TauLutRadiance::turnOf).
float lucentTapTurn(vec3 xo, float texel, int perRing)
{
  ivec3 q = ivec3(floor(xo / (0.25 * texel)));
  uint h = uint(q.x) * kTurnHashX ^ uint(q.y) * kTurnHashY ^ uint(q.z) * kTurnHashZ;
  h ^= h >> 16;
  h *= kTurnHashMix;
  h ^= h >> 16;
  return 2.0 * kPi / float(perRing) * (float(h) / 4294967296.0);
}
