// The pass's one light as a surface point sees it, in whatever frame its uniforms are given (world
// for the stages of light.glsl, millimetres for the light-view map), as scene::Light holds it:
// directional (lightIsPoint 0), from towardLight with irradiance lightIrradiance on a surface
// facing it; or a point at lightPosition of intensity lightIrradiance, whose irradiance facing it
// falls off as 1 / d^2.
uniform int lightIsPoint;
uniform vec3 towardLight;       // unit
uniform vec3 lightPosition;
uniform vec3 lightIrradiance;   // per channel

vec3 lucentTowardLight(vec3 position)
{
  return lightIsPoint != 0 ? normalize(lightPosition - position) : towardLight;
}

// Irradiance on a surface at `position` facing the light.
vec3 lucentIrradianceFacing(vec3 position)
{
  if (lightIsPoint == 0) return lightIrradiance;
  vec3 d = lightPosition - position;
  return lightIrradiance / max(dot(d, d), 1e-30);
}
