#include "vtkLucentPass.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMapper.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLCamera.h>
#include <vtkOpenGLError.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkPropCollection.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <lucent/optics/materials.hpp>
#include <lucent/plan/calibration.hpp>
#include <lucent/technique/registry.hpp>
#include <lucent/technique/scene_fingerprint.hpp>

#include "lucentFilterTechniques.h"
#include "lucentPassDrawing.h"
#include "lucentPassPlanner.h"
#include "lucentPolyDataMesh.h"
#include "lucentSmpFor.h"
#include "lucent_glsl.h"
#include "vtkLucentLocalTerm.h"
#include "vtkLucentProfile.h"
#include "vtkLucentSurface.h"
#include "vtkLucentTauLut.h"

vtkStandardNewMacro(vtkLucentPass);

namespace {
using namespace lucent::vtkpass;

int powerOfTwoAtLeast(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

namespace lt = lucent::technique;

const lt::Registry& registry() {
  static const lt::Registry r = lucent::vtkadapter::coreTechniques();
  return r;
}

/// The registry's techniques whose GPU twin is this pass, in registry order.
std::vector<const lt::Technique*> twins() {
  std::vector<const lt::Technique*> out;
  for (const auto& t : registry().all())
    if (t.capabilities.gpuTwin == kPassTwin) out.push_back(&t);
  return out;
}
const lt::Technique* twinNamed(const std::string& name) {
  for (const lt::Technique* t : twins())
    if (t->name == name) return t;
  return nullptr;
}

/// A knob as the twin takes it: the technique's spec with the twin's own upper bound.
struct PassKnob {
  const lt::KnobSpec* spec = nullptr;
  double max = 0;
};
PassKnob passKnob(const lt::Technique& t, const std::string& name) {
  for (const auto& twin : t.capabilities.gpuTwinKnobs)
    if (twin.knob == name) return {t.knob(name), std::min(t.knob(name)->max, twin.max)};
  throw std::logic_error(t.name + " declares no GPU twin knob " + name);
}

/// A given value clamped to the twin's range (numbers; choices pass as given).
std::string clampedToTwin(const PassKnob& k, const std::string& value) {
  if (k.spec->kind != lt::KnobKind::Integer && k.spec->kind != lt::KnobKind::Real) return value;
  double v = 0;
  if (!lt::detail::parseReal(value, v)) return value;  // the technique's check reports it
  v = std::clamp(v, k.spec->min, k.max);
  char text[64];
  std::snprintf(text, sizeof text, k.spec->kind == lt::KnobKind::Integer ? "%.0f" : "%.17g", v);
  return text;
}

/// The renderer's visible opaque actors with a mapper, in prop order.
std::vector<vtkActor*> opaqueActors(vtkRenderer* renderer) {
  std::vector<vtkActor*> out;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  for (vtkProp* prop = props->GetNextProp(it); prop; prop = props->GetNextProp(it)) {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (actor && actor->GetVisibility() && actor->GetMapper() &&
        !actor->HasTranslucentPolygonalGeometry())
      out.push_back(actor);
  }
  return out;
}

/// An actor whose data is marked as an inner body (lucentPolyDataMesh.h's kInnerMaterialArray).
/// What an inner-body actor was built from, for the keys of what depends on it.
std::string innerBodyKey(vtkActor* actor) {
  return " inner " + std::to_string(actor->GetMapper()->GetInputDataObject(0, 0)->GetMTime()) +
         "/" + std::to_string(actor->GetMTime());
}

bool isInnerBody(vtkActor* actor) {
  return !lucent::vtkadapter::innerMaterialOf(actor->GetMapper()->GetInputDataObject(0, 0)).empty();
}

/// The inner-body actors inside `surface`'s bounds, as inclusions in its millimetre frame; appends
/// what they were built from to `key`. Inside tests are not set: taulut voxelises the surfaces.
std::vector<lt::Inclusion> innerBodiesWithin(const vtkLucentSurface& surface,
                                             const std::vector<vtkActor*>& inner,
                                             std::string& key) {
  const glm::dvec3 centre(surface.GetCentre()[0], surface.GetCentre()[1], surface.GetCentre()[2]);
  const double radius = surface.GetRadius(), scale = surface.GetMillimetresPerUnit();
  std::vector<lt::Inclusion> out;
  for (vtkActor* actor : inner) {
    double b[6];
    actor->GetBounds(b);
    const glm::dvec3 lo(b[0], b[2], b[4]), hi(b[1], b[3], b[5]);
    if (glm::length(lo - centre) > radius || glm::length(hi - centre) > radius) continue;
    vtkDataObject* data = actor->GetMapper()->GetInputDataObject(0, 0);
    vtkNew<vtkMatrix4x4> matrix;
    actor->GetMatrix(matrix);
    for (auto& body : lucent::vtkadapter::innerBodiesOf(data, matrix)) {
      const auto material = lucent::optics::findMaterial(body.material);
      if (!material)
        throw lt::RequestError(
            "an inner body's material '" + body.material +
            "' is not a measured material; use one of: " + lucent::optics::measuredMaterialNames());
      lt::Inclusion inc;
      inc.surface = body.surface.mesh;
      for (auto& p : inc.surface.positions) p = glm::vec3((glm::dvec3(p) - centre) * scale);
      inc.medium.material = *material;
      inc.description = material->name + " inner body";
      out.push_back(std::move(inc));
    }
    key += innerBodyKey(actor);
  }
  return out;
}
/// Stage 3's fragment shader, reading the profile's table or a pole pair's closed form, with the
/// hybrid's local term or without.
std::string shadeVariant(bool closedForm, bool localTerm) {
  std::string source = lucent::glsl::kTsisShadeFrag;
  vtkShaderProgram::Substitute(source, "//LUCENT::ProfileForm",
                               std::string("#define LUCENT_CLOSED_FORM ") +
                                   (closedForm ? "1" : "0") + "\n#define LUCENT_LOCAL_TERM " +
                                   (localTerm ? "1" : "0"));
  return withSharedGlsl(source.c_str());
}
}  // namespace

struct vtkLucentPass::Internals {
  // The delegate's image, and the translucent surfaces' radiance / position / normal / depth.
  vtkSmartPointer<vtkOpenGLFramebufferObject> sceneFbo, translucentFbo, lightFbo, atlasFbo,
      samplesFbo;
  vtkSmartPointer<vtkTextureObject> sceneColor, sceneDepth;
  vtkSmartPointer<vtkTextureObject> translucentRadiance, translucentPosition, translucentNormal,
      translucentDepth;
  vtkSmartPointer<vtkTextureObject> lightDepth, powerAtlas, positionAtlas, samplePosition,
      sampleWeight;
  vtkOpenGLQuadHelper* samplesQuad = nullptr;
  vtkOpenGLQuadHelper* compositeQuad = nullptr;
  std::string lightDepthVs, lightDepthFs, atlasVs, atlasFs, shadeVs;
  std::string shadeFs[2];     ///< stage 3 with the profile's table [0], or in closed form [1]
  std::string hybridShadeFs;  ///< stage 3 with the table of Rd Wg and the local term
  std::string tauShadeFs, diffuseShadeFs;
  std::map<vtkActor*, vtkSmartPointer<vtkLucentSurface>> surfaces;
  std::map<const vtkLucentSurface*, vtkSmartPointer<vtkLucentTauLut>> tauLuts;    ///< taulut's twin
  std::map<const vtkLucentSurface*, vtkSmartPointer<vtkLucentProfile>> profiles;  ///< tsis's Rd
  std::map<const vtkLucentSurface*, vtkSmartPointer<vtkLucentLocalTerm>> localTerms;  ///< hybrid
  /// Per surface, the build, material and knobs its range was last checked for: the check copies
  /// the mesh, so it runs when one of them changes, not every frame.
  std::map<const vtkLucentSurface*, std::string> rangeChecked;
  /// Technique auto: the calibration (read once per folder) and each surface's plan with what it
  /// was made for.
  std::unique_ptr<lucent::plan::Calibration> calibration;
  std::map<const vtkLucentSurface*, std::pair<std::string, PassPlan>> plans;
  int frameWidth = 0, frameHeight = 0;
  std::vector<float> frameRadiance, framePosition, frameNormal;

