#include "vtkLucentProfile.h"

#include <algorithm>
#include <vector>

#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include <lucent/optics/dipole_lut.hpp>
#include <lucent/optics/profile.hpp>
#include <lucent/technique/technique.hpp>

#include "lucentPassDrawing.h"

vtkStandardNewMacro(vtkLucentProfile);

namespace {
namespace lo = lucent::optics;
namespace lt = lucent::technique;
}  // namespace

bool vtkLucentProfile::Update(vtkOpenGLRenderWindow* window, const lo::Material& material,
                              const lt::KnobValues& knobs, double diagonalMm, std::string& warning,
                              std::string& error) {
  const std::string profile = knobs.text("profile");
  const lt::detail::RdLookup lookup = lt::detail::rdLookupOf(knobs);
  warning = lookup.warning;
  const bool closedForm = lookup.closedForm;
  const std::string key = material.name + " " + profile + (closedForm ? " exact" : " table ") +
                          (closedForm ? std::string() : std::to_string(diagonalMm));
  if (key == this->BuiltKey) return true;
  // Until the new state is complete (the table can throw or fail), nothing counts as built.
  this->BuiltKey.clear();
  const lo::Profile<double> p = lt::detail::profileOf<double>(material, knobs);
  this->ExitScale = float(p.exitScale);
  this->ClosedForm = closedForm;
  if (closedForm) {
    const lo::Dipole<double> poles = p.poles();
    for (int c = 0; c < 3; ++c) {
      const auto& ch = poles.channel[c];
      const double v[6] = {ch.sigmaTr,    ch.zr,         ch.zv,
                           ch.alphaPrime, ch.fluxWeight, ch.fluenceWeight};
      for (int k = 0; k < 6; ++k) this->Dipole[k][c] = float(v[k]);
    }
    this->Rows = {};
  } else {
    // The CPU tsis's own table: float, from the float profile, with RadialTable's stated bound.
    const auto table =
        lo::radialTable(lt::detail::profileOf<float>(material, knobs), float(diagonalMm));
    if (!this->UploadTable(window, table, profile, error)) return false;
  }
  this->BuiltKey = key;
  return true;
}

bool vtkLucentProfile::UpdateTable(vtkOpenGLRenderWindow* window, const std::string& key,
                                   const lo::RadialTable<float>& table, double exitScale,
                                   std::string& error) {
  if (key == this->BuiltKey) return true;
  this->BuiltKey.clear();
  this->ExitScale = float(exitScale);
  this->ClosedForm = false;
  if (!this->UploadTable(window, table, key, error)) return false;
  this->BuiltKey = key;
  return true;
}

bool vtkLucentProfile::UploadTable(vtkOpenGLRenderWindow* window,
                                   const lo::RadialTable<float>& table, const std::string& name,
                                   std::string& error) {
  if (!this->Table) this->Table = lucent::vtkpass::newNearestTexture(window);
  if (!this->Rows.upload(window, this->Table, table.values(), double(table.rMax()))) {
    error = "vtkLucentPass: the " + name + " profile's table (" + std::to_string(table.size()) +
            " nodes) could not be uploaded as a texture";
    return false;
  }
  return true;
}

void vtkLucentProfile::Activate(vtkShaderProgram* program) {
  const char* names[6] = {"dipole.sigmaTr",    "dipole.zr",         "dipole.zv",
                          "dipole.alphaPrime", "dipole.fluxWeight", "dipole.fluenceWeight"};
  for (int k = 0; k < 6; ++k) program->SetUniform3f(names[k], this->Dipole[k]);
  program->SetUniformf("exitScale", this->ExitScale);
  this->Rows.setUniforms(program, "profile");
  if (this->Table) {
    this->Table->Activate();
    program->SetUniformi("profileTable", this->Table->GetTextureUnit());
  }
}

void vtkLucentProfile::Deactivate() {
  if (this->Table) this->Table->Deactivate();
}

void vtkLucentProfile::ReleaseGraphicsResources(vtkWindow* window) {
  if (this->Table) this->Table->ReleaseGraphicsResources(window);
  this->Table = nullptr;
  this->BuiltKey.clear();
}
