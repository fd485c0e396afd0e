// The "prt" technique: all-frequency wavelet PRT of translucency (Wang, Tran, Luebke 2005): prepare
// precomputes the transport vectors (include/lucent/prt), a frame relights them under the scene's
// environment, turned by the knob `rotate`. Compiled because the phase function's SVD uses Eigen.
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include <lucent/prt/relight.hpp>
#include <lucent/prt/specular.hpp>
#include <lucent/prt/thin_samples.hpp>
#include <lucent/prt/transport_points.hpp>
#include <lucent/technique/single_scattering_term.hpp>
#include <lucent/technique/technique.hpp>
#include <lucent/technique/validity.hpp>

#include "../prt/phase_svd.hpp"
#include "techniques.hpp"

namespace lucent::technique {

namespace {

/// The precomputation's structures may not exceed this (checked before they are built).
constexpr double kMaxPrecomputeBytes = 4.0 * (1u << 30);

std::vector<KnobSpec> prtKnobs() {
  return {
      KnobSpec::integer("cube", 16, 4, 64,
                        "environment cube-map face, texels across (a power of two; the paper's 32)",
                        Phase::Prepare),
      KnobSpec::integer("visibility-rays", 1, 1, 4, "rays per cube texel side at each sample",
                        Phase::Prepare),
      KnobSpec::real("fraction", "0.5", 0, kUnbounded, "",
                     "sample spacing as a fraction of the smallest mean free path", Phase::Prepare,
                     true),
      KnobSpec::integer("max-samples", 50000, 1, 2000000,
                        "surface-sample budget; a spacing from fraction is coarsened (with a "
                        "warning) to respect it",
                        Phase::Prepare),
      KnobSpec::integer("sample-terms", 512, 0, 24576,
                        "wavelet terms kept per sample's irradiance transport vector (0: all)",
                        Phase::Prepare),
      KnobSpec::integer("node-terms", 512, 0, 24576,
                        "wavelet terms kept per hierarchy node (0: all)", Phase::Prepare),
      KnobSpec::real("epsilon", "0.05", 0, kUnbounded, "",
                     "hierarchy bound: a node is one source when area / distance^2 < epsilon "
                     "(0: every sample)",
                     Phase::Prepare),
      KnobSpec::real("reach", "0.999", 0.9, 1, "",
                     "a vertex gathers R_d within the radius where this fraction of each "
                     "channel's light leaves (1: the whole surface)",
                     Phase::Prepare),
      KnobSpec::integer("transport-points", 4000, 0, 100000000,
                        "vertices the transport vectors are computed at, at most (one per grid "
                        "cell; every vertex interpolates the nearest facing ones; never sparser "
                        "than the profile's width; 0: every vertex)",
                        Phase::Prepare),
      KnobSpec::integer("vertex-terms", 768, 0, 24576,
                        "wavelet terms kept per vertex transport vector (0: all)", Phase::Prepare),
      KnobSpec::integer("light-terms", 256, 0, 24576,
                        "wavelet terms of the environment kept per frame (0: all)"),
      KnobSpec::choice("selection", {"area", "magnitude"},
                       "which light terms are kept: the largest weighted by their support's area "
                       "(Ng et al. 2003; better with few terms), or the largest"),
      KnobSpec::real("rotate", "0", -360, 360, "degrees",
                     "turn the environment about +y (a frame: no new precomputation)"),
      KnobSpec::choice("specular", {"off", "on"},
                       "add the smooth boundary's reflection of the environment (Fresnel "
                       "reflectance, the pre-convolved map in the mirror direction; no "
                       "self-shadowing, as in the paper)"),
      KnobSpec::real("specular-lobe", "0", 0, 100000, "",
                     "Phong exponent of the lobe the environment is pre-convolved with (0: a "
                     "mirror); a lobe costs (6 cube^2)^2 operations a frame"),
      KnobSpec::choice("single", {"on", "off"}, "add single scattering", Phase::Prepare),
      KnobSpec::real("g", "0", -0.99, 0.99, "",
                     "HG mean cosine; sigma_s = sigma_s' / (1 - g) keeps the reduced coefficient",
                     Phase::Prepare),
      KnobSpec::integer("phase-terms", 4, 1, 16,
                        "separable terms of the phase function (K; one when g = 0)",
                        Phase::Prepare),
      KnobSpec::integer("phase-cube", 8, 2, 16,
                        "phase table's cube, texels across (the paper's 16)", Phase::Prepare),
      KnobSpec::integer("single-cube", 4, 2, 64,
                        "single scattering: its transport's cube, texels across (a power of two "
                        "up to cube; spread onto cube)",
                        Phase::Prepare),
      KnobSpec::integer("single-samples", 4, 1, 256,
                        "single scattering: deterministic depths along -n", Phase::Prepare),
      detail::profileKnob(Phase::Prepare)};
}

/// The knobs as settings, and the checks that need more than a range.
prt::PrtSettings prtSettings(const SceneDescription& scene, const KnobValues& knobs) {
  prt::PrtSettings s;
  s.transport.size = int(knobs.integer("cube"));
  if (!prt::isPowerOfTwo(s.transport.size))
    throw RequestError("technique 'prt' knob cube=" + knobs.text("cube") +
                       " is not a power of two; use 4, 8, 16, 32 or 64");
  s.transport.subdivision = int(knobs.integer("visibility-rays"));
  s.transport.eta = scene.medium.material.eta;
  s.transport.rayEpsilon = scene.rayEpsilon();
  s.sampleTerms = std::size_t(knobs.integer("sample-terms"));
  s.nodeTerms = std::size_t(knobs.integer("node-terms"));
  s.vertexTerms = std::size_t(knobs.integer("vertex-terms"));
  s.epsilon = knobs.real("epsilon");
  s.reachFraction = knobs.real("reach");
  s.single = knobs.text("single") == "on";
  s.singleSampling.envSize = s.transport.size;
  s.singleSampling.size = int(knobs.integer("single-cube"));
  if (!prt::isPowerOfTwo(s.singleSampling.size))
    throw RequestError("technique 'prt' knob single-cube=" + knobs.text("single-cube") +
                       " is not a power of two; use 2, 4, 8, 16, 32 or 64");
  s.singleSampling.depthSamples = int(knobs.integer("single-samples"));
  s.singleSampling.rayEpsilon = scene.rayEpsilon();
  return s;
}

/// Bytes the precomputation would hold at most, refused before any work above the limit.
void checkPrecomputeBytes(std::size_t samples, std::size_t vertices, const prt::PrtSettings& s,
                          std::size_t phaseTerms) {
  const double texels = 6.0 * s.transport.size * s.transport.size;
  auto terms = [texels](std::size_t k) { return k == 0 ? texels : std::min<double>(k, texels); };
  const double bytes = double(samples) * 2 * terms(s.sampleTerms) * 8 +  // samples and nodes
                       double(vertices) * (1 + phaseTerms) * terms(s.vertexTerms) *
                           double(sizeof(prt::QuantizedVector::Index) + 6);
  if (bytes <= kMaxPrecomputeBytes) return;
  std::ostringstream why;
  why << "technique 'prt' would hold about " << bytes / double(1u << 30) << " GiB of transport "
      << "vectors (" << samples << " samples, " << vertices << " transport points); lower "
      << "sample-terms, vertex-terms, cube, max-samples or transport-points";
  throw RequestError(why.str());
}

class PrtPrepared final : public Prepared {
 public:
  PrtPrepared(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats)
      : Prepared(knobs) {
    const prt::PrtSettings s = prtSettings(scene, knobs);
    mModel.cubeSize = s.transport.size;
    mModel.eta = scene.medium.material.eta;
    const double g = knobs.real("g");
    mModel.phase = g == 0 ? prt::PhaseFactors::isotropic() : stats.timePrepare("phase_svd", [&] {
      return prt::factorPhase(g, int(knobs.integer("phase-cube")),
                              int(knobs.integer("phase-terms")))
          .factors;
    });
    const auto profile = detail::profileOf<double>(scene.medium.material, knobs);
    const double mfp = profile.minMeanFreePath();
    const reference::SpacingChoice spacing = reference::chooseSpacing(
        scene.mesh, mfp, knobs.real("fraction"), std::size_t(knobs.integer("max-samples")));
    if (spacing.budgetLimited)
      stats.warnings.push_back("prt: sample budget reached: spacing " +
                               lengthText(spacing.spacing) + " is coarser than " +
                               knobs.text("fraction") + " x the mean free path; raise max-samples");
    const std::size_t sampleCount = reference::countSurfaceSamples(scene.mesh, spacing.spacing);
    choosePoints(scene, knobs, stats);
    checkPrecomputeBytes(sampleCount, mPoints.vertex.size(), s,
                         s.single ? mModel.phase.terms() : 0);
    precompute(scene, s, profile, g, spacing.spacing, stats);
  }

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    std::vector<const scene::EnvironmentLight*> envs;
    for (const auto& light : scene.lights)
      if (const auto* env = std::get_if<scene::EnvironmentLight>(&light)) envs.push_back(env);
    const double angle = mKnobs.real("rotate") * optics::kPi / 180;
    const std::vector<glm::vec3> cube = stats.timeFrame(
        "environment_cube", [&] { return scene::sumOnCube(envs, mModel.cubeSize, angle); });
    std::size_t kept = 0;
    const std::vector<glm::vec3> light = stats.timeFrame("light_vector", [&] {
      return prt::lightVector(cube, mModel.cubeSize, std::size_t(mKnobs.integer("light-terms")),
                              mKnobs.text("selection") == "area" ? prt::Selection::AreaWeighted
                                                                 : prt::Selection::Magnitude,
                              &kept);
    });
    stats.figures["light_terms_kept"] = double(kept);
    const prt::VertexShading shading = stats.timeFrame("relight", [&] {
      return prt::shadingOnVertices(mPoints,
                                    prt::relightVertices(mModel, light, scene.parallelFor));
    });
    // The paper's specular component (Sec. 4), pre-convolved on the frame's cube.
    std::optional<prt::SpecularEnvironment> specular;
    if (mKnobs.text("specular") == "on")
      stats.timeFrame("specular_map", [&] {
        specular.emplace(envs, cube, mModel.cubeSize, angle, mKnobs.real("specular-lobe"),
                         scene.parallelFor);
      });
    FrameResult out;
    out.radiance = stats.timeFrame("interpolate", [&] {
      return pointsRadiance(scene, request, shading, specular ? &*specular : nullptr, stats);
    });
    return out;
  }

