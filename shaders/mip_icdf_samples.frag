//VTK::System::Dec
//VTK::Output::Dec
// Stage 2 (Chang et al. 2008 Sec. 3.2, Fig. 2b): N texels drawn in proportion to E'.
// The atlas's alpha holds R+G+B of the power; its mip chain (box averages, so sums up to a constant)
// is the pyramid a sample descends: one 2-D point is warped level by level, first left/right by column
// sums, then top/bottom (as include/lucent/atlas/mip_icdf.hpp does on the CPU). One fragment per sample.
in vec2 texCoord;
uniform sampler2D powerAtlas;     // RGBA32F, full mip chain
uniform sampler2D positionAtlas;  // RGBA32F: world position, w = 1 where a triangle owns the texel
uniform int topLevel;             // log2(atlas resolution): the 1x1 level
uniform int sampleCount;
uniform int samplesPerRow;
uniform vec2 rotation;            // Cranley-Patterson shift of the Hammersley set

float radicalInverse(int i)
{
  uint b = uint(i);
  float inv = 0.5;
  float r = 0.0;
  for (int k = 0; k < 32 && b != 0u; ++k)
  {
    if ((b & 1u) != 0u) r += inv;
    inv *= 0.5;
    b >>= 1;
  }
  return r;
}

void main()
{
  ivec2 pixel = ivec2(texCoord * float(samplesPerRow));  // texel centres: (i + 0.5) / samplesPerRow
  int i = pixel.y * samplesPerRow + pixel.x;
  float total = texelFetch(powerAtlas, ivec2(0), topLevel).a;
  if (i >= sampleCount || !(total > 0.0))
  {
    gl_FragData[0] = vec4(0.0);
    gl_FragData[1] = vec4(0.0);
    return;
  }
  vec2 u = fract(vec2((float(i) + 0.5) / float(sampleCount), radicalInverse(i)) + rotation);
  ivec2 t = ivec2(0);
  for (int level = topLevel - 1; level >= 0; --level)
  {
    ivec2 c = 2 * t;
    float a00 = texelFetch(powerAtlas, c, level).a;
    float a01 = texelFetch(powerAtlas, c + ivec2(0, 1), level).a;
    float a10 = texelFetch(powerAtlas, c + ivec2(1, 0), level).a;
    float a11 = texelFetch(powerAtlas, c + ivec2(1, 1), level).a;
    float left = a00 + a01;
    float pLeft = left / (left + a10 + a11);
    if (u.x < pLeft) { u.x = u.x / pLeft; }
    else { c.x += 1; u.x = (u.x - pLeft) / (1.0 - pLeft); }
    float top = c.x == 2 * t.x ? a00 : a10;
    float bottom = c.x == 2 * t.x ? a01 : a11;
    float pTop = top / (top + bottom);
    if (u.y < pTop) { u.y = u.y / pTop; }
    else { c.y += 1; u.y = (u.y - pTop) / (1.0 - pTop); }
    u = clamp(u, 0.0, 0.99999994);
    t = c;
  }
  vec4 power = texelFetch(powerAtlas, t, 0);
  // p = value / sum; the top level holds sum / texels. Eq. 10: w = E' / (p N).
  float texels = exp2(2.0 * float(topLevel));
  float probability = power.a / (total * texels);
  vec3 weight = probability > 0.0 ? power.rgb / (probability * float(sampleCount)) : vec3(0.0);
  gl_FragData[0] = vec4(texelFetch(positionAtlas, t, 0).xyz, 1.0);
  gl_FragData[1] = vec4(weight, 0.0);
}
