/// The QuadGraph diffusion method (quadgraph-diffusion): TetGen tetrahedralization graded by K, the graph,
/// multi-resolution levels from decimated surfaces, and the per-frame work: irradiance at the surface
/// nodes, the diffusion solve per colour channel, Eq. 7 at the surface, mapped to the mesh's vertices.
/// Timing: "precompute" is everything up to the graph and its transfers (once per mesh); a frame is what
/// a change of light or material redoes (irradiance, assembly, solve, mapping, shading).
#include <chrono>

#include <lucent/quadgraph/block_packing.hpp>
#include <lucent/quadgraph/multiresolution.hpp>
#include <lucent/quadgraph/surface_mapping.hpp>
#include <lucent/reference/dipole_truth.hpp>

#include "../io/vtk_quadgraph.hpp"
#include "../tetgen/tetrahedralize.hpp"
#include "../util/error.hpp"
#include "../util/progress_bar.hpp"
#include "../util/tbb_parallel.hpp"
#include "methods.hpp"

namespace lucent::render {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// One resolution level: its surface, graph, and (for all but the finest) the map to the next level.
struct Level {
  scene::TriangleMesh surface;
  quadgraph::QuadGraph graph;
  std::size_t tets = 0;
};

/// The finest level is the scene's mesh; each coarser one has about a quarter of the triangles (Sec. 4.3).
std::vector<Level> buildLevels(const cli::Scene& scene, const Knobs& knobs, RenderResult& out, bool progress) {
  const int levels = knobs.integer("levels", 1, 6);
  tetgen::TetOptions tet;
  tet.gradingK = knobs.numberIn("K", 0, 100);
  tet.radiusEdgeRatio = knobs.numberIn("quality", 1.1, 10);
  const int relaxIterations = knobs.integer("relax", 0, 50);
  const std::string packing = knobs.choice<std::string>(
      "packing", {{"blocks", "blocks"}, {"random", "random"}, {"none", "none"}});
  const std::size_t blockSide = std::size_t(knobs.integer("block", 1, 1024));

  std::vector<Level> out_levels;
  util::ProgressBar bar("tetrahedralize + QuadGraph", progress);
  for (int h = 0; h < levels; ++h) {
    Level level;
    const std::size_t target = scene.mesh.triangles.size() >> (2 * h);
    if (h > 0 && target < 64) {
      out.notes.push_back("quadgraph: stopped at " + std::to_string(h) + " levels (a coarser surface would have < 64 triangles)");
      break;
    }
    level.surface = h == 0 ? scene.mesh : io::decimate(scene.mesh, target);
    try {
      tetgen::TetReport report;
      const scene::TetMesh tm = tetgen::tetrahedralize(level.surface, tet, &report);
      level.tets = tm.tets.size();
      if (report.budgetLimited())
        out.notes.push_back("quadgraph: level " + std::to_string(h) + ": TetGen stopped at its point budget (" +
                            std::to_string(report.steinerBudget) + "); the sizes K asks for are not met near the "
                            "smallest surface triangles (remesh the surface more evenly, e.g. vtkQuadricDecimation)");
      level.graph = quadgraph::buildQuadGraph(tm);
    } catch (const std::exception& e) {
      if (h == 0) throw InputError(std::string(e.what()) + " (mesh " + scene.meshName + ")");
      out.notes.push_back("quadgraph: level " + std::to_string(h) + " dropped: its decimated surface failed (" + e.what() +
                          "); using " + std::to_string(h) + " levels");
      break;
    }
    if (relaxIterations > 0) quadgraph::relax(level.graph, relaxIterations);
    if (packing == "blocks") quadgraph::packBlocks(level.graph, blockSide);
    if (packing == "random") quadgraph::shuffleNodes(level.graph);
    out_levels.push_back(std::move(level));
    bar.update(double(h + 1) / levels);
  }
  bar.finish();
  std::reverse(out_levels.begin(), out_levels.end());  // coarsest first
  return out_levels;
}

/// The radiosity B at the mesh's vertices, interpolated over triangles: L = Ft(cos) B / pi.
class VertexRadiosity {
 public:
  VertexRadiosity(const scene::TriangleMesh& mesh, std::vector<glm::dvec3> b, double eta)
      : mMesh(mesh), mB(std::move(b)), mEta(eta) {}
  glm::dvec3 radiance(const reference::ShadingPoint& hit) const {
    const auto& tri = mMesh.triangles[hit.triangle];
    const glm::dvec3 b = (1 - hit.u - hit.v) * mB[tri.x] + hit.u * mB[tri.y] + hit.v * mB[tri.z];
    return b * (optics::fresnelTransmittance(hit.cosOut, mEta) / optics::kPi);
  }