 private:
  /// The vertices whose transport is computed (the knob transport-points), the rest interpolated.
  void choosePoints(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    const std::vector<glm::dvec3> positions(scene.mesh.positions.begin(),
                                            scene.mesh.positions.end());
    const std::vector<glm::dvec3> normals(scene.vertexNormals.begin(), scene.vertexNormals.end());
    const double width = opticalScales(scene.medium.material).rdWidth();
    mPoints = stats.timePrepare("transport_points", [&] {
      return prt::chooseTransportPoints(positions, normals,
                                        std::size_t(knobs.integer("transport-points")), width,
                                        scene.parallelFor);
    });
    if (mPoints.spacingLimited)
      stats.warnings.push_back("prt: " + std::to_string(mPoints.vertex.size()) +
                               " transport points, more than transport-points=" +
                               knobs.text("transport-points") + ", keep their spacing within " +
                               "the profile's width " + lengthText(width));
    stats.figures["transport_points"] = double(mPoints.vertex.size());
  }

  void precompute(const SceneDescription& scene, const prt::PrtSettings& s,
                  const optics::Profile<double>& profile, double g, double spacing,
                  Statistics& stats) {
    const reference::SurfaceSamples samples = stats.timePrepare("samples", [&] {
      return prt::thinSamples(reference::buildSurfaceSamples(scene.mesh, spacing), spacing);
    });
    std::vector<prt::SparseScalars> transports = stats.timePrepare("irradiance_transport", [&] {
      return prt::sampleTransports(samples, *scene.caster, s, scene.parallelFor,
                                   scene.stage("irradiance transport"));
    });
    const prt::TransportHierarchy hierarchy = stats.timePrepare("hierarchy", [&] {
      return prt::TransportHierarchy(samples.position, samples.area, std::move(transports),
                                     s.transport.size, s.nodeTerms, s.epsilon);
    });
    static const std::vector<scene::Light> kNoLights;  // the term only follows light inside
    const reference::SingleScattering single(
        detail::singleScatteringMedium(scene.medium.material, g), kNoLights, scene.mesh,
        scene.vertexNormals, *scene.caster, reference::SingleScatteringSettings{});
    std::vector<glm::dvec3> vertices;
    std::vector<glm::vec3> normals;
    for (std::uint32_t v : mPoints.vertex)
      vertices.emplace_back(scene.mesh.positions[v]), normals.push_back(scene.vertexNormals[v]);
    const reference::NearField near = prt::nearField(samples, spacing);
    stats.timePrepare("vertex_transport", [&] {
      prt::vertexTransports(vertices, normals, hierarchy, profile, &near,
                            s.single ? &single : nullptr, *scene.caster, s, mModel,
                            scene.parallelFor, scene.stage("vertex transport"));
      return 0;
    });
    stats.samples = double(samples.size());
    stats.sampleUnit = "surface samples";
    stats.bytes = double(mModel.bytes());
    stats.figures["surface_samples"] = double(samples.size());
    stats.figures["hierarchy_nodes"] = double(hierarchy.nodeCount());
    stats.figures["hierarchy_bytes"] = double(hierarchy.bytes());
    stats.figures["vertices"] = double(scene.mesh.positions.size());
    stats.figures["bytes_per_point"] =
        double(mModel.bytes()) / double(std::max<std::size_t>(1, vertices.size()));
    stats.figures["phase_terms"] = double(mModel.phase.terms());
  }

