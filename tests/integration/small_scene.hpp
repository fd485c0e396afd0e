#pragma once
// A small lit scene for integration tests: a mesh scaled to size, Embree, a framed camera, a back point
// light and a directional fill (the default scene's arrangement), and the brute-force truth's renderer.
#include <memory>
#include <vector>

#include <lucent/optics/materials.hpp>
#include <lucent/reference/dipole_truth.hpp>

#include "raycast/embree_ray_caster.hpp"
#include "util/tbb_parallel.hpp"

namespace lucent::test {
template <class T>
optics::Dipole<T> dipoleOf(const char* name, double eta = -1) {
  const optics::Material m = *optics::findMaterial(name);
  return optics::Dipole<T>::make(optics::Rgb<T>(m.sigmaA), optics::Rgb<T>(m.sigmaSPrime), T(eta > 0 ? eta : m.eta));
}

struct SmallScene {
  scene::TriangleMesh mesh;
  std::vector<glm::vec3> normals;
  std::unique_ptr<raycast::EmbreeRayCaster> caster;
  scene::PinholeCamera camera;
  std::vector<scene::Light> lights;
  scene::IrradianceSettings irr;

  SmallScene(scene::TriangleMesh m, double sizeMm, int res) : mesh(std::move(m)) {
    mesh.scaleToSize(sizeMm);
    normals = mesh.vertexNormals();
    caster = std::make_unique<raycast::EmbreeRayCaster>(mesh);
    camera = scene::PinholeCamera::frame(mesh.bounds(), glm::dvec3(0.2, 0.4, 1), res, res);
    const glm::dvec3 back = glm::normalize(glm::dvec3(0.3, 0.6, -1)) * (2 * sizeMm);
    lights = {scene::PointLight{back, glm::dvec3(glm::dot(back, back))},
              scene::DirectionalLight{glm::normalize(glm::dvec3(-0.5, 0.3, 1)), glm::dvec3(0.2)}};
    irr.rayEpsilon = 1e-5 * sizeMm;
  }

  template <class T>
  image::Image render(const optics::Dipole<T>& d, double spacing) const {
    const auto samples = reference::buildSurfaceSamples(mesh, spacing);
    const reference::DipoleTruth<T> truth(samples, d, lights, *caster, irr, util::tbbFor);
    const auto hits = reference::primaryHits(camera, mesh, normals, *caster, util::tbbFor);
    return reference::renderTruth(truth, camera, hits, util::tbbFor);
  }
};

}  // namespace lucent::test
