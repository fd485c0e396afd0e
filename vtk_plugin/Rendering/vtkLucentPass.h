/// @file vtkLucentPass.h
/// @brief Translucent (subsurface-scattering) rendering on the GPU as a vtkImageProcessingPass:
/// the GPU twins of the techniques that declare this pass their twin (`lucent techniques`):
/// texture-space importance sampling (tsis, Chang et al. 2008 Sec. 3; the default, stages below),
/// the hybrid (Sec. 4: the same stages with Rd Wg, plus the local term Rd Wl by a ring filter over
/// a translucent shadow map drawn from the light, vtkLucentLocalTerm.h), the voxel
/// optical-thickness LUT (taulut, Mochida et al. 2016: vtkLucentTauLut.h) and the diffuse BRDF
/// with Rd_total (diffuse-brdf), or "auto": the planner's choice per frame (SetMaxError).
///
/// Every visible, opaque vtkActor with polygons in the renderer is shaded as one homogeneous
/// translucent object (light does not cross from one actor to another), except actors whose data
/// is marked as an inner body (lucent::vtkadapter::markInnerBody, field data LucentInnerMaterial):
/// taulut fills them with their material inside the actor around them (the wine in a bottle);
/// tsis takes none and reports them. A cavity is an inner shell of the actor's own surface. Per
/// frame and per actor:
///  0. depth of the object from the light (shadows);
///  1. irradiance E' = E A_S / A_T rendered into the object's texture atlas, with the position map
///  (Eq. 4-7);
///  2. N texels drawn in proportion to E' by descending the atlas's mip chain (Sec. 3.2, Fig. 2b);
///  3. every pixel sums R(|x_i - x_o|) w_i over the N samples, L = Ft B / pi (Eq. 10-11), R the
///  profile of tsis's `profile` knob: its radial table, or a dipole in closed form with rd=exact
///  (vtkLucentProfile);
///  4. the translucent radiance replaces the delegate's shading where the object is visible.
/// The light: LightDirection (directional), or else the renderer's first switched-on light: from
/// its position towards its focal point, and a point light at its position when it is positional
/// (its irradiance given at its focal point). GLSL: shaders/ (constants generated from
/// lucent/optics/constants.hpp). Built on a GL 3.2 core context; checked on Mesa llvmpipe.
///
/// Usage, as with VTK's own passes:
/// @code
///   vtkNew<vtkLucentPass> lucent;  lucent->SetDelegatePass(cameraPass); renderer->SetPass(lucent);
/// @endcode
/// or, without a pass chain, lucent->SetDelegatePass(vtkNew<vtkRenderStepsPass>()).
#ifndef vtkLucentPass_h
#define vtkLucentPass_h

#include <map>
#include <string>
#include <vector>

#include <vtkImageProcessingPass.h>
#include "LucentRenderingModule.h"

class vtkActor;
class vtkLucentSurface;
#ifndef __VTK_WRAP__
namespace lucent::technique {
class KnobValues;
struct Technique;
}  // namespace lucent::technique
#endif
class vtkOpenGLFramebufferObject;
class vtkOpenGLState;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

