#include "vtkLucentSurface.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLVertexArrayObject.h>
#include <vtkPolyData.h>
#include <vtkShaderProgram.h>
#include <vtk_glew.h>

#include <lucent/atlas/texture_atlas.hpp>
#include <lucent/scene/mesh.hpp>

#include "lucentPolyDataMesh.h"

vtkStandardNewMacro(vtkLucentSurface);

namespace {
constexpr int kFloatsPerCorner = 9;  // position 3, normal 3, atlas uv 2, area per texel 1

}  // namespace

vtkLucentSurface::vtkLucentSurface() = default;
vtkLucentSurface::~vtkLucentSurface() = default;

bool vtkLucentSurface::Update(vtkActor* actor, double sizeMm, int atlasResolution,
                              std::string& error) {
  vtkMapper* mapper = actor->GetMapper();
  vtkDataObject* data = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  if (!data) {
    error = "the actor's mapper has no input data";
    return false;
  }
  vtkNew<vtkMatrix4x4> matrix;
  actor->GetMatrix(matrix);
  const double* elements = matrix->GetData();
  if (this->Buffer && data == this->BuiltData && data->GetMTime() == this->BuiltDataTime &&
      std::equal(elements, elements + 16, this->BuiltMatrix) && sizeMm == this->BuiltSizeMm &&
      atlasResolution == this->BuiltResolution)
    return true;

  // Triangulated, welded, outward, in world coordinates: the conversion the filter and the CLI use
  // too.
  const lucent::scene::TriangleMesh world = lucent::vtkadapter::meshFromData(data, matrix).mesh;
  if (world.triangles.empty()) {
    error =
        "the actor's data has no polygons (extract a surface first, e.g. Contour or Extract "
        "Surface)";
    return false;
  }

  const lucent::scene::Bounds bounds = world.bounds();
  const double diagonal = bounds.diagonal();
  if (!(diagonal > 0) || !std::isfinite(diagonal)) {
    error = "the actor's data has zero or non-finite extent";
    return false;
  }
  this->MillimetresPerUnit = sizeMm > 0 ? sizeMm / diagonal : 1.0;
  const glm::dvec3 centre = 0.5 * (bounds.lo + bounds.hi);
  for (int k = 0; k < 3; ++k) this->Centre[k] = centre[k];
  this->Radius = 0.5 * diagonal;

  // The atlas is laid out in millimetres (its scale is texels per mm).
  lucent::scene::TriangleMesh mm = world;
  for (auto& p : mm.positions) p = glm::vec3((glm::dvec3(p) - centre) * this->MillimetresPerUnit);
  lucent::atlas::AtlasOptions options;
  options.resolution = atlasResolution;
  lucent::atlas::TextureAtlas atlas;
  try {
    atlas = lucent::atlas::buildTextureAtlas(mm, options);
  } catch (const std::exception& e) {
    error = std::string("the texture atlas could not be built: ") + e.what();
    return false;
  }

  this->MillimetreMesh = mm;
  const std::vector<glm::vec3> normals = world.vertexNormals();
  std::vector<float> corners;
  corners.reserve(world.triangles.size() * 3 * kFloatsPerCorner);
  for (std::size_t t = 0; t < world.triangles.size(); ++t) {
    // A triangle owning no texel centre still covers one texel somewhere (Eq. 7 with n_T = 1).
    const double area =
        mm.triangleArea(t) / double(std::max<std::uint32_t>(atlas.texelCount[t], 1));
    for (int k = 0; k < 3; ++k) {
      const unsigned v = world.triangles[t][k];
      const glm::vec3& p = world.positions[v];
      const glm::vec3& n = normals[v];
      const glm::dvec2 uv = atlas.uv[3 * t + std::size_t(k)] / double(atlas.resolution);
      corners.insert(corners.end(),
                     {p.x, p.y, p.z, n.x, n.y, n.z, float(uv.x), float(uv.y), float(area)});
    }
  }
  if (!this->Buffer) this->Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  this->Buffer->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  if (!this->Buffer->Upload(corners, vtkOpenGLBufferObject::ArrayBuffer)) {
    error = "the vertex buffer could not be uploaded";
    return false;
  }
  this->CornerCount = int(world.triangles.size() * 3);
  for (auto& program : this->BoundProgram)
    program = nullptr;  // attributes point into the new buffer

  this->BuiltData = data;
  this->BuiltDataTime = data->GetMTime();
  std::copy(elements, elements + 16, this->BuiltMatrix);
  this->BuiltSizeMm = sizeMm;
  this->BuiltResolution = atlasResolution;
  ++this->BuildCount;
  return true;
}

void vtkLucentSurface::Draw(vtkShaderProgram* program, Stage stage) {
  auto& arrays = this->Arrays[stage];
  if (!arrays) arrays = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  arrays->Bind();
  if (this->BoundProgram[stage] != program) {
    arrays->ReleaseGraphicsResources();
    arrays->Bind();
    const int stride = kFloatsPerCorner * int(sizeof(float));
    arrays->AddAttributeArray(program, this->Buffer, "positionWC", 0, stride, VTK_FLOAT, 3, false);
    if (stage != LightDepth)
      arrays->AddAttributeArray(program, this->Buffer, "normalWC", 3 * sizeof(float), stride,
                                VTK_FLOAT, 3, false);
    if (stage == Atlas) {
      arrays->AddAttributeArray(program, this->Buffer, "atlasUV", 6 * sizeof(float), stride,
                                VTK_FLOAT, 2, false);
      arrays->AddAttributeArray(program, this->Buffer, "areaPerTexel", 8 * sizeof(float), stride,
                                VTK_FLOAT, 1, false);
    }
    this->BoundProgram[stage] = program;
  }
  glDrawArrays(GL_TRIANGLES, 0, this->CornerCount);
  arrays->Release();
}

void vtkLucentSurface::ReleaseGraphicsResources(vtkWindow*) {
  for (int s = 0; s < kStages; ++s) {
    if (this->Arrays[s]) this->Arrays[s]->ReleaseGraphicsResources();
    this->BoundProgram[s] = nullptr;
  }
  if (this->Buffer) this->Buffer->ReleaseGraphicsResources();
  this->Buffer = nullptr;  // forces a re-upload in the next context
}