  Internals()
      : lightDepthVs(lucent::glsl::kLightDepthVert),
        lightDepthFs(lucent::glsl::kLightDepthFrag),
        atlasVs(lucent::glsl::kAtlasIrradianceVert),
        atlasFs(withSharedGlsl(lucent::glsl::kAtlasIrradianceFrag)),
        shadeVs(lucent::glsl::kTsisShadeVert),
        shadeFs{shadeVariant(false, false), shadeVariant(true, false)},
        hybridShadeFs(shadeVariant(false, true)),
        tauShadeFs(withSharedGlsl(lucent::glsl::kTaulutShadeFrag)),
        diffuseShadeFs(withSharedGlsl(lucent::glsl::kDiffuseBrdfShadeFrag)) {}
};

struct vtkLucentPass::FrameSetup {
  glm::dvec3 towardLight{0, 0, 1};  ///< unit; for a point light, from its focal point to it
  float irradiance[3] = {1, 1, 1};  ///< on a surface facing the light (at `reach` from a point)
  /// A positional scene light: a point at `lightPosition` (world), its irradiance given at its
  /// focal point, `reach` (world units) away.
  bool pointLight = false;
  glm::dvec3 lightPosition{0};
  double reach = 1;
  lucent::optics::Material material;
  int atlasSize = 0, topLevel = 0, shadowSize = 0;
  int samples = 0, samplesPerRow = 0;  ///< tsis's, of the actor being shaded
  vtkMatrix4x4* worldToClip = nullptr;
  float camera[3] = {};
  glm::mat4 worldToLight{1.0f};             ///< of the actor being shaded
  vtkLucentLocalTerm* localTerm = nullptr;  ///< the hybrid's, of the actor being shaded

  /// The light in world coordinates (scale 1, no offset) or in a surface's millimetre frame, as
  /// the CPU techniques take it.
  lucent::scene::Light light(const glm::dvec3& centre = glm::dvec3(0), double mm = 1) const {
    const glm::dvec3 e(irradiance[0], irradiance[1], irradiance[2]);
    if (!pointLight) return lucent::scene::DirectionalLight{towardLight, e};
    return lucent::scene::PointLight{(lightPosition - centre) * mm,
                                     e * (reach * mm) * (reach * mm)};
  }
  lucent::scene::Light lightIn(const vtkLucentSurface& surface) const {
    const double* c = surface.GetCentre();
    return light(glm::dvec3(c[0], c[1], c[2]), surface.GetMillimetresPerUnit());
  }
};

vtkLucentPass::vtkLucentPass() : Impl(new Internals) { this->RefreshAtlasKnobs(); }

void vtkLucentPass::SetTechnique(const char* name) {
  const std::string value = name ? name : "";
  if (value == this->Technique) return;
  this->Technique = value;
  this->RefreshAtlasKnobs();
  this->Modified();
}

int vtkLucentPass::GetNumberOfTechniques() { return int(twins().size()); }
std::string vtkLucentPass::GetTechniqueName(int i) {
  const auto all = twins();
  return i >= 0 && i < int(all.size()) ? all[std::size_t(i)]->name : std::string();
}

void vtkLucentPass::SetKnob(const char* qualifiedName, const char* value) {
  if (!qualifiedName) return;
  const std::string v = value ? value : "";
  auto [it, added] = this->Knobs.emplace(qualifiedName, v);
  if (!added && it->second == v) return;
  it->second = v;
  this->RefreshAtlasKnobs();
  this->Modified();
}
void vtkLucentPass::SetKnobInteger(const char* qualifiedName, int value) {
  this->SetKnob(qualifiedName, std::to_string(value).c_str());
}
void vtkLucentPass::SetKnobReal(const char* qualifiedName, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  this->SetKnob(qualifiedName, text);
}
std::string vtkLucentPass::GetKnob(const char* qualifiedName) const {
  if (!qualifiedName) return {};
  if (const auto it = this->Knobs.find(qualifiedName); it != this->Knobs.end()) return it->second;
  for (const lt::Technique* t : twins())
    for (const auto& twin : t->capabilities.gpuTwinKnobs)
      if (t->name + "." + twin.knob == qualifiedName) return t->knob(twin.knob)->defaultValue;
  return {};
}

void vtkLucentPass::SetSamples(int n) { this->SetKnobInteger("tsis.samples", n); }
void vtkLucentPass::SetAtlasResolution(int texels) {
  this->SetKnobInteger("tsis.atlas-resolution", texels);
}

lt::KnobValues vtkLucentPass::TwinValues(const lt::Technique& t) const {
  lt::KnobList given;
  for (const auto& twin : t.capabilities.gpuTwinKnobs) {
    const auto it = this->Knobs.find(t.name + "." + twin.knob);
    if (it != this->Knobs.end())
      given.emplace_back(twin.knob, clampedToTwin(passKnob(t, twin.knob), it->second));
  }
  return t.values(given);
}

/// The atlas's stages read two knobs as members: the pass's technique's when its twin samples the
/// atlas (tsis, hybrid), else tsis's.
void vtkLucentPass::RefreshAtlasKnobs() {
  const lt::Technique* t = twinNamed(this->Technique);
  const auto& twinKnobs = t ? t->capabilities.gpuTwinKnobs : std::vector<lt::TwinKnob>{};
  if (std::none_of(twinKnobs.begin(), twinKnobs.end(),
                   [](const lt::TwinKnob& k) { return k.knob == "samples"; }))
    t = twinNamed("tsis");
  lt::KnobValues values;
  try {
    values = this->TwinValues(*t);
  } catch (const std::exception&) {
    values = t->values();  // a malformed number: the defaults, reported when drawn
  }
  this->Samples = int(values.integer("samples"));
  this->AtlasResolution = int(values.integer("atlas-resolution"));
}

vtkLucentPass::~vtkLucentPass() {
  if (this->Impl->sceneFbo)
    vtkErrorMacro("graphics resources should have been released in ReleaseGraphicsResources()");
  delete this->Impl;
}

void vtkLucentPass::SetMaterial(const char* name) {
  const std::string value = name ? name : "";
  if (value == this->Material) return;
  this->Material = value;
  this->Modified();
}

void vtkLucentPass::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Material: " << this->Material << "\n"
     << indent << "SizeMm: " << this->SizeMm << "\n"
     << indent << "Samples: " << this->Samples << "\n"
     << indent << "AtlasResolution: " << this->AtlasResolution << "\n"
     << indent << "ShadowMapResolution: " << this->ShadowMapResolution << "\n"
     << indent << "LightDirection: " << this->LightDirection[0] << " " << this->LightDirection[1]
     << " " << this->LightDirection[2] << "\n"
     << indent << "LightIrradiance: " << this->LightIrradiance << "\n"
     << indent << "Exposure: " << this->Exposure << "\n"
     << indent << "SurfaceWeight: " << this->SurfaceWeight << "\n"
     << indent << "KeepFrame: " << this->KeepFrame << "\n"
     << indent << "MaxError: " << this->MaxError << "\n"
     << indent << "CalibrationDirectory: " << this->CalibrationDirectory << "\n";
}