class LUCENTRENDERING_EXPORT vtkLucentPass : public vtkImageProcessingPass {
 public:
  static vtkLucentPass* New();
  vtkTypeMacro(vtkLucentPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /// Measured material by name (`lucent materials` lists them). Default skin1. An unknown name is
  /// reported once and renders nothing translucent.
  void SetMaterial(const char* name);
  const char* GetMaterial() const { return this->Material.c_str(); }
  ///@}

  ///@{
  /// Object size: 0 = world units are mm; > 0 = each actor is scaled so its bounding-box diagonal
  /// is this.
  vtkSetClampMacro(SizeMm, double, 0.0, 1.0e9);
  vtkGetMacro(SizeMm, double);
  ///@}

  ///@{
  /// The technique whose GPU twin shades the actors: one of the registry's techniques that declare
  /// vtkLucentPass as their twin (`lucent techniques`: tsis, the default, hybrid, taulut,
  /// diffuse-brdf), or "auto". An unknown name is reported once and renders nothing translucent.
  void SetTechnique(const char* name);
  const char* GetTechnique() const { return this->Technique.c_str(); }
  static int GetNumberOfTechniques();
  static std::string GetTechniqueName(int i);
  ///@}

  ///@{
  /// Technique "auto" (lucent::plan::kAutomatic): each frame, for each actor as the camera sees it,
  /// the planner's choice among the twins (lucentPassPlanner.h): diffuse-brdf's when Rd's reach is
  /// below a pixel, else tsis with the fewest samples predicted to meet MaxError (relative RMS
  /// against the physical truth; 0: the planner's default target). The calibration is the
  /// planner's (empty CalibrationDirectory: $LUCENT_DATA_DIR/planner, else the source tree's
  /// data/planner); its times rank settings by cost, they are not GPU times.
  vtkSetClampMacro(MaxError, double, 0.0, 1.0e3);
  vtkGetMacro(MaxError, double);
  void SetCalibrationDirectory(const char* dir);
  const char* GetCalibrationDirectory() const { return this->CalibrationDirectory.c_str(); }
  /// The last actor's technique and knobs as planned, and the plan's reasons (one per line).
  const char* GetChosenTechnique() const { return this->ChosenTechnique.c_str(); }
  const char* GetLastPlan() const { return this->LastPlan.c_str(); }
  ///@}

  ///@{
  /// A knob the twin shares with its technique, by qualified name ("taulut.voxels"): same name,
  /// default and lower bound as the technique declares; numbers are clamped to the twin's own
  /// upper bound (Capabilities::gpuTwinKnobs). A bad choice is reported when the frame is drawn.
  /// SetSamples and SetAtlasResolution are tsis.samples and tsis.atlas-resolution (the atlas
  /// rounded up to a power of two for the mip pyramid); with the hybrid, the pass's atlas is
  /// hybrid.atlas-resolution.
  void SetKnob(const char* qualifiedName, const char* value);
  void SetKnobInteger(const char* qualifiedName, int value);
  void SetKnobReal(const char* qualifiedName, double value);
  std::string GetKnob(const char* qualifiedName) const;
  void SetSamples(int n);
  int GetSamples() const { return this->Samples; }
  void SetAtlasResolution(int texels);
  int GetAtlasResolution() const { return this->AtlasResolution; }
  ///@}

  ///@{
  /// The light's depth map resolution (tsis's shadows): the pass's own.
  vtkSetClampMacro(ShadowMapResolution, int, 16, 8192);
  vtkGetMacro(ShadowMapResolution, int);
  ///@}

  ///@{
  /// Direction towards the light in world coordinates; (0, 0, 0), the default, takes the renderer's
  /// first switched-on light instead (from its position towards its focal point).
  vtkSetVector3Macro(LightDirection, double);
  vtkGetVector3Macro(LightDirection, double);
  ///@}

  ///@{
  /// Irradiance of the light on a surface facing it (times the scene light's intensity and colour).
  vtkSetClampMacro(LightIrradiance, double, 0.0, 1.0e12);
  vtkGetMacro(LightIrradiance, double);
  ///@}

  ///@{
  /// Display: radiance times Exposure, then x / (1 + x) and sRGB; SurfaceWeight of the delegate's
  /// own shading of the object is kept on top (0 = subsurface only).
  vtkSetClampMacro(Exposure, double, 0.0, 1.0e12);
  vtkGetMacro(Exposure, double);
  vtkSetClampMacro(SurfaceWeight, double, 0.0, 1.0);
  vtkGetMacro(SurfaceWeight, double);
  ///@}

  ///@{
  /// Keep the last frame's per-pixel translucent radiance, world position and normal for
  /// GetLastFrame (tests and sweeps read them back; costs a read-back per frame).
  vtkSetMacro(KeepFrame, bool);
  vtkGetMacro(KeepFrame, bool);
  vtkBooleanMacro(KeepFrame, bool);
  ///@}

  /// The frame kept by KeepFrame: width * height RGBA floats each. radiance.a = 1 where a
  /// translucent surface is drawn; normal.a = the cosine to the camera. False when nothing was
  /// kept.
  bool GetLastFrame(int& width, int& height, std::vector<float>& radiance,
                    std::vector<float>& position, std::vector<float>& normal) const;

  /// Actors shaded in the last frame, and the last problem met (empty when none).
  vtkGetMacro(TranslucentActorCount, int);
  const char* GetLastError() const { return this->LastError.c_str(); }

 protected:
  vtkLucentPass();
  ~vtkLucentPass() override;

 private:
  vtkLucentPass(const vtkLucentPass&) = delete;
  void operator=(const vtkLucentPass&) = delete;

  struct Internals;
  Internals* Impl;

  struct FrameSetup;  // the light, the material, target sizes and the camera of one frame

  void InitializeGraphicsResources(vtkOpenGLRenderWindow* window, int width, int height);
  void RenderDelegateWithDepth(const vtkRenderState* s, int width, int height);
  /// Runs the four stages for every translucent actor; false when nothing translucent was drawn.
  bool ShadeActors(const vtkRenderState* s, vtkOpenGLRenderWindow* window, int width, int height);
  bool SetUpFrame(vtkRenderer* renderer, FrameSetup& frame);
  bool ResolveLight(vtkRenderer* renderer, FrameSetup& frame);
  /// The light's view of an object (centre, radius in world units) for its depth map:
  /// orthographic for a directional light, perspective from a point light; false (reported) when
  /// a point light is inside the object's bounding sphere.
  bool LightTransform(FrameSetup& frame, const double centre[3], double radius);
  void ClearTranslucentTargets(vtkOpenGLState* state, int width, int height);
  /// Stage 0: depth from the light, orthographic over the object's bounding sphere.
  bool RenderLightDepth(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                        FrameSetup& frame);
  /// Stage 1: E' into the atlas (Eq. 4-7) with the position map, and its mip chain (Fig. 2b).
  bool RenderAtlasIrradiance(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                             const FrameSetup& frame);
  /// Binds the translucent targets with depth testing and readies the per-pixel program
  /// (shaders/tsis_shade.vert with `fragmentShader`); null when it does not compile.
  vtkShaderProgram* BeginPerPixelStage(vtkOpenGLRenderWindow* window,
                                       const std::string& fragmentShader, int width, int height);
  /// The light's uniforms of shaders/light.glsl (binds the light's depth map).
  void SetLightUniforms(vtkShaderProgram* program, const FrameSetup& frame);
  /// Stage 2: N samples by hierarchical warping down the mip chain.
  bool DrawImportanceSamples(vtkOpenGLRenderWindow* window, const FrameSetup& frame);
  /// Stage 3: every pixel sums the samples (Eq. 10-11), depth-tested among translucent actors.
  bool ShadeSurface(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                    const FrameSetup& frame, int width, int height);
  /// Stages 0-3 of tsis's twin for one actor with `samples` importance samples.
  bool ShadeTsis(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface, FrameSetup& frame,
                 int width, int height);
  void Composite(vtkOpenGLRenderWindow* window);
#ifndef __VTK_WRAP__
  /// diffuse-brdf's twin: depth from the light, then every pixel Rd_total E (no samples), with
  /// Rd_total of the profile `knobs` name.
  bool ShadeDiffuseBrdf(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                        const lucent::technique::KnobValues& knobs, FrameSetup& frame, int width,
                        int height);
  /// taulut's twin for one actor: prepare (when its geometry or prepare knobs changed), light
  /// view, per-pixel sum.
  bool ShadeTauLut(vtkOpenGLRenderWindow* window, const lucent::technique::Technique& taulut,
                   const lucent::technique::KnobValues& knobs, vtkLucentSurface* surface,
                   const std::vector<vtkActor*>& inner, const FrameSetup& frame, int width,
                   int height);
  /// Technique auto: the plan for this actor in this frame (cached while what it reads holds).
  bool PlanActor(vtkRenderer* renderer, vtkLucentSurface* surface,
                 const std::vector<vtkActor*>& inner, int width, int height,
                 const FrameSetup& frame, const lucent::technique::Technique*& twin,
                 lucent::technique::KnobValues& knobs);
  /// One actor by `twin` with `knobs`.
  bool ShadeActor(vtkOpenGLRenderWindow* window, const lucent::technique::Technique& twin,
                  const lucent::technique::KnobValues& knobs, vtkLucentSurface* surface,
                  const std::vector<vtkActor*>& inner, FrameSetup& frame, int width, int height);
  /// tsis's profile and rd knobs for this actor's stage 3 (vtkLucentProfile).
  bool UpdateProfile(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                     const lucent::technique::KnobValues& knobs, const FrameSetup& frame);
  /// The technique's knobs as its twin takes them (the given ones clamped to the twin's range).
  lucent::technique::KnobValues TwinValues(const lucent::technique::Technique& t) const;
  void RefreshAtlasKnobs();
  /// The hybrid's split, global table and translucent shadow map for this actor
  /// (vtkLucentLocalTerm); sets frame.localTerm, which stage 3 then adds.
  bool UpdateLocalTerm(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                       const lucent::technique::KnobValues& knobs, FrameSetup& frame);
#endif
  void ReadBackFrame(int width, int height);
  void ReportError(const std::string& message);
#ifndef __VTK_WRAP__
  void WarnOutsideRange(const vtkLucentSurface& surface, const lucent::technique::Technique& t,
                        const lucent::technique::KnobValues& knobs);
#endif

  std::string Material = "skin1";
  std::string Technique = "tsis";
  std::map<std::string, std::string> Knobs;  ///< qualified name -> value (tsis's: Samples, ...)
  double SizeMm = 0.0;
  int Samples = 0;          // the technique's samples, or tsis's (RefreshAtlasKnobs)
  int AtlasResolution = 0;  // the technique's atlas-resolution, or tsis's
  int ShadowMapResolution = 1024;
  double LightDirection[3] = {0.0, 0.0, 0.0};
  double LightIrradiance = 1.0;
  double Exposure = 1.0;
  double SurfaceWeight = 0.25;
  double MaxError = 0.0;
  std::string CalibrationDirectory;
  std::string ChosenTechnique, LastPlan;
  bool KeepFrame = false;
  int TranslucentActorCount = 0;
  std::string LastError;
  std::string LastRangeWarning;  ///< once per reason, not every frame
};

#endif