  /// Radiance at every point: the relit vertices interpolated, viewed through the boundary, with
  /// the specular component added where it is asked for.
  std::vector<glm::dvec3> pointsRadiance(const SceneDescription& scene, const ShadeRequest& request,
                                         const prt::VertexShading& shading,
                                         const prt::SpecularEnvironment* specular,
                                         Statistics& stats) const {
    std::vector<glm::dvec3> radiance(request.points.size());
    std::atomic<std::size_t> clamped{0};
    scene.parallelFor(radiance.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const reference::ShadingPoint& p = request.points[i];
        const glm::dvec3 w(1 - p.u - p.v, p.u, p.v);
        const glm::dvec3 normal =
            scene::shadingNormal(scene.mesh, scene.vertexNormals, p.triangle, w);
        const glm::dvec3 toEye =
            request.camera ? glm::normalize(request.camera->eye - p.position) : normal;
        radiance[i] =
            prt::pointRadiance(mModel, shading, scene.mesh.triangles[p.triangle], w, normal, toEye);
        // A truncated light or phase expansion can dip below zero where the true value is small:
        // clamped, and counted.
        if (radiance[i].x < 0 || radiance[i].y < 0 || radiance[i].z < 0) {
          radiance[i] = glm::max(radiance[i], glm::dvec3(0));
          ++clamped;
        }
        if (specular) radiance[i] += specular->radiance(normal, toEye, scene.medium.material.eta);
      }
    });
    stats.figures["negative_points_clamped"] = double(clamped);
    return radiance;
  }

  prt::TransportPoints mPoints;
  prt::PrtModel mModel;
};

}  // namespace

