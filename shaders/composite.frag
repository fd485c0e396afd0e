//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::Display
// Stage 4: the translucent radiance replaces the delegate's diffuse shading where the translucent
// surface is the visible one; SurfaceWeight keeps some of the delegate's own shading (specular, edges).
in vec2 texCoord;
uniform sampler2D sceneColor;
uniform sampler2D sceneDepth;
uniform sampler2D translucentRadiance;  // a = 1 where a translucent surface was drawn
uniform sampler2D translucentDepth;
uniform float exposure;
uniform float surfaceWeight;
uniform float depthTolerance;
void main()
{
  vec4 color = texture(sceneColor, texCoord);
  float depth = texture(sceneDepth, texCoord).r;
  vec4 radiance = texture(translucentRadiance, texCoord);
  if (radiance.a > 0.0 && texture(translucentDepth, texCoord).r <= depth + depthTolerance)
  {
    color.rgb = clamp(surfaceWeight * color.rgb + lucentDisplayEncode(exposure * radiance.rgb), 0.0, 1.0);
  }
  gl_FragData[0] = color;
  gl_FragDepth = depth;
}
