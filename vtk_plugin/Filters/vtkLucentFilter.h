/// @file vtkLucentFilter.h
/// @brief Translucent shading of a closed surface on the CPU: per-vertex radiosity B of subsurface
/// scattering (L = Ft B / pi) under one directional light with Fresnel-transmitted, shadowed irradiance,
/// by one of two techniques:
///  - Reference: lucent's brute-force dipole sum over dense surface samples (texture-space-importance-
///    sampling Eq. 3), the ground truth;
///  - TSIS: texture-space importance sampling (Sec. 3): irradiance into the chart atlas, N texels drawn by
///    the mip-map ICDF, B = sum_i w_i Rd(|x_i - x_o|) (Eq. 9-10) at every vertex.
///
/// Output: the input triangulated, with point arrays "Radiosity" (3 floats, irradiance units) and
/// "TranslucentColor" (3 unsigned chars, Exposure * B tone-mapped x / (1 + x), sRGB-encoded, the active
/// scalars so a plain mapper shows it). Lengths: the data's units are taken as millimetres, or the data is
/// scaled so its bounding-box diagonal is SizeMm. Reports progress (ProgressEvent) through both stages.
#ifndef vtkLucentFilter_h
#define vtkLucentFilter_h

#include <string>

#include "LucentFiltersModule.h"
#include <vtkPolyDataAlgorithm.h>

class LUCENTFILTERS_EXPORT vtkLucentFilter : public vtkPolyDataAlgorithm {
 public:
  static vtkLucentFilter* New();
  vtkTypeMacro(vtkLucentFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Measured material by name (`lucent materials` lists them): skin1, marble, ketchup, ... Default skin1.
  void SetMaterial(const char* name);
  const char* GetMaterial() const { return this->Material.c_str(); }
  ///@}

  ///@{
  /// Object size: 0 (default) = the data's units are mm; > 0 = scale so the bounding-box diagonal is this.
  vtkSetClampMacro(SizeMm, double, 0.0, 1.0e6);
  vtkGetMacro(SizeMm, double);
  ///@}

  ///@{
  /// Direction towards the light (need not be unit) and the irradiance it gives a surface facing it.
  vtkSetVector3Macro(LightDirection, double);
  vtkGetVector3Macro(LightDirection, double);
  vtkSetClampMacro(LightIrradiance, double, 0.0, 1.0e6);
  vtkGetMacro(LightIrradiance, double);
  ///@}

  ///@{
  /// Technique: Reference (0, default) or TSIS (1).
  enum Techniques { Reference = 0, TSIS = 1 };
  vtkSetClampMacro(Technique, int, Reference, TSIS);
  vtkGetMacro(Technique, int);
  ///@}

  ///@{
  /// TSIS knobs: N importance samples (Eq. 9-11) and the atlas's texels per side.
  vtkSetClampMacro(TsisSamples, int, 1, 10000000);
  vtkGetMacro(TsisSamples, int);
  vtkSetClampMacro(AtlasResolution, int, 16, 8192);
  vtkGetMacro(AtlasResolution, int);
  ///@}

  ///@{
  /// Accuracy knobs of the reference's dipole sum: sample spacing as a fraction of the smallest mean free path, and the
  /// sample budget (the spacing is coarsened to respect it, with a warning).
  vtkSetClampMacro(SampleFraction, double, 0.01, 100.0);
  vtkGetMacro(SampleFraction, double);
  vtkSetClampMacro(MaxSamples, int, 1000, 100000000);
  vtkGetMacro(MaxSamples, int);
  ///@}

  ///@{
  /// Exposure of the colour array (the radiosity array is not affected).
  vtkSetClampMacro(Exposure, double, 0.0, 1.0e6);
  vtkGetMacro(Exposure, double);
  ///@}

  /// Samples of the last run: the reference's surface samples, or TSIS's drawn samples (for sweeps and tests).
  vtkGetMacro(SampleCount, vtkIdType);

 protected:
  vtkLucentFilter();
  ~vtkLucentFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string Material = "skin1";
  int Technique = Reference;
  int TsisSamples = 4096;
  int AtlasResolution = 1024;
  double SizeMm = 0.0;
  double LightDirection[3] = {0.0, 0.0, 1.0};
  double LightIrradiance = 1.0;
  double SampleFraction = 0.5;
  int MaxSamples = 500000;
  double Exposure = 1.0;
  vtkIdType SampleCount = 0;

 private:
  vtkLucentFilter(const vtkLucentFilter&) = delete;
  void operator=(const vtkLucentFilter&) = delete;
};

#endif
