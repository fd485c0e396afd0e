#pragma once
/// @file single_scattering_term.hpp
/// @brief The single-scattering term as an add-on of the dipole techniques: `withSingleScattering`
/// gives a technique the knobs `single` (off, refracted, normal), `single-samples`, `single-strata`
/// and `g`, and a frame that adds reference/single_scattering.hpp's radiance to the technique's own
/// multiple-scattering radiance, so every image can carry both terms (Jensen et al. 2001, Eq. 6).
#include <atomic>
#include <memory>

#include "../reference/single_scattering.hpp"
#include "technique.hpp"

namespace lucent::technique {

namespace detail {

inline std::vector<KnobSpec> singleScatteringKnobs() {
  return {
      KnobSpec::choice("single", {"off", "refracted", "normal"},
                       "add single scattering: along the refracted view ray (Jensen 2001) or the "
                       "negative normal (Wang, Tran, Luebke 2005's view-independent path)"),
      KnobSpec::integer("single-samples", 16, 1, 256,
                        "single scattering: deterministic depths per distinct channel"),
      KnobSpec::integer("single-strata", 8, 1, 64,
                        "single scattering under an environment: strata x 2 strata directions "
                        "per depth (a sphere seen along a stratum's pole: 1.5-5 % off at 6, "
                        "under 0.5 % at 16)"),
      KnobSpec::real("g", "0", -0.99, 0.99, "",
                     "HG mean cosine of single scattering; sigma_s = sigma_s' / (1 - g) keeps the "
                     "material's reduced coefficient (the multiple-scattering term depends on "
                     "sigma_s' alone)")};
}

/// The homogeneous medium of the scene's material for single scattering with asymmetry g.
inline reference::HomogeneousScattering singleScatteringMedium(const optics::Material& m,
                                                               double g) {
  reference::HomogeneousScattering s;
  for (int c = 0; c < 3; ++c) {
    s.sigmaS[c] = m.sigmaSPrime[c] / (1 - g);
    s.sigmaT[c] = m.sigmaA[c] + s.sigmaS[c];
  }
  s.g = g, s.eta = m.eta;
  return s;
}

/// A prepared technique whose frames also carry single scattering.
class WithSingleScattering final : public Prepared {
 public:
  WithSingleScattering(std::unique_ptr<Prepared> inner, const KnobValues& knobs)
      : Prepared(knobs), mInner(std::move(inner)) {}

  void retune(const KnobValues& knobs) override {
    Prepared::retune(knobs);
    mInner->retune(knobs);  // the inner technique reads the same values
  }

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    FrameResult out = mInner->frame(scene, request, stats);
    completeRadiance(out, request, scene.medium.material.eta);
    const std::string path = mKnobs.text("single");
    if (path == "off") return out;
    reference::SingleScatteringSettings settings;
    settings.path = path == "normal" ? reference::SingleScatteringSettings::Path::NegativeNormal
                                     : reference::SingleScatteringSettings::Path::Refracted;
    settings.depthSamples = int(mKnobs.integer("single-samples"));
    settings.environmentStrata = int(mKnobs.integer("single-strata"));
    settings.rayEpsilon = scene.rayEpsilon();
    const reference::SingleScattering term(
        singleScatteringMedium(scene.medium.material, mKnobs.real("g")), scene.lights, scene.mesh,
        scene.vertexNormals, *scene.caster, settings);
    stats.timeFrame("single_scattering", [&] { addTerm(term, scene, request, out.radiance); });
    return out;
  }

 private:
  static void addTerm(const reference::SingleScattering& term, const SceneDescription& scene,
                      const ShadeRequest& request, std::vector<glm::dvec3>& radiance) {
    const util::Progress progress = scene.stage("single scattering");
    std::atomic<std::size_t> done{0};
    scene.parallelFor(radiance.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const reference::ShadingPoint& p = request.points[i];
        const glm::dvec3 faceNormal = glm::normalize(scene.mesh.areaVector(p.triangle));
        const glm::dvec3 normal = scene::shadingNormal(scene.mesh, scene.vertexNormals, p.triangle,
                                                       {1 - p.u - p.v, p.u, p.v});
        const glm::dvec3 toEye =
            request.camera ? glm::normalize(request.camera->eye - p.position) : normal;
        radiance[i] += term.radiance(p.position, normal, faceNormal, toEye);
      }
      if (progress) progress(double(done += end - begin) / double(radiance.size()));
    });
  }

  std::unique_ptr<Prepared> mInner;
};

}  // namespace detail

/// `t` with the single-scattering knobs; its frames add the term when `single` is not off. The term
/// takes a homogeneous object; with a density field or inclusions it is refused before any work.
inline Technique withSingleScattering(Technique t) {
  for (KnobSpec& k : detail::singleScatteringKnobs()) t.knobs.push_back(std::move(k));
  t.capabilities.singleScattering = true;
  t.paper += "; single scattering (knob single): Jensen et al. 2001 Eq. 6, Wang, Tran, Luebke 2005";
  auto inner = std::move(t.prepare);
  auto innerValidity = std::move(t.validity);
  t.validity = [innerValidity](const SceneDescription& scene, const KnobValues& knobs) {
    if (knobs.text("single") != "off" &&
        (scene.medium.heterogeneous() || !scene.inclusions.empty()))
      return std::string(
          "single=" + knobs.text("single") +
          " takes a homogeneous object; use voxel-single or pathtrace for heterogeneous media");
    return innerValidity ? innerValidity(scene, knobs) : std::string();
  };
  t.prepare = [inner](const SceneDescription& scene, const KnobValues& knobs,
                      Statistics& stats) -> std::unique_ptr<Prepared> {
    return std::make_unique<detail::WithSingleScattering>(inner(scene, knobs, stats), knobs);
  };
  return t;
}

}  // namespace lucent::technique
