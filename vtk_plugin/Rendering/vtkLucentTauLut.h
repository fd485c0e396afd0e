/// @file vtkLucentTauLut.h
/// @brief taulut's GPU twin for one translucent actor (private to Lucent::Rendering): the voxel
/// optical-thickness LUT of Mochida et al. 2016. taulut's own prepare runs on the CPU
/// (lucent/technique/optical_thickness.hpp: media grid, surface voxels, per-medium path lengths);
/// its grid, surface voxels and table go up as textures; per frame the light view renders the
/// irradiance and voxel-number maps, and every pixel sums Eq. 1-3 over the ring filter's taps
/// (shaders/taulut_*.{vert,frag}, shaders/voxel.glsl). A material edit re-uploads sigma_t only.
#ifndef vtkLucentTauLut_h
#define vtkLucentTauLut_h

#include <memory>
#include <string>

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <glm/vec3.hpp>

#include <lucent/technique/optical_thickness.hpp>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;
class vtkLucentSurface;

class vtkLucentTauLut : public vtkObject {
 public:
  static vtkLucentTauLut* New();
  vtkTypeMacro(vtkLucentTauLut, vtkObject);

  /// Runs taulut's prepare when `key` (the geometry and prepare knobs it was built for) changed,
  /// and uploads the result; false with @p error (the technique's message) when it cannot.
  bool Prepare(vtkOpenGLRenderWindow* window, const lucent::technique::Technique& taulut,
               const lucent::technique::SceneDescription& scene,
               const lucent::technique::KnobValues& knobs, const std::string& key,
               std::string& error);

  /// The light view (stage 1) under the scene's light and material; false when a shader failed.
  bool RenderLightView(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface,
                       const lucent::technique::SceneDescription& scene, std::string& error);

  /// Stage 2: sets the shading program's uniforms and textures and draws the surface into the
  /// framebuffer the caller bound; `camera` in world coordinates.
  bool Shade(vtkOpenGLRenderWindow* window, vtkLucentSurface* surface, const float camera[3],
             vtkShaderProgram* program);

  /// Surface voxels and table bytes of the last prepare (what it costs on the GPU).
  std::size_t GetSurfaceVoxels() const;
  double GetTextureBytes() const { return this->TextureBytes; }

  void ReleaseGraphicsResources(vtkWindow* window);

 protected:
  vtkLucentTauLut();
  ~vtkLucentTauLut() override;

 private:
  vtkLucentTauLut(const vtkLucentTauLut&) = delete;
  void operator=(const vtkLucentTauLut&) = delete;

  bool Upload(vtkOpenGLRenderWindow* window, std::string& error);
  bool UploadTable(vtkOpenGLRenderWindow* window, std::string& error);
  void UploadFrameInputs(vtkOpenGLRenderWindow* window,
                         const lucent::technique::SceneDescription& scene);
  void BindVoxelData(vtkShaderProgram* program);
  void UnbindVoxelData();

  struct Textures;
  std::unique_ptr<Textures> Tex;
  std::unique_ptr<lucent::technique::Prepared> Prepared;
  const lucent::technique::detail::TauLut* Lut = nullptr;  ///< Prepared, as taulut's
  std::string BuiltKey;
  std::string LightViewVs, LightViewFs;
  double TextureBytes = 0;
  // This frame's inputs (UploadFrameInputs).
  lucent::atlas::LightViewFrame MapFrame;
  lucent::atlas::RingFilter Filter;
  float Eta = 1.3f;
  int MapResolution = 0, RowTexels = 1;
};

#endif
