// The curves of docs/accuracy/prt.md, measured in one run:
// 1. the phase function's factorisation: RMS error against K terms for HG g in {-0.4, -0.25, 0,
//    0.25, 0.5} on the paper's 6 x 16 x 16 table (Wang, Tran, Luebke 2005, Fig. 6f);
// 2. the all-frequency curve: relighting error against the light terms kept (area-weighted and
//    plain magnitude) and the frame time, on a 30 mm skin1 torus under the synthetic sky with a
//    sun, against the same precomputation relit with every light term; multiple scattering only.
//
//   build/bench/prt_curves [OUT_DIR]   (default: prt-curves; writes phase.csv/png, light.csv/png)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <lucent/image/metrics.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/prt/relight.hpp>
#include <lucent/reference/dipole_truth.hpp>
#include <lucent/scene/shapes.hpp>

#include "plot/line_chart.hpp"
#include "prt/phase_svd.hpp"
#include "raycast/embree_ray_caster.hpp"
#include "scene/synthetic_sky.hpp"
#include "util/tbb_parallel.hpp"

using namespace lucent;

namespace {
const unsigned char kColours[5][3] = {
    {31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189}};

void phaseCurves(const std::filesystem::path& dir) {
  std::ofstream csv(dir / "phase.csv");
  csv << "g,terms,rms_error\n";
  std::vector<plot::Series> series;
  const double gs[] = {-0.4, -0.25, 0, 0.25, 0.5};
  for (int i = 0; i < 5; ++i) {
    plot::Series s;
    s.name = "g = " + std::to_string(gs[i]).substr(0, gs[i] < 0 ? 5 : 4);
    std::copy(kColours[i], kColours[i] + 3, s.rgb);
    const prt::PhaseDecomposition d = prt::factorPhase(gs[i], 16, 16);
    for (int k = 1; k <= 16; ++k) {
      prt::PhaseFactors f = d.factors;
      f.light.resize(std::size_t(k)), f.view.resize(std::size_t(k));
      const double e = prt::phaseFactorError(f, gs[i]);
      csv << gs[i] << "," << k << "," << e << "\n";
      std::printf("phase g %+.2f  K %2d  rms error %.3e\n", gs[i], k, e);
      if (e > 1e-6) s.x.push_back(k), s.y.push_back(e);  // g = 0: exact from K = 1, not drawn
    }
    if (!s.x.empty()) series.push_back(s);
  }
  if (plot::chartsAvailable())
    plot::writeLineChart((dir / "phase.png").string(),
                         {"HG phase function: RMS error of K separable terms (6 x 16 x 16 table)",
                          "terms K", "relative RMS error", false, true},
                         series);
}

void lightCurves(const std::filesystem::path& dir) {
  scene::TriangleMesh mesh = scene::shapes::torus(1.0, 0.4, 96, 48);
  mesh.scaleToSize(30);
  const std::vector<glm::vec3> normals = mesh.vertexNormals();
  const raycast::EmbreeRayCaster caster(mesh);
  const optics::Material m = *optics::findMaterial("skin1");
  const auto profile =
      optics::Profile<double>::make(optics::ProfileModel::Dipole, optics::Rgb<double>(m.sigmaA),
                                    optics::Rgb<double>(m.sigmaSPrime), m.eta);
  prt::PrtSettings s;
  s.transport.size = 16, s.transport.eta = m.eta, s.transport.rayEpsilon = 1e-4;
  s.epsilon = 0.05, s.single = false;  // every wavelet term kept: only the light is truncated
  const auto spacing = reference::chooseSpacing(mesh, profile.minMeanFreePath(), 0.5, 50000);
  const reference::SurfaceSamples samples = reference::buildSurfaceSamples(mesh, spacing.spacing);
  auto t0 = std::chrono::steady_clock::now();
  prt::TransportHierarchy hierarchy(samples.position, samples.area,
                                    prt::sampleTransports(samples, caster, s, util::tbbFor, {}),
                                    s.transport.size, 0, s.epsilon);
  prt::PrtModel model;
  model.cubeSize = 16, model.eta = m.eta, model.phase = prt::PhaseFactors::isotropic();
  const reference::NearField near = prt::nearField(samples, spacing.spacing);
  const std::vector<glm::dvec3> vertices(mesh.positions.begin(), mesh.positions.end());
  prt::vertexTransports(vertices, normals, hierarchy, profile, &near, nullptr, caster, s, model,
                        util::tbbFor, {});
  std::printf("precomputed %zu vertices from %zu samples in %.1f s, %.1f MB\n", vertices.size(),
              samples.size(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
              double(model.bytes()) / 1e6);
  const scene::EnvironmentLight sky = scene::syntheticSky();
  const auto all = prt::relightVertices(
      model, prt::lightVector({&sky}, 16, 0, 0, prt::Selection::Magnitude), util::tbbFor);
  std::ofstream csv(dir / "light.csv");
  csv << "selection,light_terms,relative_rms,frame_ms\n";
  std::vector<plot::Series> series;
  int colour = 0;
  for (auto selection : {prt::Selection::AreaWeighted, prt::Selection::Magnitude}) {
    plot::Series curve;
    curve.name = selection == prt::Selection::AreaWeighted ? "area-weighted" : "magnitude";
    std::copy(kColours[colour], kColours[colour] + 3, curve.rgb), ++colour;
    for (std::size_t terms : {1u, 4u, 16u, 64u, 256u, 1024u, 4096u}) {
      const auto t = std::chrono::steady_clock::now();
      const auto light = prt::lightVector({&sky}, 16, 0, terms, selection);
      const auto relit = prt::relightVertices(model, light, util::tbbFor);
      const double ms =
          1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      const double e = image::relativeRms(relit.diffuse, all.diffuse);
      csv << curve.name << "," << terms << "," << e << "," << ms << "\n";
      std::printf("light %-13s %5zu terms  relative RMS %.3e  frame %.1f ms\n", curve.name.c_str(),
                  terms, e, ms);
      if (e > 0) curve.x.push_back(double(terms)), curve.y.push_back(e);
    }
    series.push_back(curve);
  }
  if (plot::chartsAvailable())
    plot::writeLineChart(
        (dir / "light.png").string(),
        {"Relighting error against light terms kept (30 mm skin1 torus, sky with a sun)",
         "light wavelet terms kept", "relative RMS against all 6144 terms", true, true},
        series);
}
}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "prt-curves";
  std::filesystem::create_directories(dir);
  phaseCurves(dir);
  lightCurves(dir);
  if (!plot::chartsAvailable())
    std::printf("no display: CSVs only (run under xvfb-run for PNGs)\n");
  return 0;
}
