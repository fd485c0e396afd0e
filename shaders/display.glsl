// Linear radiance to a display value: x / (1 + x), then sRGB (include/lucent/image/display_encode.hpp).
vec3 lucentDisplayEncode(vec3 radiance)
{
  vec3 x = max(radiance, vec3(0.0));
  // NaN compares false: it maps to 0 like the C++.
  x = mix(vec3(0.0), x, greaterThan(radiance, vec3(0.0)));
  vec3 v = clamp(x / (1.0 + x), 0.0, 1.0);
  vec3 lo = 12.92 * v;
  vec3 hi = 1.055 * pow(v, vec3(1.0 / 2.4)) - 0.055;
  return mix(hi, lo, lessThanEqual(v, vec3(0.0031308)));
}
