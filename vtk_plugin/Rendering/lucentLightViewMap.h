/// @file lucentLightViewMap.h
/// @brief The object seen from its directional light (private to Lucent::Rendering): the map that
/// the hybrid's local term and taulut both filter, drawn by shaders/light_view_map.{vert,frag}
/// into a position (mm, tag) and a density (rho) target, framed as atlas::lightViewFrame frames
/// the CPU's map.
#ifndef lucentLightViewMap_h
#define lucentLightViewMap_h

#include <variant>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <lucent/atlas/translucent_shadow_map.hpp>

#include "lucentPassDrawing.h"
#include "vtkLucentSurface.h"

namespace lucent::vtkpass {

inline void setUniform3(vtkShaderProgram* program, const char* name, const glm::dvec3& v) {
  const float f[3] = {float(v.x), float(v.y), float(v.z)};
  program->SetUniform3f(name, f);
}

/// The uniforms of shaders/light_source.glsl for `light`, a point or a directional light, in the
/// frame the stage's positions are in.
inline void setLightSourceUniforms(vtkShaderProgram* program, const scene::Light& light) {
  if (const auto* p = std::get_if<scene::PointLight>(&light)) {
    program->SetUniformi("lightIsPoint", 1);
    setUniform3(program, "lightPosition", p->position);
    setUniform3(program, "lightIrradiance", p->intensity);
    setUniform3(program, "towardLight", glm::dvec3(0, 0, 1));  // unread
  } else if (const auto* d = std::get_if<scene::DirectionalLight>(&light)) {
    program->SetUniformi("lightIsPoint", 0);
    setUniform3(program, "towardLight", glm::normalize(d->towardLight));
    setUniform3(program, "lightIrradiance", d->irradiance);
    setUniform3(program, "lightPosition", glm::dvec3(0));  // unread
  }
}

/// The map's render targets, sized `resolution` a side.
struct LightViewTargets {
  vtkSmartPointer<vtkOpenGLFramebufferObject> fbo;
  vtkSmartPointer<vtkTextureObject> position, density, depth;

  /// Creates or resizes the targets, binds them, and clears them (uncovered, far).
  void begin(vtkOpenGLRenderWindow* window, int resolution) {
    if (!fbo) {
      fbo = newFramebuffer(window);
      position = newColorTexture(window, resolution, resolution);
      density = newColorTexture(window, resolution, resolution);
      depth = newDepthTexture(window, resolution, resolution);
    }
    for (auto* t : {position.Get(), density.Get(), depth.Get()})
      if (int(t->GetWidth()) != resolution) t->Resize(unsigned(resolution), unsigned(resolution));
    vtkOpenGLState* state = window->GetState();
    beginDrawing(state, fbo, {position, density}, depth, resolution, resolution);
    state->vtkglEnable(GL_DEPTH_TEST);  // the first hit from the light
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->vtkglClearColor(0, 0, 0, 0);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  void end() { endDrawing(fbo); }
  void release(vtkWindow* window) {
    for (auto* t : {position.Get(), density.Get(), depth.Get()})
      if (t) t->ReleaseGraphicsResources(window);
    if (fbo) fbo->ReleaseGraphicsResources(window);
    fbo = nullptr, position = density = depth = nullptr;
  }
};

/// The uniforms of light_view_map.{vert,frag}: the surface's millimetre frame, the map's frame and
/// the light (in millimetres).
inline void setLightViewUniforms(vtkShaderProgram* program, const vtkLucentSurface& surface,
                                 const atlas::LightViewFrame& frame, const scene::Light& lightMm,
                                 float eta) {
  setUniform3(program, "worldCentre",
              glm::dvec3(surface.GetCentre()[0], surface.GetCentre()[1], surface.GetCentre()[2]));
  program->SetUniformf("mmPerUnit", float(surface.GetMillimetresPerUnit()));
  setUniform3(program, "mapCentre", frame.centre);
  setUniform3(program, "mapT", frame.t);
  setUniform3(program, "mapB", frame.b);
  setUniform3(program, "mapAxis", frame.axis);
  program->SetUniformf("mapHalfExtent", float(frame.halfExtent));
  setLightSourceUniforms(program, lightMm);
  program->SetUniformf("eta", eta);
  program->SetUniformf("maxObliquity", float(atlas::kMaxObliquity));
}

/// The uniforms a filter of the map reads to find x_o's texel (taulut_shade.frag,
/// ring_filter.glsl), with the map's textures bound.
inline void bindMapForFiltering(vtkShaderProgram* program, const LightViewTargets& map,
                                const atlas::LightViewFrame& frame, int resolution) {
  map.position->Activate();
  map.density->Activate();
  program->SetUniformi("mapPosition", map.position->GetTextureUnit());
  program->SetUniformi("mapDensity", map.density->GetTextureUnit());
  program->SetUniformi("mapResolution", resolution);
  setUniform3(program, "mapCentre", frame.centre);
  setUniform3(program, "mapT", frame.t);
  setUniform3(program, "mapB", frame.b);
  program->SetUniformf("mapHalfExtent", float(frame.halfExtent));
  program->SetUniformf("mapTexel", float(2 * frame.halfExtent / resolution));
}
inline void unbindMap(const LightViewTargets& map) {
  map.density->Deactivate();
  map.position->Deactivate();
}

}  // namespace lucent::vtkpass

#endif