void vtkLucentPass::WarnOutsideRange(const vtkLucentSurface& surface, const lt::Technique& t,
                                     const lt::KnobValues& knobs) {
  // The technique's stated range, with the pass's knobs. The CLI and the filter refuse outside it;
  // an interactive view keeps drawing (finite, but not what the technique promises) and says so
  // once.
  std::string checkedFor = std::to_string(surface.GetBuildCount()) + " " + this->Material;
  for (const auto& k : t.knobs) checkedFor += " " + knobs.text(k.name);
  std::string& lastChecked = this->Impl->rangeChecked[&surface];
  if (lastChecked == checkedFor || !t.validity) return;
  lastChecked = checkedFor;
  const auto material = lucent::optics::findMaterial(this->Material);
  if (!material) return;
  lt::SceneDescription scene;
  scene.mesh = surface.GetMillimetreMesh();
  scene.medium.material = *material;
  const std::string why = t.validity(scene, knobs);
  if (why.empty() || why == this->LastRangeWarning) return;
  this->LastRangeWarning = why;
  vtkWarningMacro(<< "vtkLucentPass (" << t.name << "'s GPU twin) is outside " << t.name
                  << "'s valid range: " << why << " (valid for: " << t.validRange << ")");
}

void vtkLucentPass::ReportError(const std::string& message) {
  if (message == this->LastError) return;  // once, not every frame
  this->LastError = message;
  vtkErrorMacro(<< message);
}

void vtkLucentPass::InitializeGraphicsResources(vtkOpenGLRenderWindow* window, int width,
                                                int height) {
  Internals& I = *this->Impl;
  if (!I.sceneFbo) {
    I.sceneFbo = newFramebuffer(window);
    I.translucentFbo = newFramebuffer(window);
    I.lightFbo = newFramebuffer(window);
    I.atlasFbo = newFramebuffer(window);
    I.samplesFbo = newFramebuffer(window);
    I.sceneColor = newColorTexture(window, width, height);
    I.sceneDepth = newDepthTexture(window, width, height);
    I.translucentRadiance = newColorTexture(window, width, height);
    I.translucentPosition = newColorTexture(window, width, height);
    I.translucentNormal = newColorTexture(window, width, height);
    I.translucentDepth = newDepthTexture(window, width, height);
    I.lightDepth = newDepthTexture(window, this->ShadowMapResolution, this->ShadowMapResolution);
    const int atlas = powerOfTwoAtLeast(this->AtlasResolution);
    I.powerAtlas = newColorTexture(window, atlas, atlas);
    I.powerAtlas->SetMinificationFilter(vtkTextureObject::NearestMipmapNearest);
    I.positionAtlas = newColorTexture(window, atlas, atlas);
    I.samplePosition = newColorTexture(window, 1, 1);
    I.sampleWeight = newColorTexture(window, 1, 1);
  }
  for (auto* t : {I.sceneColor.Get(), I.sceneDepth.Get(), I.translucentRadiance.Get(),
                  I.translucentPosition.Get(), I.translucentNormal.Get(), I.translucentDepth.Get()})
    t->Resize(unsigned(width), unsigned(height));
}

void vtkLucentPass::RenderDelegateWithDepth(const vtkRenderState* s, int width, int height) {
  Internals& I = *this->Impl;
  vtkOpenGLState* state =
      static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow())->GetState();
  beginDrawing(state, I.sceneFbo, {I.sceneColor}, I.sceneDepth, width, height);
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  endDrawing(I.sceneFbo);
}

void vtkLucentPass::ClearTranslucentTargets(vtkOpenGLState* state, int width, int height) {
  Internals& I = *this->Impl;
  beginDrawing(state, I.translucentFbo,
               {I.translucentRadiance, I.translucentPosition, I.translucentNormal},
               I.translucentDepth, width, height);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  endDrawing(I.translucentFbo);
}

