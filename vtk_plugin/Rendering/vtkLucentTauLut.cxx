#include "vtkLucentTauLut.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "lucentLightViewMap.h"
#include "lucentPassDrawing.h"
#include "vtkLucentSurface.h"

vtkStandardNewMacro(vtkLucentTauLut);

namespace {
namespace lt = lucent::technique;
namespace lv = lucent::voxel;
using namespace lucent::vtkpass;

/// sigma_t's table: medium indices 0 (none) .. 255.
constexpr int kMediumSlots = 256;

}  // namespace

struct vtkLucentTauLut::Textures {
  vtkSmartPointer<vtkTextureObject> voxelMedium, voxelNumber, surfaceVoxel, mediumSigmaT,
      pathLengths, clusterCell, clusterPoint;
  LightViewTargets map;  ///< the irradiance and voxel-number maps
  float lengthUnit = 1;
  int storage = 0, media = 1;
  std::vector<vtkTextureObject*> voxelData() const {
    return {voxelMedium, voxelNumber, surfaceVoxel, mediumSigmaT,
            pathLengths, clusterCell, clusterPoint};
  }
};

vtkLucentTauLut::vtkLucentTauLut()
    : Tex(new Textures),
      LightViewVs(lucent::glsl::kLightViewMapVert),
      LightViewFs(lightViewMapShader(true)) {}
vtkLucentTauLut::~vtkLucentTauLut() = default;

std::size_t vtkLucentTauLut::GetSurfaceVoxels() const {
  return this->Lut ? this->Lut->surface().count() : 0;
}

