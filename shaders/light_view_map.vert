//VTK::System::Dec
// The object seen from the light, for the hybrid's translucent shadow map and taulut's stage 1:
// orthographic along the light's axis over the object's bounding sphere, as
// atlas/translucent_shadow_map.hpp frames it.
in vec3 positionWC;
in vec3 normalWC;
uniform vec3 worldCentre;  // the world point at the millimetre frame's origin
uniform float mmPerUnit;
uniform vec3 mapCentre;     // mm
uniform vec3 mapT;
uniform vec3 mapB;
uniform vec3 mapAxis;       // from the light into the object
uniform float mapHalfExtent;
out vec3 positionMmOutput;
out vec3 normalVSOutput;
void main()
{
  vec3 p = (positionWC - worldCentre) * mmPerUnit;
  positionMmOutput = p;
  normalVSOutput = normalWC;
  vec3 rel = p - mapCentre;
  gl_Position = vec4(dot(rel, mapT) / mapHalfExtent, dot(rel, mapB) / mapHalfExtent,
                     dot(rel, mapAxis) / (2.0 * mapHalfExtent), 1.0);
}
