// Run-time changes on one QuadGraph without rebuilding it (Wang et al. 2010 Sec. 6.4): the graph is built
// once; then the light orbits, the material changes, and the object bends. Each kind of change redoes only
// what it must: light -> irradiance + solve; material -> assembly + solve; shape -> geometric weights +
// assembly + solve (TetGen never runs again). Frames are shown on the Sec. 5.3 node surface, which follows
// the deformed graph by construction.
//
//   build/examples/quadgraph_runtime_changes [OUT_DIR]   (default: quadgraph-runtime)
// writes OUT_DIR/frames.png (one row per kind of change) and OUT_DIR/frames.csv (times per frame), and
// prints the same table with the one-off build time it avoids.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <lucent/reference/vertex_radiosity.hpp>

#include "cli/image_output.hpp"
#include "cli/scene_setup.hpp"
#include "raycast/embree_ray_caster.hpp"
#include "render/quadgraph_pipeline.hpp"
#include "util/error.hpp"
#include "util/tbb_parallel.hpp"

using namespace lucent;
using Clock = std::chrono::steady_clock;

namespace {
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

render::MediumField homogeneous(const optics::Material& m) {
  return [m](const glm::dvec3&, int c) { return std::pair<double, double>{m.sigmaA[c], m.sigmaSPrime[c]}; };
}

/// A bend about the z axis: x' = (R + y) sin(x / R), y' = (R + y) cos(x / R) - R, with R from the curvature.
/// Angle-preserving near the centre, so tets stay positively oriented for moderate curvatures.
glm::dvec3 bend(const glm::dvec3& p, double curvature) {
  if (curvature == 0) return p;
  const double r = 1 / curvature, a = p.x * curvature;
  return {(r + p.y) * std::sin(a), (r + p.y) * std::cos(a) - r, p.z};
}

struct Row {
  std::string change;
  double irradiance = 0, geometry = 0, assemble = 0, solve = 0, display = 0;
};
}  // namespace

int main(int argc, char** argv) try {
  const std::filesystem::path outDir = argc > 1 ? argv[1] : "quadgraph-runtime";
  std::filesystem::create_directories(outDir);

  // The scene: a 30 mm torus of skin, back-lit, as `lucent render --shape torus` builds it.
  cli::Args args("example", "", cli::sceneOptionSpecs());
  std::vector<std::string> words = {"example", "--shape", "torus", "--width", "160", "--height", "160"};
  std::vector<char*> argvScene;
  for (auto& w : words) argvScene.push_back(w.data());
  args.parse(int(argvScene.size()), argvScene.data(), 1);
  cli::Scene scene = cli::buildScene(args);

  std::vector<std::string> notes;
  render::QuadGraphOptions options;
  options.gradingK = 1;
  options.levels = 2;
  auto t = Clock::now();
  render::QuadGraphPipeline pipeline(scene.mesh, scene.meshName, options, notes, false);
  const double buildSeconds = since(t);
  for (const auto& n : notes) std::fprintf(stderr, "note: %s\n", n.c_str());
  std::printf("built once: %zu nodes in %.2f s (TetGen, graph, levels, transfers)\n", pipeline.finest().nodeCount(),
              buildSeconds);

  std::vector<Row> rows;
  std::vector<image::Image> frames;
  scene::TriangleMesh mesh = scene.mesh;  // the input surface, bent along with the graph for shadow rays
  std::unique_ptr<scene::RayCaster> caster = std::make_unique<raycast::EmbreeRayCaster>(mesh);
  std::vector<glm::vec3> normals = mesh.vertexNormals();  // recomputed only when the mesh bends
  auto render = [&](const std::vector<scene::Light>& lights, const optics::Material& material, Row row) {
    auto t0 = Clock::now();
    const auto q = pipeline.irradiance(mesh, normals, lights, *caster, material.eta);
    row.irradiance = since(t0);
    const auto frame = pipeline.solve(q, homogeneous(material), material.eta, false);
    row.assemble = frame.assembleSeconds;
    row.solve = frame.solveSeconds;
    t0 = Clock::now();
    const scene::TriangleMesh nodes = pipeline.nodeSurface().mesh(pipeline.finest());
    const raycast::EmbreeRayCaster nodeCaster(nodes);
    const reference::VertexRadiosity shading(nodes, frame.radiosity, material.eta);
    const auto hits = reference::primaryHits(scene.camera, nodes, nodes.vertexNormals(), nodeCaster, util::tbbFor);
    frames.push_back(reference::renderTruth(shading, scene.camera, hits, util::tbbFor));
    row.display = since(t0);
    rows.push_back(row);
  };

  // 1. The light orbits the object (the back light of the default scene, turned about the vertical).
  const double diag = mesh.bounds().diagonal();
  for (int k = 0; k < 4; ++k) {
    const double a = 2 * optics::kPi * k / 4;
    const glm::dvec3 p = glm::dvec3(std::sin(a), 0.9, -std::cos(a)) * (1.5 * diag);
    render({scene::PointLight{p, glm::dvec3(glm::dot(p, p))}}, scene.medium.material, {"light " + std::to_string(90 * k) + " deg"});
  }
  // 2. The material changes under the default light.
  for (const char* name : {"skin1", "marble", "ketchup", "skimmilk"})
    render(scene.lights, *optics::findMaterial(name), {std::string("material ") + name});
  // 3. The object bends: only geometric weights change (and the shadow-ray surface).
  const std::vector<glm::vec3> rest = scene.mesh.positions;
  for (double curvature : {0.02, 0.04, 0.06, 0.08}) {
    t = Clock::now();
    pipeline.deform([&](const glm::dvec3& p) { return bend(p, curvature); });
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) mesh.positions[v] = glm::vec3(bend(glm::dvec3(rest[v]), curvature));
    caster = std::make_unique<raycast::EmbreeRayCaster>(mesh);
    normals = mesh.vertexNormals();
    Row row{"bend " + std::to_string(int(std::lround(curvature * 1000))) + "/m"};
    row.geometry = since(t);
    render(scene.lights, scene.medium.material, row);
  }

  // The picture: one row per kind of change, 4 frames each.
  const int w = frames[0].width, h = frames[0].height;
  image::Image sheet(4 * w, 3 * h);
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) sheet.at(int(f % 4) * w + x, int(f / 4) * h + y) = frames[f].at(x, y);
  cli::writeImage((outDir / "frames.png").string(), sheet, image::ToneMap{});

  std::ofstream csv(outDir / "frames.csv");
  csv << "change,irradiance_s,geometry_s,assemble_s,solve_s,display_s,frame_s\n";
  std::printf("%-22s %10s %10s %10s %10s %10s %10s\n", "change", "irradiance", "geometry", "assemble", "solve",
              "display", "frame");
  for (const Row& r : rows) {
    const double frame = r.irradiance + r.geometry + r.assemble + r.solve + r.display;
    csv << r.change << ',' << r.irradiance << ',' << r.geometry << ',' << r.assemble << ',' << r.solve << ','
        << r.display << ',' << frame << '\n';
    std::printf("%-22s %10.4f %10.4f %10.4f %10.4f %10.4f %10.4f  (%.0fx faster than a rebuild)\n", r.change.c_str(),
                r.irradiance, r.geometry, r.assemble, r.solve, r.display, frame, (buildSeconds + frame) / frame);
  }
  std::printf("wrote %s and %s\n", (outDir / "frames.png").c_str(), (outDir / "frames.csv").c_str());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "quadgraph_runtime_changes: %s\n", e.what());
  return 2;
}
