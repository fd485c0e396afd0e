#include "vtkLucentLocalTerm.h"

#include <vector>

#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "vtkLucentSurface.h"

vtkStandardNewMacro(vtkLucentLocalTerm);

namespace {
namespace lt = lucent::technique;
using namespace lucent::vtkpass;
}  // namespace

vtkLucentLocalTerm::vtkLucentLocalTerm()
    : LightViewVs(lucent::glsl::kLightViewMapVert), LightViewFs(lightViewMapShader(false)) {}
vtkLucentLocalTerm::~vtkLucentLocalTerm() = default;

bool vtkLucentLocalTerm::Update(vtkOpenGLRenderWindow* window,
                                const lucent::optics::Material& material,
                                const lt::KnobValues& knobs, double diagonalMm,
                                std::string& error) {
  this->MapResolution = int(knobs.integer("map"));
  lucent::util::Fingerprint f;  // what the split reads: the material, the knobs, the diagonal
  lt::detail::addMaterial(f, material);
  lt::detail::addKnobs(f, knobs);
  f.addValue(diagonalMm);
  const std::string key = f.hex();
  if (this->Split && key == this->BuiltKey) return true;
  this->BuiltKey.clear();
  try {
    lt::Statistics stats;
    this->Split = std::make_unique<lt::detail::HybridSplit>(material, knobs, diagonalMm, stats);
  } catch (const std::exception& e) {  // an object too small or too large for the tables
    this->Split.reset();
    error = std::string("the hybrid's split: ") + e.what();
    return false;
  }
  if (!this->UploadFilter(window, error)) return false;
  this->BuiltKey = key;
  return true;
}

bool vtkLucentLocalTerm::UploadFilter(vtkOpenGLRenderWindow* window, std::string& error) {
  for (auto* t : {&this->TapOffset, &this->TapFactor, &this->LocalTable, &this->CentreCumulative})
    if (!*t) *t = newNearestTexture(window);
  const lucent::atlas::RingFilter& ring = this->Split->ring;
  std::vector<float> offsets, factors;
  for (std::size_t j = 0; j < ring.tapOffset.size(); ++j) {
    const glm::dvec2 o = ring.tapOffset[j];
    const glm::dvec3 f = ring.tapFactor[j];
    offsets.insert(offsets.end(), {float(o.x), float(o.y), 0.0f, 0.0f});
    factors.insert(factors.end(), {float(f.x), float(f.y), float(f.z), 0.0f});
  }
  this->Taps = int(ring.tapOffset.size());
  this->TapsPerRow = std::max(1, std::min(this->Taps, rowLimit(window)));
  const bool ok =
      uploadRows(this->TapOffset, std::move(offsets), rowLimit(window)) &&
      uploadRows(this->TapFactor, std::move(factors), rowLimit(window)) &&
      this->LocalRows.upload(window, this->LocalTable, this->Split->tables.local.values(),
                             double(this->Split->tables.local.rMax())) &&
      this->CentreRows.upload(window, this->CentreCumulative, ring.cumulative, ring.domain);
  if (!ok) error = "the hybrid's ring filter could not be uploaded as textures";
  return ok;
}

bool vtkLucentLocalTerm::RenderMap(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                   const lucent::scene::Light& lightMm, float eta,
                                   std::string& error) {
  this->MapFrame = lucent::atlas::lightViewFrame(lightMm, surface->GetMillimetreMesh().bounds());
  this->Map.begin(window, this->MapResolution);
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
      this->LightViewVs.c_str(), this->LightViewFs.c_str(), "");
  if (program) {
    setLightViewUniforms(program, *surface, this->MapFrame, lightMm, eta);
    surface->Draw(program, vtkLucentSurface::LocalLightView);
  }
  this->Map.end();
  if (!program) error = "the hybrid's light-view shader did not compile";
  return program != nullptr;
}

std::vector<vtkTextureObject*> vtkLucentLocalTerm::FilterTextures() const {
  return {this->TapOffset, this->TapFactor, this->LocalTable, this->CentreCumulative};
}

void vtkLucentLocalTerm::Activate(vtkShaderProgram* program) {
  bindMapForFiltering(program, this->Map, this->MapFrame, this->MapResolution);
  const char* names[] = {"tapOffset", "tapFactor", "localTable", "centreCumulative"};
  const auto textures = this->FilterTextures();
  for (std::size_t k = 0; k < textures.size(); ++k) {
    textures[k]->Activate();
    program->SetUniformi(names[k], textures[k]->GetTextureUnit());
  }
  program->SetUniformi("taps", this->Taps);
  program->SetUniformi("tapsPerRow", this->TapsPerRow);
  this->LocalRows.setUniforms(program, "localProfile");
  this->CentreRows.setUniforms(program, "centreGrid");
  const lucent::atlas::RingFilter& ring = this->Split->ring;
  setUniform3(program, "centreMass", ring.mass.empty() ? glm::dvec3(0) : ring.mass[0]);
  program->SetUniformf("innerRadius", float(ring.innerRadius));
}

void vtkLucentLocalTerm::Deactivate() {
  for (vtkTextureObject* t : this->FilterTextures()) t->Deactivate();
  unbindMap(this->Map);
}

void vtkLucentLocalTerm::ReleaseGraphicsResources(vtkWindow* window) {
  this->Map.release(window);
  for (vtkTextureObject* t : this->FilterTextures())
    if (t) t->ReleaseGraphicsResources(window);
  this->TapOffset = this->TapFactor = this->LocalTable = this->CentreCumulative = nullptr;
  this->BuiltKey.clear();  // the next Update uploads again into the new context
}
