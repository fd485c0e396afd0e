#include "vtkLucentRenderView.h"

#include <vtkObjectFactory.h>
#include <vtkPVSynchronizedRenderer.h>
#include <vtkRenderWindow.h>

#include "vtkLucentPass.h"

vtkStandardNewMacro(vtkLucentRenderView);

vtkLucentRenderView::vtkLucentRenderView() : Pass(vtkLucentPass::New()) {
  this->SynchronizedRenderers->SetImageProcessingPass(this->Pass);
}

vtkLucentRenderView::~vtkLucentRenderView() {
  // The pass may be out of the renderer (LucentEnabled off), where the window would not reach it.
  this->Pass->ReleaseGraphicsResources(this->GetRenderWindow());
  this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
  this->Pass->Delete();
}

void vtkLucentRenderView::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Pass:\n";
  this->Pass->PrintSelf(os, indent.GetNextIndent());
}

void vtkLucentRenderView::SetLucentEnabled(bool enabled) {
  if (!enabled) this->Pass->ReleaseGraphicsResources(this->GetRenderWindow());
  this->SynchronizedRenderers->SetImageProcessingPass(enabled ? this->Pass : nullptr);
  this->Modified();
}

void vtkLucentRenderView::SetLucentMaterial(const char* name) {
  this->Pass->SetMaterial(name);
  this->Modified();
}
void vtkLucentRenderView::SetLucentSizeMm(double mm) {
  this->Pass->SetSizeMm(mm);
  this->Modified();
}
void vtkLucentRenderView::SetLucentTechnique(const char* name) {
  this->Pass->SetTechnique(name);
  this->Modified();
}
void vtkLucentRenderView::SetLucentKnob(const char* qualifiedName, const char* value) {
  this->Pass->SetKnob(qualifiedName, value);
  this->Modified();
}
void vtkLucentRenderView::SetLucentKnobInteger(const char* qualifiedName, int value) {
  this->Pass->SetKnobInteger(qualifiedName, value);
  this->Modified();
}
void vtkLucentRenderView::SetLucentKnobReal(const char* qualifiedName, double value) {
  this->Pass->SetKnobReal(qualifiedName, value);
  this->Modified();
}
void vtkLucentRenderView::SetLucentLightDirection(double x, double y, double z) {
  this->Pass->SetLightDirection(x, y, z);
  this->Modified();
}
void vtkLucentRenderView::SetLucentLightIrradiance(double e) {
  this->Pass->SetLightIrradiance(e);
  this->Modified();
}
void vtkLucentRenderView::SetLucentExposure(double exposure) {
  this->Pass->SetExposure(exposure);
  this->Modified();
}
void vtkLucentRenderView::SetLucentSurfaceWeight(double weight) {
  this->Pass->SetSurfaceWeight(weight);
  this->Modified();
}
void vtkLucentRenderView::SetLucentMaxError(double error) {
  this->Pass->SetMaxError(error);
  this->Modified();
}
void vtkLucentRenderView::SetLucentCalibrationDirectory(const char* dir) {
  this->Pass->SetCalibrationDirectory(dir);
  this->Modified();
}