 private:
  const scene::TriangleMesh& mMesh;
  std::vector<glm::dvec3> mB;
  double mEta;
};

double graphBytes(const quadgraph::QuadGraph& g) {
  // What one solve reads per node: 4 neighbour indices + 4 weights + diagonal + rhs + two flux buffers.
  return double(g.nodeCount()) * (4 * 4 + 4 * 8 + 8 + 8 + 2 * 8);
}
}  // namespace

Method quadgraphMethod() {
  std::vector<KnobSpec> knobs{
      {"K", "1", "tet size growth with depth: h(x) = h_surface + K * distance to the surface (Sec. 4.1)"},
      {"levels", "2", "multi-resolution levels (Sec. 4.3): each coarser level has 1/4 of the surface triangles"},
      {"solver", "cg", "jacobi (the paper's Eq. 8-9), sor (multi-colour over-relaxation) or cg (conjugate gradients)"},
      {"tolerance", "1e-4", "stop each level at this relative residual ||b - M phi|| / ||b||"},
      {"iterations", "20000", "most iterations per level"},
      {"omega", "1.6", "SOR relaxation factor in (0, 2)"},
      {"stencil", "fv", "fv (finite-volume face fluxes) or paper (Eq. 5's 1/d^2 weights; see diffusion_system.hpp)"},
      {"relax", "3", "bounded relaxation iterations of the inner nodes toward even spacing"},
      {"quality", "2.0", "TetGen radius-edge bound (-q): smaller = rounder tets, more of them"},
      {"packing", "blocks", "node order: blocks (BFS blocks, Sec. 5.1), random (the paper's baseline) or none"},
      {"block", "32", "block side r (r x r nodes per block)"},
      {"env-strata", "16", "environment light: strata x strata directions per surface node"},
      {"vtu", "", "write the finest graph with flux per channel, kappa and mu to this .vtu file"}};
  return {"quadgraph", "QuadGraph: the diffusion equation solved on a tetrahedralization's dual graph (quadgraph-diffusion)",
          knobs, [](const cli::Scene& scene, const Knobs& knobs, bool progress) {
            RenderResult out;
            const auto start = Clock::now();
            const auto solver = knobs.choice<quadgraph::Solver>(
                "solver", {{"jacobi", quadgraph::Solver::Jacobi}, {"sor", quadgraph::Solver::Sor},
                           {"cg", quadgraph::Solver::ConjugateGradient}});
            const auto stencil = knobs.choice<quadgraph::Stencil>(
                "stencil", {{"fv", quadgraph::Stencil::FiniteVolume}, {"paper", quadgraph::Stencil::Paper}});
            quadgraph::SolveOptions so;
            so.tolerance = knobs.numberIn("tolerance", 1e-14, 1);
            so.maxIterations = knobs.integer("iterations", 1, 10000000);
            so.omega = knobs.numberIn("omega", 0.01, 1.99);
            const int envStrata = knobs.integer("env-strata", 1, 256);

            // --- precompute: levels, transfers, barycentrics on the input mesh ---
            auto t = Clock::now();
            std::vector<Level> levels = buildLevels(scene, knobs, out, progress);
            std::vector<quadgraph::LevelTransfer> transfers;
            for (std::size_t h = 0; h + 1 < levels.size(); ++h)
              transfers.push_back(quadgraph::levelTransfer(levels[h].graph, levels[h + 1].graph));
            const quadgraph::QuadGraph& fine = levels.back().graph;
            // Irradiance is evaluated once, at the finest surface nodes; coarser levels get it by Eq. 10's
            // weights from there (b = 4), so shadow rays never start from a decimated surface.
            std::vector<quadgraph::ShepardWeights> restrictQ(levels.size());
            for (std::size_t h = 0; h + 1 < levels.size(); ++h) {
              const auto& g = levels[h].graph;
              restrictQ[h] = quadgraph::shepardWeights(
                  {fine.positions.begin() + std::ptrdiff_t(fine.innerCount()), fine.positions.end()},
                  {g.positions.begin() + std::ptrdiff_t(g.innerCount()), g.positions.end()}, 4);
            }
            const std::vector<glm::dvec3> bary = quadgraph::sourceBarycentrics(fine, scene.mesh);
            out.figures["precompute_seconds"] = since(t);
            out.figures["levels"] = double(levels.size());
            out.figures["nodes"] = double(fine.nodeCount());
            out.figures["surface_nodes"] = double(fine.surfaceCount());
            out.figures["inner_nodes"] = double(fine.innerCount());
            out.figures["tets"] = double(levels.back().tets);
            double bytes = 0;
            for (const auto& l : levels) bytes += graphBytes(l.graph);
            out.figures["solver_bytes"] = bytes;

            // --- frame: irradiance at the surface nodes ---
            t = Clock::now();
            scene::IrradianceSettings irr;
            irr.eta = scene.material.eta;
            irr.rayEpsilon = 1e-5 * scene.mesh.bounds().diagonal();
            irr.environmentStrata = envStrata;
            std::vector<glm::dvec3> qFine(fine.surfaceCount());
            util::tbbFor(qFine.size(), [&](std::size_t begin, std::size_t end) {
              for (std::size_t s = begin; s < end; ++s) {
                const std::uint32_t tri = fine.surfaceSource[s];
                const glm::dvec3 faceN = glm::normalize(scene.mesh.areaVector(tri));
                const glm::dvec3 n = scene::shadingNormal(scene.mesh, scene.vertexNormals, tri, bary[s]);
                qFine[s] = scene::irradianceAt(fine.positions[fine.innerCount() + s], n, faceN, scene.lights,
                                               *scene.caster, irr, s);
              }
            });
            out.figures["irradiance_seconds"] = since(t);

            // --- frame: per channel, assemble and solve every level, Eq. 7 at the finest surface ---
            t = Clock::now();
            std::vector<glm::dvec3> nodeB(fine.surfaceCount());
            std::vector<std::vector<double>> flux(3), kappa(3), mu(3);
            double assembleSeconds = 0;
            std::size_t clampedTotal = 0;
            util::ProgressBar bar("diffusion solve", progress);
            for (int c = 0; c < 3; ++c) {
              const auto ta = Clock::now();
              const auto field = [&](const glm::dvec3&) {
                return std::pair<double, double>{scene.material.sigmaA[c], scene.material.sigmaSPrime[c]};
              };
              std::vector<quadgraph::DiffusionSystem<double>> systems;
              std::vector<quadgraph::LevelProblem<double>> problems(levels.size());
              std::vector<std::vector<double>> q(levels.size());
              for (std::size_t h = 0; h < levels.size(); ++h) {
                const auto medium = quadgraph::sampleMedium(levels[h].graph, field);
                systems.push_back(quadgraph::assemble<double>(levels[h].graph, medium, scene.material.eta, stencil));
                if (h + 1 == levels.size()) kappa[std::size_t(c)] = medium.kappa, mu[std::size_t(c)] = medium.mu;
              }
              for (std::size_t h = 0; h < levels.size(); ++h) {
                std::vector<double> qc(fine.surfaceCount());
                for (std::size_t s = 0; s < qc.size(); ++s) qc[s] = qFine[s][c];
                if (h + 1 < levels.size()) {
                  std::vector<double> coarse(levels[h].graph.surfaceCount());
                  restrictQ[h].apply(qc.data(), coarse.data(), coarse.size());
                  qc = std::move(coarse);
                }
                q[h] = std::move(qc);
                problems[h].system = &systems[h];
                problems[h].rhs = systems[h].rhs(q[h]);
                if (solver == quadgraph::Solver::Sor) problems[h].colours = quadgraph::colourRows(systems[h]);
              }
              assembleSeconds += since(ta);
              std::vector<double> phi;
              const auto reports = quadgraph::solveMultiresolution(solver, problems, transfers, phi, so, util::tbbFor);
              for (std::size_t h = 0; h < reports.size(); ++h) {
                const std::string key = "iterations_level" + std::to_string(h) + "_" + "rgb"[c];
                out.figures[key] = reports[h].iterations;
                if (!reports[h].converged)
                  out.notes.push_back("quadgraph: level " + std::to_string(h) + " channel " + "RGB"[c] +
                                      " stopped at the iteration limit with residual " +
                                      std::to_string(reports[h].relativeResidual) + "; raise iterations");
              }
              out.figures[std::string("residual_") + "rgb"[c]] = reports.back().relativeResidual;
              std::size_t clamped = 0;
              const auto b = quadgraph::surfaceRadiosity(systems.back(), phi, q.back(), &clamped);
              clampedTotal += clamped;
              for (std::size_t s = 0; s < b.size(); ++s) nodeB[s][c] = b[s];
              flux[std::size_t(c)] = std::move(phi);
              bar.update((c + 1) / 3.0);
            }
            bar.finish();
            out.figures["assemble_seconds"] = assembleSeconds;
            out.figures["solve_seconds"] = since(t) - assembleSeconds;
            out.figures["negative_exitance_nodes"] = double(clampedTotal);
            if (clampedTotal > 0)
              out.notes.push_back("quadgraph: " + std::to_string(clampedTotal) +
                                  " surface node values had phi < 2q (Eq. 7 negative) and were set to 0: the tets are "
                                  "coarse for this absorption; lower K or refine the mesh");

            // --- frame: map to vertices and shade ---
            t = Clock::now();
            std::vector<glm::dvec3> vertexB(scene.mesh.positions.size(), glm::dvec3(0));
            for (int c = 0; c < 3; ++c) {
              std::vector<double> values(nodeB.size());
              for (std::size_t s = 0; s < values.size(); ++s) values[s] = nodeB[s][c];
              const auto v = quadgraph::nodesToVertices(fine, scene.mesh, bary, values);
              for (std::size_t i = 0; i < v.size(); ++i) vertexB[i][c] = v[i];
            }
            const VertexRadiosity shading(scene.mesh, std::move(vertexB), scene.material.eta);
            const auto hits =
                reference::primaryHits(scene.camera, scene.mesh, scene.vertexNormals, *scene.caster, util::tbbFor);
            out.image = reference::renderTruth(shading, scene.camera, hits, util::tbbFor);
            out.figures["evaluation_seconds"] = since(t);
            out.figures["frame_seconds"] = out.figures["irradiance_seconds"] + assembleSeconds +
                                           out.figures["solve_seconds"] + out.figures["evaluation_seconds"];

            if (const std::string& path = knobs.text("vtu"); !path.empty()) {
              std::map<std::string, std::vector<double>> fields{{"flux_r", flux[0]}, {"flux_g", flux[1]},
                                                                {"flux_b", flux[2]}, {"kappa_r", kappa[0]},
                                                                {"mu_r", mu[0]}};
              io::writeQuadGraphVtu(path, fine, fields);
            }
            out.seconds = since(start);
            return out;
          }};
}

}  // namespace lucent::render