bool vtkLucentPass::ResolveLight(vtkRenderer* renderer, FrameSetup& frame) {
  glm::dvec3 towardLight(this->LightDirection[0], this->LightDirection[1], this->LightDirection[2]);
  double scale = this->LightIrradiance, colour[3] = {1, 1, 1};
  if (!(glm::length(towardLight) > 0)) {
    vtkLight* light = nullptr;
    vtkLightCollection* lights = renderer->GetLights();
    lights->InitTraversal();
    for (vtkLight* l = lights->GetNextItem(); l && !light; l = lights->GetNextItem())
      if (l->GetSwitch()) light = l;
    if (!light) {
      this->ReportError(
          "vtkLucentPass: the renderer has no light switched on and LightDirection is not set; "
          "nothing is lit, so nothing glows");
      return false;
    }
    double position[3], focal[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    light->GetDiffuseColor(colour);
    scale *= light->GetIntensity();
    towardLight =
        glm::dvec3(position[0] - focal[0], position[1] - focal[1], position[2] - focal[2]);
    if (!(glm::length(towardLight) > 0)) {
      this->ReportError(
          "vtkLucentPass: the light's position equals its focal point; give it a direction");
      return false;
    }
    // A positional light is a point light (VTK's cone angle is not modelled): its irradiance is
    // LightIrradiance x intensity at its focal point, falling off as 1 / d^2.
    frame.pointLight = light->GetPositional() != 0;
    frame.lightPosition = glm::dvec3(position[0], position[1], position[2]);
    frame.reach = glm::length(towardLight);
  }
  frame.towardLight = glm::normalize(towardLight);
  for (int c = 0; c < 3; ++c) frame.irradiance[c] = float(scale * colour[c]);
  return true;
}

bool vtkLucentPass::SetUpFrame(vtkRenderer* renderer, FrameSetup& frame) {
  Internals& I = *this->Impl;
  const auto material = lucent::optics::findMaterial(this->Material);
  if (!material) {
    this->ReportError(
        "vtkLucentPass: material '" + this->Material +
        "' is not a measured material; use one of: " + lucent::optics::measuredMaterialNames());
    return false;
  }
  if (!this->ResolveLight(renderer, frame)) return false;
  frame.material = *material;

  frame.atlasSize = powerOfTwoAtLeast(this->AtlasResolution);
  frame.topLevel = int(std::lround(std::log2(double(frame.atlasSize))));
  I.powerAtlas->SetMaxLevel(frame.topLevel);  // vtkTextureObject's default keeps level 0 only
  if (int(I.powerAtlas->GetWidth()) != frame.atlasSize) {
    I.powerAtlas->Resize(unsigned(frame.atlasSize), unsigned(frame.atlasSize));
    I.positionAtlas->Resize(unsigned(frame.atlasSize), unsigned(frame.atlasSize));
  }
  frame.shadowSize = this->ShadowMapResolution;
  if (int(I.lightDepth->GetWidth()) != frame.shadowSize)
    I.lightDepth->Resize(unsigned(frame.shadowSize), unsigned(frame.shadowSize));

  vtkMatrix4x4 *worldToView, *viewToClip;
  vtkMatrix3x3* normalMatrix;
  static_cast<vtkOpenGLCamera*>(renderer->GetActiveCamera())
      ->GetKeyMatrices(renderer, worldToView, normalMatrix, viewToClip, frame.worldToClip);
  double cameraPosition[3];
  renderer->GetActiveCamera()->GetPosition(cameraPosition);
  for (int k = 0; k < 3; ++k) frame.camera[k] = float(cameraPosition[k]);
  return true;
}

bool vtkLucentPass::LightTransform(FrameSetup& frame, const double centreWorld[3], double radius) {
  const glm::dvec3 centre(centreWorld[0], centreWorld[1], centreWorld[2]);
  if (!frame.pointLight) {
    const glm::dvec3 up =
        std::abs(frame.towardLight.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    frame.worldToLight =
        glm::mat4(glm::ortho(-radius, radius, -radius, radius, 0.5 * radius, 3.5 * radius) *
                  glm::lookAt(centre + 2.0 * radius * frame.towardLight, centre, up));
    return true;
  }
  // A point light: a perspective view from it framing the object's bounding sphere.
  const glm::dvec3 toCentre = centre - frame.lightPosition;
  const double distance = glm::length(toCentre);
  if (!(distance > 1.01 * radius)) {
    this->ReportError(
        "vtkLucentPass: the point light is inside (or at) the object's bounding sphere; its "
        "shadow map cannot frame the object: move the light out, or make it directional "
        "(PositionalOff, or set LightDirection)");
    return false;
  }
  const glm::dvec3 axis = toCentre / distance;
  const glm::dvec3 up = std::abs(axis.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const double halfAngle = std::asin(std::min(1.0, radius / distance));
  const double nearPlane = std::max(distance - radius, 1e-3 * radius);
  frame.worldToLight =
      glm::mat4(glm::perspective(2.0 * halfAngle, 1.0, nearPlane, distance + radius) *
                glm::lookAt(frame.lightPosition, centre, up));
  return true;
}

bool vtkLucentPass::RenderLightDepth(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                     FrameSetup& frame) {
  Internals& I = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  if (!this->LightTransform(frame, surface->GetCentre(), surface->GetRadius())) return false;
  beginDrawing(state, I.lightFbo, {}, I.lightDepth, frame.shadowSize, frame.shadowSize);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
      I.lightDepthVs.c_str(), I.lightDepthFs.c_str(), "");
  if (program) {
    program->SetUniformMatrix4x4("worldToLight", glm::value_ptr(frame.worldToLight));
    surface->Draw(program, vtkLucentSurface::LightDepth);
  }
  endDrawing(I.lightFbo);
  if (!program) this->ReportError("vtkLucentPass: the light-depth shader did not compile");
  return program != nullptr;
}

vtkShaderProgram* vtkLucentPass::BeginPerPixelStage(vtkOpenGLRenderWindow* window,
                                                    const std::string& fragmentShader, int width,
                                                    int height) {
  Internals& I = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  beginDrawing(state, I.translucentFbo,
               {I.translucentRadiance, I.translucentPosition, I.translucentNormal},
               I.translucentDepth, width, height);
  state->vtkglEnable(GL_DEPTH_TEST);  // the nearest translucent surface per pixel
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDepthMask(GL_TRUE);
  return window->GetShaderCache()->ReadyShaderProgram(I.shadeVs.c_str(), fragmentShader.c_str(),
                                                      "");
}

void vtkLucentPass::SetLightUniforms(vtkShaderProgram* program, const FrameSetup& frame) {
  Internals& I = *this->Impl;
  I.lightDepth->Activate();
  program->SetUniformi("lightDepth", I.lightDepth->GetTextureUnit());
  program->SetUniformMatrix4x4("worldToLight",
                               const_cast<float*>(glm::value_ptr(frame.worldToLight)));
  setLightSourceUniforms(program, frame.light());
  program->SetUniformf("eta", float(frame.material.eta));
  program->SetUniformf("shadowBias", 1.0f / float(frame.shadowSize));
}

bool vtkLucentPass::RenderAtlasIrradiance(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                          const FrameSetup& frame) {
  Internals& I = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  beginDrawing(state, I.atlasFbo, {I.powerAtlas, I.positionAtlas}, nullptr, frame.atlasSize,
               frame.atlasSize);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  vtkShaderProgram* program =
      window->GetShaderCache()->ReadyShaderProgram(I.atlasVs.c_str(), I.atlasFs.c_str(), "");
  if (program) {
    this->SetLightUniforms(program, frame);
    surface->Draw(program, vtkLucentSurface::Atlas);
    I.lightDepth->Deactivate();
  }
  endDrawing(I.atlasFbo);
  if (!program) {
    this->ReportError("vtkLucentPass: the atlas shader did not compile");
    return false;
  }
  I.powerAtlas->Activate();
  glGenerateMipmap(GL_TEXTURE_2D);
  I.powerAtlas->Deactivate();
  return true;
}

bool vtkLucentPass::DrawImportanceSamples(vtkOpenGLRenderWindow* window, const FrameSetup& frame) {
  Internals& I = *this->Impl;
  if (!I.samplesQuad) {
    I.samplesQuad = new vtkOpenGLQuadHelper(
        window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
        lucent::glsl::kMipIcdfSamplesFrag, "");
  } else {
    window->GetShaderCache()->ReadyShaderProgram(I.samplesQuad->Program);
  }
  if (!I.samplesQuad->Program || !I.samplesQuad->Program->GetCompiled()) {
    this->ReportError("vtkLucentPass: the sampling shader did not compile");
    return false;
  }
  beginDrawing(window->GetState(), I.samplesFbo, {I.samplePosition, I.sampleWeight}, nullptr,
               frame.samplesPerRow, frame.samplesPerRow);
  I.powerAtlas->Activate();
  I.positionAtlas->Activate();
  vtkShaderProgram* program = I.samplesQuad->Program;
  program->SetUniformi("powerAtlas", I.powerAtlas->GetTextureUnit());
  program->SetUniformi("positionAtlas", I.positionAtlas->GetTextureUnit());
  program->SetUniformi("topLevel", frame.topLevel);
  program->SetUniformi("sampleCount", frame.samples);
  program->SetUniformi("samplesPerRow", frame.samplesPerRow);
  const float rotation[2] = {0.5f / float(frame.samples), 0.0f};
  program->SetUniform2f("rotation", rotation);
  I.samplesQuad->Render();
  I.positionAtlas->Deactivate();
  I.powerAtlas->Deactivate();
  endDrawing(I.samplesFbo);
  return true;
}

bool vtkLucentPass::ShadeSurface(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                 const FrameSetup& frame, int width, int height) {
  Internals& I = *this->Impl;
  vtkLucentProfile* profile = I.profiles.at(surface);
  const std::string& shader =
      frame.localTerm ? I.hybridShadeFs : I.shadeFs[profile->IsClosedForm() ? 1 : 0];
  vtkShaderProgram* program = this->BeginPerPixelStage(window, shader, width, height);
  if (program) {
    I.samplePosition->Activate();
    I.sampleWeight->Activate();
    program->SetUniformi("samplePosition", I.samplePosition->GetTextureUnit());
    program->SetUniformi("sampleWeight", I.sampleWeight->GetTextureUnit());
    program->SetUniformi("sampleCount", frame.samples);
    program->SetUniformi("samplesPerRow", frame.samplesPerRow);
    program->SetUniformf("mmPerUnit", float(surface->GetMillimetresPerUnit()));
    program->SetUniform3f("cameraPosition", frame.camera);
    program->SetUniformf("eta", float(frame.material.eta));
    profile->Activate(program);
    if (frame.localTerm) {
      setUniform3(
          program, "worldCentre",
          glm::dvec3(surface->GetCentre()[0], surface->GetCentre()[1], surface->GetCentre()[2]));
      frame.localTerm->Activate(program);
    }
    program->SetUniformMatrix("worldToClip", frame.worldToClip);
    surface->Draw(program,
                  frame.localTerm ? vtkLucentSurface::HybridShade : vtkLucentSurface::Shade);
    if (frame.localTerm) frame.localTerm->Deactivate();
    profile->Deactivate();
    I.sampleWeight->Deactivate();
    I.samplePosition->Deactivate();
  }
  endDrawing(I.translucentFbo);
  if (!program) this->ReportError("vtkLucentPass: the shading shader did not compile");
  return program != nullptr;
}

bool vtkLucentPass::UpdateProfile(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                  const lt::KnobValues& knobs, const FrameSetup& frame) {
  auto& profile = this->Impl->profiles[surface];
  if (!profile) profile = vtkSmartPointer<vtkLucentProfile>::New();
  std::string warning, error;
  try {
    if (!profile->Update(window, frame.material, knobs,
                         surface->GetMillimetreMesh().bounds().diagonal(), warning, error)) {
      this->ReportError(error);
      return false;
    }
  } catch (const std::exception& e) {  // an object too small or too large for the table
    this->ReportError(std::string("vtkLucentPass: the profile's table: ") + e.what());
    return false;
  }
  if (!warning.empty() && warning != this->LastRangeWarning) {
    this->LastRangeWarning = warning;
    vtkWarningMacro(<< "vtkLucentPass (tsis's GPU twin): " << warning);
  }
  return true;
}

bool vtkLucentPass::ShadeTauLut(vtkOpenGLRenderWindow* window, const lt::Technique& taulut,
                                const lt::KnobValues& knobs, vtkLucentSurface* surface,
                                const std::vector<vtkActor*>& inner, const FrameSetup& frame,
                                int width, int height) {
  Internals& I = *this->Impl;
  lt::SceneDescription scene;
  scene.meshName = "the actor's data";
  scene.mesh = surface->GetMillimetreMesh();
  scene.vertexNormals = scene.mesh.vertexNormals();
  scene.medium.material = *lucent::optics::findMaterial(this->Material);  // SetUpFrame checked it
  scene.lights = {frame.lightIn(*surface)};
  scene.parallelFor = lucent::vtkadapter::smpFor;
  // Prepared again only when the geometry or a prepare knob changed; light and material are the
  // frame's.
  std::string key = std::to_string(surface->GetBuildCount());
  for (const auto& k : taulut.knobs)
    if (k.invalidates == lt::Phase::Prepare) key += " " + k.name + "=" + knobs.text(k.name);
  try {
    scene.inclusions = innerBodiesWithin(*surface, inner, key);
  } catch (const std::exception& e) {
    this->ReportError(std::string("vtkLucentPass (") + taulut.name + "): " + e.what());
    return false;
  }
  auto& lut = I.tauLuts[surface];
  if (!lut) lut = vtkSmartPointer<vtkLucentTauLut>::New();
  std::string error;
  if (!lut->Prepare(window, taulut, scene, knobs, key, error) ||
      !lut->RenderLightView(window, surface, scene, error)) {
    this->ReportError("vtkLucentPass (" + taulut.name + "): " + error);
    return false;
  }
  vtkShaderProgram* program = this->BeginPerPixelStage(window, I.tauShadeFs, width, height);
  if (program) {
    program->SetUniformMatrix("worldToClip", frame.worldToClip);
    lut->Shade(window, surface, frame.camera, program);
  }
  endDrawing(I.translucentFbo);
  if (!program) this->ReportError("vtkLucentPass: the taulut shading shader did not compile");
  return program != nullptr;
}

bool vtkLucentPass::ShadeActors(const vtkRenderState* s, vtkOpenGLRenderWindow* window, int width,
                                int height) {
  Internals& I = *this->Impl;
  vtkRenderer* renderer = s->GetRenderer();
  this->ClearTranslucentTargets(window->GetState(), width,
                                height);  // empty even when nothing is translucent
  const bool automatic = this->Technique == lucent::plan::kAutomatic;
  const lt::Technique* twin = automatic ? nullptr : twinNamed(this->Technique);
  if (!automatic && !twin) {
    std::string names;
    for (const lt::Technique* t : twins()) names += t->name + ", ";
    this->ReportError("vtkLucentPass: technique '" + this->Technique +
                      "' has no GPU twin here; use one of: " + names + lucent::plan::kAutomatic);
    return false;
  }
  lt::KnobValues knobs;
  try {
    if (twin) knobs = this->TwinValues(*twin);
  } catch (const std::exception& e) {
    this->ReportError(std::string("vtkLucentPass: ") + e.what());
    return false;
  }
  FrameSetup frame;
  if (!this->SetUpFrame(renderer, frame)) return false;

  std::map<vtkActor*, vtkSmartPointer<vtkLucentSurface>> seen;
  const std::vector<vtkActor*> actors = opaqueActors(renderer);
  std::vector<vtkActor*> inner;
  for (vtkActor* actor : actors)
    if (isInnerBody(actor)) inner.push_back(actor);
  if (twin && !inner.empty() && !twin->capabilities.inclusions)
    this->ReportError("vtkLucentPass: " + twin->name + " takes no inner bodies (" +
                      std::to_string(inner.size()) + " actors carry " +
                      lucent::vtkadapter::kInnerMaterialArray +
                      "; they are not drawn as translucent); use a technique that does: taulut");
  for (vtkActor* actor : actors) {
    if (isInnerBody(actor)) continue;  // shaded as part of the object around it
    auto found = I.surfaces.find(actor);
    vtkSmartPointer<vtkLucentSurface> surface =
        found != I.surfaces.end() ? found->second : vtkSmartPointer<vtkLucentSurface>::New();
    seen[actor] = surface;
    std::string error;
    if (!surface->Update(actor, this->SizeMm, frame.atlasSize, error))
      continue;  // lines, points: not ours
    const lt::Technique* actorTwin = twin;
    lt::KnobValues actorKnobs = knobs;
    if (automatic &&
        !this->PlanActor(renderer, surface, inner, width, height, frame, actorTwin, actorKnobs))
      continue;  // reported; the other actors are still drawn
    if (!automatic) this->ChosenTechnique = lucent::plan::settingText(*actorTwin, actorKnobs);
    ++this->TranslucentActorCount;
    this->WarnOutsideRange(*surface, *actorTwin, actorKnobs);
    if (!this->ShadeActor(window, *actorTwin, actorKnobs, surface, inner, frame, width, height))
      return false;
  }
  // Actors gone from the renderer give their buffers back.
  for (auto& [actor, surface] : I.surfaces)
    if (!seen.count(actor)) {
      surface->ReleaseGraphicsResources(window);
      I.rangeChecked.erase(surface.Get());
      if (auto lut = I.tauLuts.find(surface.Get()); lut != I.tauLuts.end()) {
        lut->second->ReleaseGraphicsResources(window);
        I.tauLuts.erase(lut);
      }
      if (auto p = I.profiles.find(surface.Get()); p != I.profiles.end()) {
        p->second->ReleaseGraphicsResources(window);
        I.profiles.erase(p);
      }
      if (auto l = I.localTerms.find(surface.Get()); l != I.localTerms.end()) {
        l->second->ReleaseGraphicsResources(window);
        I.localTerms.erase(l);
      }
      I.plans.erase(surface.Get());
    }
  I.surfaces = std::move(seen);
  return this->TranslucentActorCount > 0;
}

bool vtkLucentPass::ShadeActor(vtkOpenGLRenderWindow* window, const lt::Technique& twin,
                               const lt::KnobValues& knobs, vtkLucentSurface* surface,
                               const std::vector<vtkActor*>& inner, FrameSetup& frame, int width,
                               int height) {
  if (twin.name == "taulut")
    return this->ShadeTauLut(window, twin, knobs, surface, inner, frame, width, height);
  if (twin.name == "diffuse-brdf")
    return this->ShadeDiffuseBrdf(window, surface, knobs, frame, width, height);
  frame.samples = int(knobs.integer("samples"));
  frame.localTerm = nullptr;
  if (twin.name == "hybrid")
    return this->UpdateLocalTerm(window, surface, knobs, frame) &&
           this->ShadeTsis(window, surface, frame, width, height);
  return this->UpdateProfile(window, surface, knobs, frame) &&
         this->ShadeTsis(window, surface, frame, width, height);
}

bool vtkLucentPass::UpdateLocalTerm(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                    const lt::KnobValues& knobs, FrameSetup& frame) {
  Internals& I = *this->Impl;
  auto& local = I.localTerms[surface];
  if (!local) local = vtkSmartPointer<vtkLucentLocalTerm>::New();
  auto& profile = I.profiles[surface];
  if (!profile) profile = vtkSmartPointer<vtkLucentProfile>::New();
  std::string error;
  const double diagonal = surface->GetMillimetreMesh().bounds().diagonal();
  const bool ok =
      local->Update(window, frame.material, knobs, diagonal, error) &&
      profile->UpdateTable(window, "hybrid Rd Wg " + local->GetKey(),
                           local->GetSplit()->tables.global, local->GetSplit()->profile.exitScale,
                           error) &&
      local->RenderMap(window, surface, frame.lightIn(*surface), float(frame.material.eta), error);
  if (!ok) {
    this->ReportError("vtkLucentPass (hybrid): " + error);
    return false;
  }
  frame.localTerm = local;
  return true;
}

bool vtkLucentPass::ShadeTsis(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                              FrameSetup& frame, int width, int height) {
  Internals& I = *this->Impl;
  frame.samplesPerRow = int(std::ceil(std::sqrt(double(frame.samples))));
  if (int(I.samplePosition->GetWidth()) != frame.samplesPerRow) {
    I.samplePosition->Resize(unsigned(frame.samplesPerRow), unsigned(frame.samplesPerRow));
    I.sampleWeight->Resize(unsigned(frame.samplesPerRow), unsigned(frame.samplesPerRow));
  }
  return this->RenderLightDepth(window, surface, frame) &&
         this->RenderAtlasIrradiance(window, surface, frame) &&
         this->DrawImportanceSamples(window, frame) &&
         this->ShadeSurface(window, surface, frame, width, height);
}

bool vtkLucentPass::ShadeDiffuseBrdf(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                     const lt::KnobValues& knobs, FrameSetup& frame, int width,
                                     int height) {
  Internals& I = *this->Impl;
  lucent::optics::Profile<double> profile;  // Rd_total and the exit scale, as the CPU takes them
  try {
    profile = lt::detail::profileOf<double>(frame.material, knobs);
  } catch (const std::exception& e) {
    this->ReportError(std::string("vtkLucentPass (diffuse-brdf): ") + e.what());
    return false;
  }
  const glm::vec3 total(profile.total());
  if (!this->RenderLightDepth(window, surface, frame)) return false;
  vtkShaderProgram* program = this->BeginPerPixelStage(window, I.diffuseShadeFs, width, height);
  if (program) {
    this->SetLightUniforms(program, frame);
    program->SetUniform3f("cameraPosition", frame.camera);
    program->SetUniform3f("totalDiffuseReflectance", glm::value_ptr(total));
    program->SetUniformf("exitScale", float(profile.exitScale));
    program->SetUniformMatrix("worldToClip", frame.worldToClip);
    surface->Draw(program, vtkLucentSurface::Shade);
    I.lightDepth->Deactivate();
  }
  endDrawing(I.translucentFbo);
  if (!program) this->ReportError("vtkLucentPass: the diffuse-brdf shader did not compile");
  return program != nullptr;
}

void vtkLucentPass::SetCalibrationDirectory(const char* dir) {
  const std::string value = dir ? dir : "";
  if (value == this->CalibrationDirectory) return;
  this->CalibrationDirectory = value;
  this->Impl->calibration.reset();
  this->Impl->plans.clear();
  this->Modified();
}

namespace {
/// The frame's camera in the surface's millimetre frame (centred on it, scaled), for the plan.
FrameView frameView(vtkRenderer* renderer, const vtkLucentSurface& surface, int width, int height) {
  vtkCamera* camera = renderer->GetActiveCamera();
  const double scale = surface.GetMillimetresPerUnit();
  const glm::dvec3 centre(surface.GetCentre()[0], surface.GetCentre()[1], surface.GetCentre()[2]);
  double eye[3], focal[3];
  camera->GetPosition(eye);
  camera->GetFocalPoint(focal);
  FrameView v;
  v.camera.eye = (glm::dvec3(eye[0], eye[1], eye[2]) - centre) * scale;
  v.camera.target = (glm::dvec3(focal[0], focal[1], focal[2]) - centre) * scale;
  v.camera.verticalFovDeg = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle())  // the angle spans the width: the height's share of it
    v.camera.verticalFovDeg =
        2 *
        std::atan(std::tan(0.5 * camera->GetViewAngle() * lucent::optics::kPi / 180) *
                  double(std::max(1, height)) / double(std::max(1, width))) *
        180 / lucent::optics::kPi;
  v.camera.width = std::max(1, width), v.camera.height = std::max(1, height);
  if (camera->GetParallelProjection())
    v.parallelPixelMm = 2 * camera->GetParallelScale() * scale / double(v.camera.height);
  return v;
}
}  // namespace

bool vtkLucentPass::PlanActor(vtkRenderer* renderer, vtkLucentSurface* surface,
                              const std::vector<vtkActor*>& inner, int width, int height,
                              const FrameSetup& frame, const lt::Technique*& twin,
                              lt::KnobValues& knobs) {
  Internals& I = *this->Impl;
  try {
    if (!I.calibration)
      I.calibration = std::make_unique<lucent::plan::Calibration>(lucent::plan::readCalibration(
          lucent::plan::calibrationDirectory(this->CalibrationDirectory, LUCENT_SOURCE_DATA_DIR)));
    const FrameView view = frameView(renderer, *surface, width, height);
    // Planned again when the pixel at the object changes by 5 %, the camera changes sides, or what
    // else the plan reads changes: the mesh, its inner bodies, the material, light and limits.
    std::string key = viewKey(view, frame.towardLight) + " " +
                      std::to_string(surface->GetBuildCount()) + " " + frame.material.name + " " +
                      std::to_string(this->MaxError) + " " + std::to_string(this->AtlasResolution);
    lucent::util::Fingerprint light;  // a directional or a point light, as the plan reads it
    lt::detail::addLight(light, frame.lightIn(*surface));
    key += " " + light.hex();
    for (vtkActor* actor : inner) key += innerBodyKey(actor);
    auto& [plannedFor, plan] = I.plans[surface];
    if (plannedFor != key || !plan.twin) {
      lt::SceneDescription scene;
      scene.mesh = surface->GetMillimetreMesh();
      scene.medium.material = frame.material;
      scene.lights = {frame.lightIn(*surface)};
      std::string innerKey;
      scene.inclusions = innerBodiesWithin(*surface, inner, innerKey);
      lucent::plan::Budget budget;
      if (this->MaxError > 0) budget.error = this->MaxError;
      plannedFor.clear();  // a plan that throws leaves no key behind
      plan = planView(registry(), scene, view, *I.calibration, budget,
                      {{"atlas-resolution", std::to_string(this->AtlasResolution)}});
      plannedFor = key;
    }
    twin = plan.twin;
    knobs = plan.knobs;
    this->ChosenTechnique = plan.setting;
    this->LastPlan.clear();
    for (const auto& line : plan.explanation) this->LastPlan += line + "\n";
    return true;
  } catch (const std::exception& e) {
    this->ReportError(std::string("vtkLucentPass: ") + e.what());
    return false;
  }
}

void vtkLucentPass::Composite(vtkOpenGLRenderWindow* window) {
  Internals& I = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  if (!I.compositeQuad) {
    const std::string fs = withSharedGlsl(lucent::glsl::kCompositeFrag);
    I.compositeQuad = new vtkOpenGLQuadHelper(
        window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
  } else {
    window->GetShaderCache()->ReadyShaderProgram(I.compositeQuad->Program);
  }
  if (!I.compositeQuad->Program || !I.compositeQuad->Program->GetCompiled()) {
    this->ReportError("vtkLucentPass: the composite shader did not compile");
    return;
  }
  vtkShaderProgram* program = I.compositeQuad->Program;
  I.sceneColor->Activate();
  I.sceneDepth->Activate();
  I.translucentRadiance->Activate();
  I.translucentDepth->Activate();
  program->SetUniformi("sceneColor", I.sceneColor->GetTextureUnit());
  program->SetUniformi("sceneDepth", I.sceneDepth->GetTextureUnit());
  program->SetUniformi("translucentRadiance", I.translucentRadiance->GetTextureUnit());
  program->SetUniformi("translucentDepth", I.translucentDepth->GetTextureUnit());
  program->SetUniformf("exposure", float(this->Exposure));
  program->SetUniformf("surfaceWeight", float(this->SurfaceWeight));
  program->SetUniformf("depthTolerance", 1e-4f);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  I.compositeQuad->Render();
  I.translucentDepth->Deactivate();
  I.translucentRadiance->Deactivate();
  I.sceneDepth->Deactivate();
  I.sceneColor->Deactivate();
}

void vtkLucentPass::ReadBackFrame(int width, int height) {
  Internals& I = *this->Impl;
  I.frameWidth = width;
  I.frameHeight = height;
  std::vector<float>* targets[3] = {&I.frameRadiance, &I.framePosition, &I.frameNormal};
  I.translucentFbo->SaveCurrentBindingsAndBuffers();
  I.translucentFbo->Bind(GL_READ_FRAMEBUFFER);
  for (unsigned k = 0; k < 3; ++k) {
    targets[k]->assign(std::size_t(width) * std::size_t(height) * 4, 0.0f);
    I.translucentFbo->ActivateReadBuffer(k);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, targets[k]->data());
  }
  I.translucentFbo->UnBind(GL_READ_FRAMEBUFFER);
  I.translucentFbo->RestorePreviousBindingsAndBuffers();
}

bool vtkLucentPass::GetLastFrame(int& width, int& height, std::vector<float>& radiance,
                                 std::vector<float>& position, std::vector<float>& normal) const {
  const Internals& I = *this->Impl;
  if (I.frameRadiance.empty()) return false;
  width = I.frameWidth;
  height = I.frameHeight;
  radiance = I.frameRadiance;
  position = I.framePosition;
  normal = I.frameNormal;
  return true;
}

void vtkLucentPass::Render(const vtkRenderState* s) {
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->TranslucentActorCount = 0;
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(
      state);  // the stages set their own; the caller's comes back
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  if (!this->DelegatePass) {
    vtkWarningMacro("no delegate in vtkLucentPass: set one, e.g. a vtkRenderStepsPass");
    return;
  }
  int x, y, width, height;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  this->InitializeGraphicsResources(window, width, height);

  state->vtkglDisable(GL_BLEND);  // full-screen and atlas passes must not blend
  this->RenderDelegateWithDepth(s, width, height);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_CULL_FACE);
  if (this->ShadeActors(s, window, width, height)) this->LastError.clear();
  state->vtkglViewport(x, y, width, height);
  state->vtkglScissor(x, y, width, height);
  this->Composite(window);
  if (this->KeepFrame) this->ReadBackFrame(width, height);
  vtkOpenGLCheckErrorMacro("failed after Render");
}

