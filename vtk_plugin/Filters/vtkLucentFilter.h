/// @file vtkLucentFilter.h
/// @brief Translucent shading of a closed surface on the CPU, by any technique of lucent's registry
/// that shades vertices (lucent/technique: reference, jensen-buhler, tsis, hybrid, tsm; `lucent
/// techniques`): per-vertex radiosity B of subsurface scattering (L = Ft B / pi) under one
/// directional light with Fresnel-transmitted, shadowed irradiance.
///
/// Knobs are the technique's own, by qualified name ("tsis.samples"), set with SetKnob; their
/// types, defaults and ranges live in the technique's description only, and the ParaView properties
/// ("TsisSamples", the mechanical CamelCase) are generated from it. Values are checked when the
/// filter runs.
///
/// Input: a surface (vtkPolyData) or a composite of surfaces, shaded as one. A block whose field
/// data holds the string array LucentInnerMaterial (lucent::vtkadapter::markInnerBody) is an inner
/// body of that material inside the surface (the wine in a bottle; techniques that take inclusions:
/// taulut, voxel-single, pathtrace) and is not part of the output; a cavity is an inner shell of
/// the surface itself, wound inward. Inner bodies need one process. Output: the input triangulated
/// and welded (lucentPolyDataMesh.h), with point arrays "Radiosity" (3 floats, irradiance units;
/// techniques that compute B), "Radiance" (3 floats, seen head-on) and "TranslucentColor" (3
/// unsigned chars, Exposure * B (else the radiance) tone-mapped x / (1 + x), sRGB-encoded, the
/// active scalars). Lengths: the data's units are millimetres, or the data is scaled so its
/// bounding-box diagonal is SizeMm. Reports progress (ProgressEvent) through every stage.
#ifndef vtkLucentFilter_h
#define vtkLucentFilter_h

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vtkPolyDataAlgorithm.h>
#include "LucentFiltersModule.h"

class vtkMultiProcessController;
#ifndef __VTK_WRAP__
namespace lucent::technique {
class KnobValues;
struct Technique;
class Registry;
struct Rendered;
struct Medium;
struct SceneDescription;
struct ShadeRequest;
}  // namespace lucent::technique
namespace lucent::vtkadapter {
struct PolyDataMesh;
}
#endif

