//VTK::System::Dec
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(gl_FragCoord.z);
}