void vtkLucentPass::ReleaseGraphicsResources(vtkWindow* w) {
  this->Superclass::ReleaseGraphicsResources(w);
  Internals& I = *this->Impl;
  delete I.samplesQuad;
  I.samplesQuad = nullptr;
  delete I.compositeQuad;
  I.compositeQuad = nullptr;
  for (auto& entry : I.surfaces) entry.second->ReleaseGraphicsResources(w);
  I.surfaces.clear();
  for (auto& entry : I.tauLuts) entry.second->ReleaseGraphicsResources(w);
  I.tauLuts.clear();
  for (auto& entry : I.profiles) entry.second->ReleaseGraphicsResources(w);
  I.profiles.clear();
  for (auto& entry : I.localTerms) entry.second->ReleaseGraphicsResources(w);
  I.localTerms.clear();
  I.rangeChecked.clear();
  I.plans.clear();  // keyed by the surfaces just released
  for (auto* fbo : {I.sceneFbo.Get(), I.translucentFbo.Get(), I.lightFbo.Get(), I.atlasFbo.Get(),
                    I.samplesFbo.Get()})
    if (fbo) fbo->ReleaseGraphicsResources(w);
  for (auto* t : {I.sceneColor.Get(), I.sceneDepth.Get(), I.translucentRadiance.Get(),
                  I.translucentPosition.Get(), I.translucentNormal.Get(), I.translucentDepth.Get(),
                  I.lightDepth.Get(), I.powerAtlas.Get(), I.positionAtlas.Get(),
                  I.samplePosition.Get(), I.sampleWeight.Get()})
    if (t) t->ReleaseGraphicsResources(w);
  I.sceneFbo = I.translucentFbo = I.lightFbo = I.atlasFbo = I.samplesFbo = nullptr;
  I.sceneColor = I.sceneDepth = I.translucentRadiance = I.translucentPosition =
      I.translucentNormal = nullptr;
  I.translucentDepth = I.lightDepth = I.powerAtlas = I.positionAtlas = I.samplePosition =
      I.sampleWeight = nullptr;
}
