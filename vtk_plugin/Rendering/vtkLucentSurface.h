/// @file vtkLucentSurface.h
/// @brief One translucent actor as the GPU path needs it (private to Lucent::Rendering): its
/// triangles in world coordinates with vertex normals, the texture atlas of
/// Chang et al. 2008 Sec. 2.2 (built on the CPU by lucent/atlas/texture_atlas.hpp)
/// and one vertex buffer with, per corner, position, normal, atlas coordinate and the texel area
/// weight A_S / n_T of Eq. 7. Rebuilt only when the data, the actor's matrix, the size or the atlas
/// resolution change.
#ifndef vtkLucentSurface_h
#define vtkLucentSurface_h

#include <string>

#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkOpenGLBufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
#include <lucent/scene/mesh.hpp>

class vtkWindow;

class vtkLucentSurface : public vtkObject {
 public:
  static vtkLucentSurface* New();
  vtkTypeMacro(vtkLucentSurface, vtkObject);

  /// Brings the CPU and GPU data up to date with the actor; false with @p error when the actor has
  /// nothing to draw (no polygons) or the atlas cannot be built.
  /// The vertex buffer binds in the current context (the pass's render window).
  bool Update(vtkActor* actor, double sizeMm, int atlasResolution, std::string& error);

  /// Draws the triangles with @p program; @p stage picks the vertex array (one per program).
  enum Stage {
    LightDepth = 0,
    Atlas = 1,
    Shade = 2,
    TauLightView = 3,
    TauShade = 4,
    LocalLightView = 5,
    HybridShade = 6
  };
  static constexpr int kStages = 7;
  void Draw(vtkShaderProgram* program, Stage stage);

  void ReleaseGraphicsResources(vtkWindow* window);

  double GetMillimetresPerUnit() const { return this->MillimetresPerUnit; }
  const double* GetCentre() const { return this->Centre; }
  double GetRadius() const { return this->Radius; }
  /// The surface in millimetres, centred (what the atlas is laid out on; tsis's range reads it).
  const lucent::scene::TriangleMesh& GetMillimetreMesh() const { return this->MillimetreMesh; }
  /// Grows by one each time Update rebuilds the surface (what depends on the mesh can cache by it).
  unsigned long GetBuildCount() const { return this->BuildCount; }

 protected:
  vtkLucentSurface();
  ~vtkLucentSurface() override;

 private:
  vtkLucentSurface(const vtkLucentSurface&) = delete;
  void operator=(const vtkLucentSurface&) = delete;

  vtkMTimeType BuiltDataTime = 0;
  double BuiltMatrix[16] = {};
  const void* BuiltData = nullptr;
  double BuiltSizeMm = -1;
  int BuiltResolution = 0;

  vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> Arrays[kStages];
  vtkShaderProgram* BoundProgram[kStages] = {};
  int CornerCount = 0;
  double MillimetresPerUnit = 1, Centre[3] = {0, 0, 0}, Radius = 1;
  lucent::scene::TriangleMesh MillimetreMesh;
  unsigned long BuildCount = 0;
};

#endif
