/// The volumetric path tracer as a render method: the physical truth every dipole technique is measured
/// against. The scene's mesh becomes one medium (the material, sigma_s = sigma_s' / (1 - g)), optionally
/// with a density field and an inclusion of another material; lights, camera and images are the shared ones.
#include <chrono>
#include <cmath>

#include <lucent/reference/volume_path_tracer.hpp>
#include <lucent/scene/shapes.hpp>

#include "../io/exr_io.hpp"
#include "../raycast/embree_ray_caster.hpp"
#include "../util/error.hpp"
#include "../util/progress_bar.hpp"
#include "../util/tbb_parallel.hpp"
#include "density_field.hpp"
#include "methods.hpp"

namespace lucent::render {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Whether a point lies inside the closed mesh (odd crossings along +x).
bool inside(const scene::RayCaster& caster, glm::dvec3 p, double epsilon) {
  int crossings = 0;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(1, 0.0123, 0.0321));
  for (int i = 0; i < 10000; ++i) {
    const auto hit = caster.intersect(p, dir, epsilon, std::numeric_limits<double>::infinity());
    if (!hit) break;
    ++crossings;
    p += hit->t * dir;
  }
  return crossings % 2 == 1;
}

reference::ScatteringOrders ordersKnob(const Knobs& knobs) {
  return knobs.choice<reference::ScatteringOrders>("orders", {{"all", reference::ScatteringOrders::All},
                                                              {"single", reference::ScatteringOrders::Single},
                                                              {"multiple", reference::ScatteringOrders::Multiple}});
}
}  // namespace

