//VTK::System::Dec
// Stage 1 (Chang et al. 2008 Sec. 3, Eq. 4-7): every triangle is rasterised at its atlas
// coordinates, so each texel receives the irradiance of the surface point it stands for.
in vec3 positionWC;
in vec3 normalWC;
in vec2 atlasUV;        // [0, 1]^2
in float areaPerTexel;  // A_S / n_T of the texel's triangle, mm^2 (Eq. 7)
out vec3 positionVSOutput;
out vec3 normalVSOutput;
out float areaVSOutput;
void main()
{
  positionVSOutput = positionWC;
  normalVSOutput = normalWC;
  areaVSOutput = areaPerTexel;
  gl_Position = vec4(2.0 * atlasUV - 1.0, 0.0, 1.0);
}
