//VTK::System::Dec
// Stage 3: the object seen from the camera; world position and normal go to the fragment shader.
in vec3 positionWC;
in vec3 normalWC;
uniform mat4 worldToClip;
out vec3 positionVSOutput;
out vec3 normalVSOutput;
void main()
{
  positionVSOutput = positionWC;
  normalVSOutput = normalWC;
  gl_Position = worldToClip * vec4(positionWC, 1.0);
}
