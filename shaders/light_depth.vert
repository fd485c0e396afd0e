//VTK::System::Dec
// Stage 0: depth of the object seen from the directional light (orthographic), for the shadow test of
// stage 1. Positions are in world coordinates.
in vec3 positionWC;
uniform mat4 worldToLight;
void main()
{
  gl_Position = worldToLight * vec4(positionWC, 1.0);
}
