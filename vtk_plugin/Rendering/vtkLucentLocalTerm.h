/// @file vtkLucentLocalTerm.h
/// @brief The hybrid's local term on the GPU for one translucent actor (private to
/// Lucent::Rendering): the translucent shadow map seen from the light (shaders/light_view_map.*),
/// and what shaders/ring_filter.glsl reads of the CPU hybrid's own split
/// (lucent::technique::detail::HybridSplit): the ring filter's taps and ratio factors, the table of
/// Rd Wl and the centre disc's cumulative. The split is rebuilt when the material, a knob or the
/// object's diagonal changes; the map every frame (the light may have moved).
#ifndef vtkLucentLocalTerm_h
#define vtkLucentLocalTerm_h

#include <memory>
#include <string>

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <glm/vec3.hpp>

#include <lucent/technique/scene_fingerprint.hpp>
#include <lucent/technique/texture_space.hpp>

#include "lucentLightViewMap.h"
#include "lucentPassDrawing.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;
class vtkLucentSurface;

class vtkLucentLocalTerm : public vtkObject {
 public:
  static vtkLucentLocalTerm* New();
  vtkTypeMacro(vtkLucentLocalTerm, vtkObject);

  /// Brings the split up to date with the hybrid's knobs; false with @p error when the technique
  /// refuses them or a table cannot be uploaded.
  bool Update(vtkOpenGLRenderWindow* window, const lucent::optics::Material& material,
              const lucent::technique::KnobValues& knobs, double diagonalMm, std::string& error);
  /// The split of the last Update (its global table is what the samples sum); null before one.
  const lucent::technique::detail::HybridSplit* GetSplit() const { return this->Split.get(); }
  /// What the split was built for (the global table's key).
  const std::string& GetKey() const { return this->BuiltKey; }

  /// The translucent shadow map under the light (a point or directional light in the surface's
  /// millimetre frame); false with @p error when the shader does not compile.
  bool RenderMap(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                 const lucent::scene::Light& lightMm, float eta, std::string& error);

  /// Binds the map and the filter's tables and sets ring_filter.glsl's uniforms; Deactivate after
  /// drawing.
  void Activate(vtkShaderProgram* program);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* window);

 protected:
  vtkLucentLocalTerm();
  ~vtkLucentLocalTerm() override;

 private:
  vtkLucentLocalTerm(const vtkLucentLocalTerm&) = delete;
  void operator=(const vtkLucentLocalTerm&) = delete;

  bool UploadFilter(vtkOpenGLRenderWindow* window, std::string& error);
  std::vector<vtkTextureObject*> FilterTextures() const;

  std::unique_ptr<lucent::technique::detail::HybridSplit> Split;
  std::string BuiltKey;
  int MapResolution = 0;
  lucent::atlas::LightViewFrame MapFrame;
  std::string LightViewVs, LightViewFs;
  lucent::vtkpass::LightViewTargets Map;
  vtkSmartPointer<vtkTextureObject> TapOffset, TapFactor, LocalTable, CentreCumulative;
  lucent::vtkpass::RowTable LocalRows, CentreRows;
  int Taps = 0, TapsPerRow = 1;
};

#endif