Method pathtraceMethod() {
  return {"pathtrace",
          "volumetric Monte Carlo path tracing inside the mesh (physical truth: every scattering order, exact boundary)",
          {{"spp", "16", "samples per pixel (the error falls as 1/sqrt(spp); see the reported standard error)"},
           {"seed", "1", "random seed (fixed seeds give identical images on any thread count)"},
           {"g", "0", "HG mean cosine; sigma_s = sigma_s' / (1 - g) keeps the material's reduced coefficient"},
           {"boundary", "fresnel", "fresnel (the material's eta) or matched (eta 1: no refraction, no reflection)"},
           {"subsurface", "0", "1 = leave out the camera's first surface reflection (what the dipole methods render)"},
           {"orders", "all", "scattering orders counted: all, single or multiple"},
           {"env", "escape", "environment light: escape (paths that leave look it up) or connect (light subpaths)"},
           {"paths", "all", "escaping paths counted: all, or connectable (those a delta light could reach through a refracting boundary)"},
           {"light-paths", "1", "light subpaths per delta light and camera sample (behind a refracting boundary)"},
           {"guide-radius", "0", "mm: spread of light entry points around the camera's (0 = 1/sigma_tr of the material)"},
           {"max-events", "200000", "surface and scattering events per path before it is dropped (counted)"},
           {"density", "", "noise:F (procedural field), FILE.vdb[:GRID] or FILE.vti[:ARRAY] (fitted to the bounding box); empty = homogeneous"},
           {"inclusion", "", "a material name: a sphere of it at the bounding-box centre, inside the object"},
           {"inclusion-radius", "0.3", "radius of the inclusion as a fraction of half the smallest box extent"},
           {"stderr", "", "write the per-pixel standard error image to this EXR file"}},
          [](const cli::Scene& scene, const Knobs& knobs, bool showProgress) {
            RenderResult out;
            const auto start = Clock::now();
            const scene::Bounds bounds = scene.mesh.bounds();
            const double diag = bounds.diagonal();
            reference::PathTracerSettings s;
            s.samplesPerPixel = knobs.integer("spp", 1, 1 << 20);
            s.seed = std::uint64_t(knobs.numberIn("seed", 0, 1e15, true));
            s.maxEvents = std::uint64_t(knobs.numberIn("max-events", 10, 1e9, true));
            s.subsurfaceOnly = knobs.integer("subsurface", 0, 1) == 1;
            s.orders = ordersKnob(knobs);
            s.environment = knobs.choice<reference::EnvironmentStrategy>(
                "env", {{"escape", reference::EnvironmentStrategy::Escape}, {"connect", reference::EnvironmentStrategy::Connect}});
            s.lightSubpaths = knobs.integer("light-paths", 1, 1024);
            s.connectableOnly = knobs.choice<bool>("paths", {{"all", false}, {"connectable", true}});
            s.guideRadius = knobs.numberIn("guide-radius", 0, 1e9);
            s.rayEpsilon = 1e-5 * diag;
            const double g = knobs.numberIn("g", -0.99, 0.99);
            const bool matched = knobs.choice<bool>("boundary", {{"fresnel", false}, {"matched", true}});

            reference::MediumScene media;
            reference::Medium material = reference::mediumFromMaterial(scene.material, g);
            if (matched) material.eta = 1;
            if (const auto field = parseDensityField("pathtrace", "density", knobs.text("density"), bounds)) {
              material.density = field.at;
              material.maxDensity = 1;
              out.notes.push_back("density: " + field.description);
            }
            const auto materialId = media.addMedium(material);
            media.addBody(scene.mesh, materialId, 0);
            if (!knobs.text("inclusion").empty()) {
              const auto found = optics::findMaterial(knobs.text("inclusion"));
              if (!found) throw InputError("method 'pathtrace' knob inclusion='" + knobs.text("inclusion") +
                                           "' is not a material; `lucent materials` lists them");
              reference::Medium inner = reference::mediumFromMaterial(*found, g);
              if (matched) inner.eta = 1;
              const glm::dvec3 extent = bounds.hi - bounds.lo;
              const double radius = knobs.numberIn("inclusion-radius", 1e-3, 1) * 0.5 * std::min(extent.x, std::min(extent.y, extent.z));
              const scene::TriangleMesh sphere = scene::shapes::sphere(radius, 4, bounds.center());
              for (const auto& p : sphere.positions)
                if (!inside(*scene.caster, glm::dvec3(p), 1e-7 * diag))
                  throw InputError("method 'pathtrace': the inclusion sphere (radius " + std::to_string(radius) +
                                   " mm at the bounding-box centre) is not inside the object; lower inclusion-radius "
                                   "or use a shape that is solid at its centre (e.g. --shape sphere)");
              media.addBody(sphere, media.addMedium(inner), materialId);
              out.notes.push_back("inclusion: " + found->name + " sphere of radius " + std::to_string(radius) + " mm");
            }

            const raycast::EmbreeRayCaster caster(media.mesh);
            const reference::VolumePathTracer tracer(media, caster, scene.lights, s);
            if (tracer.joinsDeltaLights())
              out.notes.push_back("pathtrace: point/directional light behind a refracting boundary is reached by light subpaths "
                                  "joined to camera segments; paths whose every scatter-to-scatter segment is specular (single "
                                  "scattering among them) cannot be sampled and are left out (boundary=matched or an "
                                  "environment light include them)");
            util::ProgressBar bar("path tracing", showProgress);
            const reference::PathTracedImage img =
                reference::renderPathTraced(tracer, caster, scene.camera, s, util::tbbFor, [&](double f) { bar.update(f); });
            bar.finish();
            out.image = img.image;
            if (!knobs.text("stderr").empty()) io::writeExr(knobs.text("stderr"), img.standardError);

            // Standard errors: per pixel (relative, mean over lit pixels) and of the whole image's mean.
            double relSum = 0, meanSum = 0, varSum = 0;
            std::size_t lit = 0, covered = 0;
            for (std::size_t i = 0; i < img.image.pixels.size(); ++i) {
              if (!img.image.covered(i)) continue;
              ++covered;
              const glm::dvec3 m(img.image.pixels[i]), e(img.standardError.pixels[i]);
              const double lum = (m.x + m.y + m.z) / 3, lumErr = (e.x + e.y + e.z) / 3;
              meanSum += lum;
              varSum += lumErr * lumErr;
              if (lum > 0) relSum += lumErr / lum, ++lit;
            }
            const reference::PathTracerStats& st = img.stats;
            out.seconds = since(start);
            out.figures["spp"] = s.samplesPerPixel;
            out.figures["shaded_pixels"] = double(covered);
            out.figures["mean_pixel_relative_stderr"] = lit ? relSum / double(lit) : 0;
            out.figures["image_mean_relative_stderr"] = meanSum > 0 ? std::sqrt(varSum) / meanSum : 0;
            out.figures["camera_samples"] = double(st.cameraSamples);
            out.figures["scatter_events"] = double(st.scatterEvents);
            out.figures["light_subpaths"] = double(st.lightSubpaths);
            out.figures["joins"] = double(st.connections);
            out.figures["guide_radius_mm"] = tracer.guideRadius();
            out.figures["truncated_paths"] = double(st.truncatedPaths);
            out.figures["leaked_paths"] = double(st.leakedPaths);
            auto warn = [&](std::uint64_t n, const std::string& what) {
              if (n) out.notes.push_back("pathtrace: " + std::to_string(n) + " " + what);
            };
            warn(st.truncatedPaths, "paths reached max-events and were dropped (their weight is lost: a bias); raise max-events");
            warn(st.leakedPaths, "paths found no surface from inside the medium (is the mesh closed?)");
            warn(st.mediumMismatches, "surface crossings disagreed with the media on either side (self-intersecting or nested wrongly?)");
            warn(st.medium.majorantViolations, "density samples exceeded the majorant and were clamped");
            warn(st.nonFiniteSamples, "non-finite estimates were dropped (please report this)");
            return out;
          }};
}

}  // namespace lucent::render
