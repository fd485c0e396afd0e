// The hybrid's local term B_l (Chang et al. 2008 Sec. 4.2) on the GPU: the ring filter of
// atlas/ring_filter.hpp over the translucent shadow map, as TranslucentShadowMap::filterTable sums
// it. The CPU's own filter goes up as it is: the taps' offsets and ratio factors share M_k / f(r_k),
// the table of f = Rd Wl, and the cumulative C_c(r) of the centre's disc transfer. Needs
// //LUCENT::Optics before it.
uniform sampler2D mapPosition;  // first hit (mm); w = 1 where the surface covers the texel
uniform sampler2D mapDensity;   // rho per channel
uniform int mapResolution;
uniform vec3 mapCentre;         // the map's frame (atlas::LightViewFrame), mm
uniform vec3 mapT;
uniform vec3 mapB;
uniform float mapHalfExtent;
uniform float mapTexel;
uniform sampler2D tapOffset;    // per ring tap: its offset (mm) on the map's axes
uniform sampler2D tapFactor;    // per ring tap: share M_k / f(r_k) per channel
uniform int taps;
uniform int tapsPerRow;
uniform sampler2D localTable;   // f = Rd Wl
uniform LucentRadialTable localProfile;
uniform sampler2D centreCumulative;  // C_c on the nodes r_j = domain (j / J)^2
uniform LucentRadialTable centreGrid;
uniform vec3 centreMass;        // M_0 per channel
uniform float innerRadius;      // R_0, the centre disc's edge (mm)

// C_c(r): linear between the nodes, the total beyond the domain (RingFilter::cumulativeAt).
vec3 lucentCumulativeAt(float r)
{
  if (!(r > 0.0)) return vec3(0.0);
  float last = float(centreGrid.nodes - 1);
  float u = sqrt(r / centreGrid.rMax) * last;
  if (!(u < last)) return lucentTableNode(centreCumulative, centreGrid, centreGrid.nodes - 1);
  int i = int(u);
  float f = u - float(i);
  return mix(lucentTableNode(centreCumulative, centreGrid, i),
             lucentTableNode(centreCumulative, centreGrid, i + 1), f);
}

// T_c(d), the centre sample's transfer at distance d off its disc (RingFilter::centreTransfer).
vec3 lucentCentreTransfer(float d)
{
  vec3 disc = lucentCumulativeAt(innerRadius);
  vec3 seen = lucentCumulativeAt(sqrt(innerRadius * innerRadius + d * d)) - lucentCumulativeAt(d);
  vec3 t = clamp(seen / max(disc, vec3(1e-37)), 0.0, 1.0);
  return mix(vec3(0.0), t, greaterThan(disc, vec3(0.0)));
}

// int rho f(|x - x_o|) dA over the map around x_o (mm): the centre's disc, then every ring tap that
// lands on a covered texel (the ratio estimator of ring_filter.hpp).
vec3 lucentLocalTerm(vec3 xo)
{
  vec3 rel = xo - mapCentre;
  vec2 origin = (vec2(dot(rel, mapT), dot(rel, mapB)) + vec2(mapHalfExtent)) / mapTexel;
  vec2 size = vec2(float(mapResolution));
  vec3 sum = vec3(0.0);
  if (all(greaterThanEqual(origin, vec2(0.0))) && all(lessThan(origin, size)))
  {
    ivec2 c = ivec2(origin);
    vec4 hit = texelFetch(mapPosition, c, 0);
    if (hit.w > 0.5)
      sum += centreMass * texelFetch(mapDensity, c, 0).rgb * lucentCentreTransfer(distance(hit.xyz, xo));
  }
  for (int j = 0; j < taps; ++j)
  {
    ivec2 at = ivec2(j % tapsPerRow, j / tapsPerRow);
    vec2 f = origin + texelFetch(tapOffset, at, 0).xy / mapTexel;
    if (!(all(greaterThanEqual(f, vec2(0.0))) && all(lessThan(f, size)))) continue;
    ivec2 c = ivec2(f);
    vec4 hit = texelFetch(mapPosition, c, 0);
    if (!(hit.w > 0.5)) continue;
    vec3 f_d = lucentRadialTableRd(localTable, localProfile, distance(hit.xyz, xo));
    sum += texelFetch(tapFactor, at, 0).rgb * texelFetch(mapDensity, c, 0).rgb * f_d;
  }
  return sum;
}