class LUCENTFILTERS_EXPORT vtkLucentFilter : public vtkPolyDataAlgorithm {
 public:
  static vtkLucentFilter* New();
  vtkTypeMacro(vtkLucentFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Measured material by name (`lucent materials` lists them): skin1, marble, ketchup, ... Default
  /// skin1.
  void SetMaterial(const char* name);
  const char* GetMaterial() const { return this->Material.c_str(); }
  ///@}

  ///@{
  /// Object size: 0 (default) = the data's units are mm; > 0 = scale so the bounding-box diagonal
  /// is this.
  vtkSetClampMacro(SizeMm, double, 0.0, 1.0e6);
  vtkGetMacro(SizeMm, double);
  ///@}

  ///@{
  /// Direction towards the light (need not be unit) and the irradiance it gives a surface facing
  /// it.
  vtkSetVector3Macro(LightDirection, double);
  vtkGetVector3Macro(LightDirection, double);
  vtkSetClampMacro(LightIrradiance, double, 0.0, 1.0e6);
  vtkGetMacro(LightIrradiance, double);
  ///@}

  ///@{
  /// An environment map that lights the surface instead of the directional light: an OpenEXR file
  /// holding a lat-long probe or a cube map (6N x N or N x 6N strips, 4N x 3N or 3N x 4N crosses),
  /// its radiance times EnvironmentScale. Empty (the default): the directional light. prt needs
  /// one; its knob prt.rotate turns it, and re-runs only the frame.
  void SetEnvironmentFileName(const char* path);
  const char* GetEnvironmentFileName() const { return this->EnvironmentFileName.c_str(); }
  vtkSetClampMacro(EnvironmentScale, double, 0.0, 1.0e12);
  vtkGetMacro(EnvironmentScale, double);
  ///@}

  ///@{
  /// The last run: whether it reused the precomputation of the run before (the same surface,
  /// technique and prepare-phase knobs, and the same material and light unless the technique's
  /// frame takes them, lucent/technique/prepared_cache.hpp), and the seconds of its prepare and
  /// frame.
  vtkGetMacro(PrepareReused, bool);
  vtkGetMacro(PrepareSeconds, double);
  vtkGetMacro(FrameSeconds, double);
  ///@}

  ///@{
  /// The technique, by its registry name; default the first offered (the ground truth, reference).
  /// GetTechniqueName(i) lists those offered. "auto" (lucent::plan::kAutomatic): the planner's
  /// choice for this surface, material and light within BudgetMs and MaxError (`lucent plan`). The
  /// default hands a scene it cannot take (a scan's heterogeneous medium) to the planner too; the
  /// output's field data "LucentPlan" says so.
  void SetTechnique(const char* name);
  const char* GetTechnique() const { return this->Technique.c_str(); }
  static int GetNumberOfTechniques();
  static std::string GetTechniqueName(int i);
  ///@}

  ///@{
  /// The limits Technique "auto" plans within: BudgetMs, time for one run (0: none); MaxError,
  /// relative RMS against the physical truth (0: none; with neither, the planner's default
  /// target). The plan, one line per decision with the measured figures it rests on, is the
  /// output's field data "LucentPlan".
  vtkSetClampMacro(BudgetMs, double, 0.0, 1.0e12);
  vtkGetMacro(BudgetMs, double);
  vtkSetClampMacro(MaxError, double, 0.0, 1.0e3);
  vtkGetMacro(MaxError, double);
  ///@}

  ///@{
  /// The planner's measured data (settings.csv, model-floors.csv). Empty, the default:
  /// $LUCENT_DATA_DIR/planner, else the source tree's data/planner.
  void SetCalibrationDirectory(const char* dir);
  const char* GetCalibrationDirectory() const { return this->CalibrationDirectory.c_str(); }
  ///@}

  /// The technique and knobs of the last run ("tsis: samples=400", the planner's choice with
  /// "auto"); also the output's field data "LucentTechnique".
  const char* GetChosenTechnique() const { return this->ChosenTechnique.c_str(); }

  ///@{
  /// A knob of any offered technique by its qualified name, e.g. SetKnob("tsis.samples", "4096").
  /// The typed forms are what the ParaView properties call. GetKnob gives the value set, else the
  /// technique's default.
  void SetKnob(const char* qualifiedName, const char* value);
  void SetKnobInteger(const char* qualifiedName, int value);
  void SetKnobReal(const char* qualifiedName, double value);
  std::string GetKnob(const char* qualifiedName) const;
  ///@}

  ///@{
  /// The knob properties of every offered technique, in registry order: the property name
  /// ("TsisSamples") and the qualified knob name ("tsis.samples") of each.
  static int GetNumberOfKnobProperties();
  static std::string GetKnobPropertyName(int i);
  static std::string GetKnobQualifiedName(int i);
  ///@}

  ///@{
  /// Exposure of the colour array (the radiosity array is not affected).
  vtkSetClampMacro(Exposure, double, 0.0, 1.0e6);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /// The processes a distributed surface is split across (pvbatch --mpi, pvserver); default the
  /// global controller. With more than one, every rank gathers all ranks' triangles and shades its
  /// own vertices from the whole surface (lucentSurfaceGather.h), so the result equals the
  /// one-process result.
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController() const { return this->Controller; }
  ///@}

  /// Samples of the last run, as the technique counts them (surface samples, importance samples,
  /// ...).
  vtkGetMacro(SampleCount, vtkIdType);

#ifndef __VTK_WRAP__
  /// The techniques the filter offers from: lucent's core techniques and prt
  /// (lucentFilterTechniques.h). Code may add its own (tests do).
  static lucent::technique::Registry& Techniques();
#endif

 protected:
  vtkLucentFilter();
  ~vtkLucentFilter() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
#ifndef __VTK_WRAP__
  struct Request;  // material, technique, knobs and light of one run
  struct KeptRun;  // the last run's scene and prepare, reused while they still hold
  /// Sets the medium beyond the material (a subclass's scan), given millimetres per data unit.
  using MediumSetup = std::function<void(lucent::technique::Medium&, double mmPerUnit)>;
  /// Shades `input` (surfaces) into `output`: the checks, the whole surface in millimetres, the
  /// technique, the arrays. 1 on success; 0 with the error reported.
  int ShadeSurface(vtkDataObject* input, vtkPolyData* output, const MediumSetup& medium);
  /// The scene of this run: the kept one when the surface and inner bodies are those it was built
  /// from (and no medium beyond the material is set), else a new one; lights, material and progress
  /// set for this run.
  lucent::technique::SceneDescription& SceneFor(vtkDataObject* input,
                                                lucent::vtkadapter::PolyDataMesh& whole,
                                                const Request& request, const MediumSetup& medium);
  /// Reads EnvironmentFileName, checked, unless the file's name, modification time and size are
  /// those last read (after rewriting it in place, call Modified()).
  void ReadEnvironment();
  /// The light of this run into `scene`: the environment map ReadEnvironment read, or the
  /// directional light.
  void SetLights(lucent::technique::SceneDescription& scene, const Request& request) const;
  /// Checks the material, technique, knobs and light against the technique's own description
  /// (with "auto": reads the planner's calibration).
  Request CheckRequest() const;
  /// The filter's knobs of `technique`, checked against its description.
  lucent::technique::KnobValues KnobsOf(const lucent::technique::Technique& technique) const;
  /// The default technique cannot take `scene` shaded at `whole` (`unmet` says why): the planner's
  /// choice into `request`, or, when it has none, the first offered technique that takes the
  /// scene; the plan's lines, the first saying why.
  std::vector<std::string> HandOverDefault(Request& request,
                                           const lucent::technique::SceneDescription& scene,
                                           const lucent::technique::ShadeRequest& whole,
                                           const std::string& unmet) const;
  /// The planner's budget (BudgetMs, MaxError) and calibration into `request`.
  void ReadPlanInputs(Request& request) const;
  void WriteArrays(vtkPolyData* output, const lucent::technique::Rendered& result) const;
  /// With Technique "auto": the plan's technique and knobs for the scene, into `request`; its
  /// explanation, one line per decision.
  std::vector<std::string> PlanTechnique(Request& request,
                                         const lucent::technique::SceneDescription& scene,
                                         const lucent::technique::ShadeRequest& shade) const;
#endif

  std::string Material = "skin1";
  std::string Technique;  ///< default: the registry's default reference (the ground truth)
  std::map<std::string, std::string> Knobs;  ///< qualified name -> value, as set
  double SizeMm = 0.0;
  double LightDirection[3] = {0.0, 0.0, 1.0};
  double LightIrradiance = 1.0;
  double Exposure = 1.0;
  double BudgetMs = 0.0;
  double MaxError = 0.0;
  std::string CalibrationDirectory;
  std::string EnvironmentFileName;
  double EnvironmentScale = 1.0;
  std::string ChosenTechnique;
  bool PrepareReused = false;
  double PrepareSeconds = 0, FrameSeconds = 0;
  std::unique_ptr<KeptRun> LastRun;
  vtkIdType SampleCount = 0;
  vtkMultiProcessController* Controller = nullptr;

 private:
  vtkLucentFilter(const vtkLucentFilter&) = delete;
  void operator=(const vtkLucentFilter&) = delete;
};

#endif