bool vtkLucentTauLut::Prepare(vtkOpenGLRenderWindow* window, const lt::Technique& taulut,
                              const lt::SceneDescription& scene, const lt::KnobValues& knobs,
                              const std::string& key, std::string& error) {
  if (this->Lut && key == this->BuiltKey) return true;
  this->Prepared.reset();
  this->Lut = nullptr;
  this->BuiltKey.clear();
  try {
    lt::Statistics stats;
    this->Prepared = taulut.prepare(scene, knobs, stats);
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  this->Lut = dynamic_cast<const lt::detail::TauLut*>(this->Prepared.get());
  if (!this->Lut) {
    error = "technique '" + taulut.name + "' did not prepare a voxel optical-thickness LUT";
    return false;
  }
  if (!this->Upload(window, error)) {
    this->Prepared.reset();
    this->Lut = nullptr;
    return false;
  }
  this->BuiltKey = key;
  return true;
}

bool vtkLucentTauLut::Upload(vtkOpenGLRenderWindow* window, std::string& error) {
  Textures& T = *this->Tex;
  for (auto* t : {&T.voxelMedium, &T.voxelNumber, &T.surfaceVoxel, &T.mediumSigmaT, &T.pathLengths,
                  &T.clusterCell, &T.clusterPoint})
    if (!*t) *t = newNearestTexture(window);
  const lv::SurfacePaths& paths = this->Lut->paths();
  const lv::MediaGrid& grid = paths.grid();
  const lv::SurfaceVoxels& surface = this->Lut->surface();
  const int max3d = vtkTextureObject::GetMaximumTextureSize3D(window);
  if (grid.dims.x > max3d || grid.dims.y > max3d || grid.dims.z > max3d) {
    error = "taulut: the voxel grid (" + std::to_string(grid.dims.x) + " x " +
            std::to_string(grid.dims.y) + " x " + std::to_string(grid.dims.z) +
            ") exceeds this GPU's largest 3-D texture (" + std::to_string(max3d) +
            " a side); lower voxels";
    return false;
  }
  // The grid: medium and density; each voxel's surface number and the flood fill's nearest.
  const std::vector<std::int32_t>& nearest = this->Lut->lookup().nearestMap();
  std::vector<float> medium(2 * grid.voxelCount()), number(2 * grid.voxelCount());
  for (std::size_t i = 0; i < grid.voxelCount(); ++i) {
    medium[2 * i] = float(grid.medium[i]), medium[2 * i + 1] = float(grid.densityAt(i));
    number[2 * i] = float(surface.number[i]), number[2 * i + 1] = float(nearest[i]);
  }
  const glm::uvec3 dims(grid.dims);
  if (!T.voxelMedium->Create3DFromRaw(dims.x, dims.y, dims.z, 2, VTK_FLOAT, medium.data()) ||
      !T.voxelNumber->Create3DFromRaw(dims.x, dims.y, dims.z, 2, VTK_FLOAT, number.data())) {
    error = "taulut: the voxel grid could not be uploaded";
    return false;
  }
  this->RowTexels = std::min(kMaxRowTexels, vtkTextureObject::GetMaximumTextureSize(window));
  const bool hierarchical = paths.storage() == lv::Storage::Hierarchical;
  std::vector<float> centres;
  for (std::size_t n = 0; n < surface.count(); ++n) {
    const glm::dvec3 c = paths.centre(std::int32_t(n));
    const float cluster = hierarchical ? float(paths.clusterOf()[n]) : 0.0f;
    centres.insert(centres.end(), {float(c.x), float(c.y), float(c.z), cluster});
  }
  std::vector<float> cells, points;
  if (hierarchical)
    for (std::size_t c = 0; c < paths.clusterCells().size(); ++c) {
      const glm::dvec3 cell(paths.clusterCells()[c]), p = paths.table()->point(c);
      cells.insert(cells.end(), {float(cell.x), float(cell.y), float(cell.z), 0.0f});
      points.insert(points.end(), {float(p.x), float(p.y), float(p.z), 0.0f});
    }
  if (!uploadRows(T.surfaceVoxel, centres, this->RowTexels) ||
      !uploadRows(T.clusterCell, cells, this->RowTexels) ||
      !uploadRows(T.clusterPoint, points, this->RowTexels)) {
    error = "taulut: the surface voxels could not be uploaded";
    return false;
  }
  T.storage = int(paths.storage());
  T.media = paths.media();
  this->TextureBytes =
      double(grid.voxelCount()) * 16 + double(centres.size() + cells.size() + points.size()) * 4;
  return this->UploadTable(window, error);
}

bool vtkLucentTauLut::UploadTable(vtkOpenGLRenderWindow* window, std::string& error) {
  Textures& T = *this->Tex;
  const lv::PathLengthTable* table = this->Lut->paths().table();
  if (!table) {  // march: nothing stored
    const float zero = 0;
    T.lengthUnit = 1;
    return T.pathLengths->Create2DFromRaw(1, 1, 1, VTK_FLOAT, const_cast<float*>(&zero));
  }
  const bool half = table->precision() == lv::Precision::Half;
  const std::size_t values = half ? table->halfValues().size() : table->singleValues().size();
  const std::size_t width = std::min<std::size_t>(std::max<std::size_t>(values, 1), RowTexels);
  const std::size_t rows = (values + width - 1) / width;
  const int maxTexture = vtkTextureObject::GetMaximumTextureSize(window);
  if (rows > std::size_t(maxTexture) || values > std::size_t(0xffffffffu)) {
    error = "taulut: the optical-thickness table's " + std::to_string(values) +
            " values exceed this GPU's largest texture (" + std::to_string(width) + " x " +
            std::to_string(maxTexture) +
            "); use storage=hierarchical or storage=march, or lower voxels";
    return false;
  }
  bool ok;
  if (half) {
    std::vector<std::uint16_t> padded(table->halfValues());
    padded.resize(width * rows, 0);
    T.pathLengths->SetInternalFormat(GL_R16F);
    T.pathLengths->SetFormat(GL_RED);
    T.pathLengths->SetDataType(GL_HALF_FLOAT);
    ok = T.pathLengths->Create2DFromRaw(unsigned(width), unsigned(rows), 1, VTK_UNSIGNED_SHORT,
                                        padded.data());
    T.lengthUnit = float(table->halfUnit());
  } else {
    std::vector<float> padded(table->singleValues());
    padded.resize(width * rows, 0.0f);
    ok = T.pathLengths->Create2DFromRaw(unsigned(width), unsigned(rows), 1, VTK_FLOAT,
                                        padded.data());
    T.lengthUnit = 1;
  }
  if (!ok) error = "taulut: the optical-thickness table could not be uploaded";
  this->TextureBytes += double(width * rows) * (half ? 2 : 4);
  return ok;
}

void vtkLucentTauLut::UploadFrameInputs(vtkOpenGLRenderWindow* window,
                                        const lt::SceneDescription& scene) {
  const std::vector<glm::dvec3> sigmaT = this->Lut->extinction(scene);  // throws: media changed
  std::vector<float> table(4 * kMediumSlots, 0.0f);
  for (std::size_t m = 0; m < sigmaT.size(); ++m)
    for (int c = 0; c < 3; ++c) table[4 * (m + 1) + std::size_t(c)] = float(sigmaT[m][c]);
  if (!this->Tex->mediumSigmaT) this->Tex->mediumSigmaT = newNearestTexture(window);
  this->Tex->mediumSigmaT->Create2DFromRaw(kMediumSlots, 1, 4, VTK_FLOAT, table.data());
  this->Filter = lv::tapFilter(this->Lut->filterExtinction(sigmaT), this->Lut->taps(),
                               scene.mesh.bounds().diagonal());
  this->MapFrame = lucent::atlas::lightViewFrame(scene.lights.front(), scene.mesh.bounds());
  this->MapResolution = this->Lut->mapResolution();
  this->Eta = float(scene.medium.material.eta);
}

void vtkLucentTauLut::BindVoxelData(vtkShaderProgram* program) {
  const Textures& T = *this->Tex;
  const char* names[] = {"voxelMedium", "voxelNumber", "surfaceVoxel", "mediumSigmaT",
                         "pathLengths", "clusterCell", "clusterPoint"};
  const auto textures = T.voxelData();
  for (std::size_t k = 0; k < textures.size(); ++k) {
    textures[k]->Activate();
    program->SetUniformi(names[k], textures[k]->GetTextureUnit());
  }
  const lv::MediaGrid& grid = this->Lut->paths().grid();
  setUniform3(program, "gridSize", glm::dvec3(grid.dims));
  setUniform3(program, "gridOrigin", grid.origin);
  setUniform3(program, "gridSpacing", grid.spacing);
  program->SetUniformi("rowTexels", this->RowTexels);
  program->SetUniformi("storage", T.storage);
  program->SetUniformi("media", T.media);
  program->SetUniformf("lengthUnit", T.lengthUnit);
}

void vtkLucentTauLut::UnbindVoxelData() {
  for (vtkTextureObject* t : this->Tex->voxelData()) t->Deactivate();
}

bool vtkLucentTauLut::RenderLightView(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                                      const lt::SceneDescription& scene, std::string& error) {
  try {
    this->UploadFrameInputs(window, scene);
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  Textures& T = *this->Tex;
  T.map.begin(window, this->MapResolution);
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
      this->LightViewVs.c_str(), this->LightViewFs.c_str(), "");
  if (program) {
    setLightViewUniforms(program, *surface, this->MapFrame, scene.lights.front(), this->Eta);
    this->BindVoxelData(program);
    surface->Draw(program, vtkLucentSurface::TauLightView);
    this->UnbindVoxelData();
  }
  T.map.end();
  if (!program) error = "vtkLucentPass: the taulut light-view shader did not compile";
  return program != nullptr;
}

bool vtkLucentTauLut::Shade(vtkOpenGLRenderWindow*, vtkLucentSurface* surface,
                            const float camera[3], vtkShaderProgram* program) {
  Textures& T = *this->Tex;
  const lucent::atlas::RingFilter& f = this->Filter;
  constexpr int kMaxStrata = 17;  // shaders/taulut_shade.frag
  const int strata = std::min(kMaxStrata, f.rings + 1);
  std::vector<float> radius(kMaxStrata, 0.0f);
  std::vector<float> mass(3 * kMaxStrata, 0.0f), profile(3 * kMaxStrata, 0.0f);
  for (int k = 0; k < strata; ++k) {
    radius[std::size_t(k)] = float(f.radius[std::size_t(k)]);
    for (int c = 0; c < 3; ++c) {
      mass[3 * std::size_t(k) + std::size_t(c)] = float(f.mass[std::size_t(k)][c]);
      profile[3 * std::size_t(k) + std::size_t(c)] = float(f.profileAt[std::size_t(k)][c]);
    }
  }
  bindMapForFiltering(program, T.map, this->MapFrame, this->MapResolution);
  program->SetUniformi("rings", strata - 1);
  program->SetUniformi("perRing", f.perRing);
  program->SetUniform1fv("ringRadius", kMaxStrata, radius.data());
  program->SetUniform3fv("ringMass", kMaxStrata, reinterpret_cast<const float(*)[3]>(mass.data()));
  program->SetUniform3fv("ringProfile", kMaxStrata,
                         reinterpret_cast<const float(*)[3]>(profile.data()));
  program->SetUniformi("rotated", this->Lut->rotatedPattern() ? 1 : 0);
  setUniform3(
      program, "worldCentre",
      glm::dvec3(surface->GetCentre()[0], surface->GetCentre()[1], surface->GetCentre()[2]));
  program->SetUniformf("mmPerUnit", float(surface->GetMillimetresPerUnit()));
  program->SetUniform3f("cameraPosition", camera);
  program->SetUniformf("eta", this->Eta);
  this->BindVoxelData(program);
  surface->Draw(program, vtkLucentSurface::TauShade);
  this->UnbindVoxelData();
  unbindMap(T.map);
  return true;
}

void vtkLucentTauLut::ReleaseGraphicsResources(vtkWindow* window) {
  Textures& T = *this->Tex;
  for (auto* t :
       {T.voxelMedium.Get(), T.voxelNumber.Get(), T.surfaceVoxel.Get(), T.mediumSigmaT.Get(),
        T.pathLengths.Get(), T.clusterCell.Get(), T.clusterPoint.Get()})
    if (t) t->ReleaseGraphicsResources(window);
  T.map.release(window);
  this->Tex.reset(new Textures);
  this->BuiltKey.clear();  // the next Prepare uploads again into the new context
  this->Lut = nullptr;
  this->Prepared.reset();
}
