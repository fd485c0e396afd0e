/// @file vtkLucentRenderView.h
/// @brief ParaView's render view with vtkLucentPass as its image-processing pass: every opaque
/// surface shown in it is rendered as a translucent material (ParaView's view hosts one
/// vtkImageProcessingPass, through its synchronized renderer). The Lucent* properties forward to
/// the pass.
#ifndef vtkLucentRenderView_h
#define vtkLucentRenderView_h

#include <vtkPVRenderView.h>
#include "LucentParaViewViewModule.h"

class vtkLucentPass;

class LUCENTPARAVIEWVIEW_EXPORT vtkLucentRenderView : public vtkPVRenderView {
 public:
  static vtkLucentRenderView* New();
  vtkTypeMacro(vtkLucentRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Off: the plain render view (the pass is taken out).
  void SetLucentEnabled(bool enabled);
  void SetLucentMaterial(const char* name);
  void SetLucentSizeMm(double mm);
  /// The technique whose GPU twin shades the view, and its knobs by qualified name (the generated
  /// properties pass it: "tsis.samples").
  void SetLucentTechnique(const char* name);
  void SetLucentKnob(const char* qualifiedName, const char* value);
  void SetLucentKnobInteger(const char* qualifiedName, int value);
  void SetLucentKnobReal(const char* qualifiedName, double value);
  void SetLucentLightDirection(double x, double y, double z);
  void SetLucentLightIrradiance(double e);
  void SetLucentExposure(double exposure);
  void SetLucentSurfaceWeight(double weight);
  /// Technique auto's target error and calibration folder (vtkLucentPass::SetMaxError).
  void SetLucentMaxError(double error);
  void SetLucentCalibrationDirectory(const char* dir);

 protected:
  vtkLucentRenderView();
  ~vtkLucentRenderView() override;

 private:
  vtkLucentRenderView(const vtkLucentRenderView&) = delete;
  void operator=(const vtkLucentRenderView&) = delete;
  vtkLucentPass* Pass;
};

#endif