Technique prtTechnique() {
  Technique t;
  t.name = "prt";
  t.summary =
      "all-frequency wavelet PRT: multiple and single scattering precomputed per vertex, relit "
      "under a (turning) environment by sparse Haar dot products";
  t.paper =
      "Wang, Tran, Luebke 2005, All-Frequency Interactive Relighting of Translucent Objects with "
      "Single and Multiple Scattering, Sec. 3-4 (Eq. 6-11); Ng, Ramamoorthi, Hanrahan 2003; "
      "Jensen, "
      "Buhler 2002";
  t.requiredLibrary = "Eigen (the phase function's SVD, src/prt/phase_svd.cpp)";
  t.knobs = prtKnobs();
  Capabilities& c = t.capabilities;
  c.pointLights = false, c.directionalLights = false, c.environmentLights = true;
  c.singleScattering = true;
  c.dynamicLight = true, c.dynamicMaterial = false;
  c.precomputeScaling = "O(samples x cube texels) rays + O(vertices x visited nodes x node terms)";
  c.frameScaling = "O(vertices x vertex terms) + O(pixels)";
  t.defaultSweep = {{"light-terms", {"16", "64", "256", "1024"}}};
  t.referenceKnobs = {{"transport-points", "0"},
                      {"sample-terms", "0"},
                      {"node-terms", "0"},
                      {"vertex-terms", "0"},
                      {"light-terms", "0"},
                      {"epsilon", "0"}};
  // The quick run leaves single scattering out so that it is measured against the dipole's truth
  // (tests/integration/test_prt.cpp and test_single_scattering.cpp measure the single term).
  t.quickKnobs = {{"cube", "8"}, {"max-samples", "4000"}, {"single", "off"}};
  // Multiple scattering is the dipole's; single scattering is the add-on every dipole technique
  // takes (knob single), so its model is the dipole's.
  t.model = "dipole";
  t.validRange =
      "homogeneous objects under environment light, optically thick as the dipole needs, static "
      "shape";
  t.validity = [](const SceneDescription& scene, const KnobValues&) {
    if (scene.medium.heterogeneous() || !scene.inclusions.empty())
      return std::string("prt precomputes a homogeneous object; use pathtrace or quadgraph");
    return validity::opticallyThick(scene.mesh, scene.medium.material);
  };
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs,
                 Statistics& stats) -> std::unique_ptr<Prepared> {
    return std::make_unique<PrtPrepared>(scene, knobs, stats);
  };
  return t;
}

}  // namespace lucent::technique
