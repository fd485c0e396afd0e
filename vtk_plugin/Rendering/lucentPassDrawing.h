/// @file lucentPassDrawing.h
/// @brief What every stage of vtkLucentPass draws with (private to Lucent::Rendering): the shared
/// GLSL pasted into a stage, texel-exact textures, and drawing into one of the pass's framebuffers.
#ifndef lucentPassDrawing_h
#define lucentPassDrawing_h

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>

#include "lucent_glsl.h"

namespace lucent::vtkpass {

/// The shared GLSL pasted where a stage asks for it (shaders/README.md).
inline std::string withSharedGlsl(const char* stage) {
  std::string source = stage;
  vtkShaderProgram::Substitute(source, "//LUCENT::Optics",
                               std::string(lucent::glsl::kConstants) + lucent::glsl::kOpticsGlsl);
  // LightSource before Light, whose marker is its prefix; light.glsl reads light_source.glsl.
  vtkShaderProgram::Substitute(source, "//LUCENT::LightSource", lucent::glsl::kLightSourceGlsl);
  vtkShaderProgram::Substitute(
      source, "//LUCENT::Light",
      std::string(lucent::glsl::kLightSourceGlsl) + lucent::glsl::kLightGlsl);
  vtkShaderProgram::Substitute(source, "//LUCENT::Voxel", lucent::glsl::kVoxelGlsl);
  vtkShaderProgram::Substitute(source, "//LUCENT::RingFilter", lucent::glsl::kRingFilterGlsl);
  vtkShaderProgram::Substitute(source, "//LUCENT::Display", lucent::glsl::kDisplayGlsl);
  return source;
}

/// shaders/light_view_map.frag tagging covered texels 1 (the hybrid's translucent shadow map) or
/// 1 + their surface voxel's number (taulut's voxel-number map).
inline std::string lightViewMapShader(bool voxelNumber) {
  std::string source = lucent::glsl::kLightViewMapFrag;
  vtkShaderProgram::Substitute(
      source, "//LUCENT::MapVariant",
      voxelNumber ? "#define LUCENT_VOXEL_NUMBER 1" : "#define LUCENT_VOXEL_NUMBER 0");
  return withSharedGlsl(source.c_str());
}

/// Every texture of the pass is read texel for texel: nearest filtering, clamped at the edges.
inline vtkSmartPointer<vtkTextureObject> newNearestTexture(vtkOpenGLRenderWindow* window) {
  auto t = vtkSmartPointer<vtkTextureObject>::New();
  t->SetContext(window);
  t->SetMinificationFilter(vtkTextureObject::Nearest);
  t->SetMagnificationFilter(vtkTextureObject::Nearest);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->SetWrapR(vtkTextureObject::ClampToEdge);
  return t;
}

inline vtkSmartPointer<vtkTextureObject> newColorTexture(vtkOpenGLRenderWindow* window, int width,
                                                         int height) {
  auto t = newNearestTexture(window);
  t->Allocate2D(unsigned(width), unsigned(height), 4, VTK_FLOAT);
  return t;
}

inline vtkSmartPointer<vtkTextureObject> newDepthTexture(vtkOpenGLRenderWindow* window, int width,
                                                         int height) {
  auto t = newNearestTexture(window);
  t->AllocateDepth(unsigned(width), unsigned(height), vtkTextureObject::Float32);
  return t;
}

/// Upper bound on texels per row of the 1-D tables laid out in 2-D (the GL limit may be lower).
constexpr int kMaxRowTexels = 16384;

/// A table of `count` RGBA values as rows of `rowTexels` (the last padded), or one texel of zeros.
inline bool uploadRows(vtkTextureObject* texture, std::vector<float> rgba, int rowTexels) {
  const std::size_t count = rgba.size() / 4;
  const std::size_t width = std::max<std::size_t>(1, std::min<std::size_t>(count, rowTexels));
  const std::size_t rows = std::max<std::size_t>(1, (count + width - 1) / width);
  rgba.resize(width * rows * 4, 0.0f);
  return texture->Create2DFromRaw(unsigned(width), unsigned(rows), 4, VTK_FLOAT, rgba.data());
}

/// Texels a row of a 1-D table may take on this GPU (kMaxRowTexels, or the GL limit if lower).
inline int rowLimit(vtkOpenGLRenderWindow* window) {
  const int glLimit = vtkTextureObject::GetMaximumTextureSize(window);  // -1 without a context
  return glLimit > 0 ? std::min(kMaxRowTexels, glLimit) : kMaxRowTexels;
}

/// A table on the nodes r_i = rMax (i / (n - 1))^2 (optics::RadialTable's, the ring filter's
/// cumulative grid) as rows of a texture, and the uniforms of LucentRadialTable
/// (shaders/optics.glsl) that read it.
struct RowTable {
  int nodes = 0, perRow = 1;
  float rMax = 1;
  /// Uploads `values` (RGB per node); false when the texture cannot hold them.
  template <class Rgb>
  bool upload(vtkOpenGLRenderWindow* window, vtkTextureObject* texture,
              const std::vector<Rgb>& values, double rMaxMm) {
    std::vector<float> rgba;
    rgba.reserve(4 * values.size());
    for (const auto& v : values)
      rgba.insert(rgba.end(), {float(v[0]), float(v[1]), float(v[2]), 0.0f});
    const int limit = rowLimit(window);
    nodes = int(values.size());
    perRow = std::max(1, std::min(nodes, limit));
    rMax = float(rMaxMm);
    return uploadRows(texture, std::move(rgba), limit);
  }
  /// Sets `name`.nodes, .perRow and .rMax.
  void setUniforms(vtkShaderProgram* program, const std::string& name) const {
    program->SetUniformi((name + ".nodes").c_str(), nodes);
    program->SetUniformi((name + ".perRow").c_str(), perRow);
    program->SetUniformf((name + ".rMax").c_str(), rMax);
  }
};

inline vtkSmartPointer<vtkOpenGLFramebufferObject> newFramebuffer(vtkOpenGLRenderWindow* window) {
  auto f = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  f->SetContext(window);
  return f;
}

/// Saves the caller's bindings, binds @p fbo with these attachments for drawing, viewport and
/// scissor 0,0,w,h (not the renderer's tile origin: inside our own framebuffers the origin is
/// always 0).
inline void beginDrawing(vtkOpenGLState* state, vtkOpenGLFramebufferObject* fbo,
                         std::initializer_list<vtkTextureObject*> colors, vtkTextureObject* depth,
                         int width, int height) {
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  unsigned count = 0;
  for (vtkTextureObject* c : colors) fbo->AddColorAttachment(count++, c);
  if (depth) fbo->AddDepthAttachment(depth);
  if (count > 0)
    fbo->ActivateDrawBuffers(count);
  else
    fbo->DeactivateDrawBuffers();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglScissor(0, 0, width, height);
}

inline void endDrawing(vtkOpenGLFramebufferObject* fbo) {
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
}

}  // namespace lucent::vtkpass

#endif
