//VTK::System::Dec
//VTK::Output::Dec
//LUCENT::Optics
//LUCENT::Light
in vec3 positionVSOutput;
in vec3 normalVSOutput;
in float areaVSOutput;
void main()
{
  vec3 e = lucentTransmittedIrradiance(positionVSOutput, normalize(normalVSOutput));
  vec3 power = e * areaVSOutput;  // E' times the texel area (Eq. 7)
  gl_FragData[0] = vec4(power, power.r + power.g + power.b);
  gl_FragData[1] = vec4(positionVSOutput, 1.0);
}
