/// The QuadGraph diffusion method (quadgraph-diffusion) as a CLI method: the knobs, a QuadGraphPipeline
/// built once, one frame (irradiance, per-channel solve, Eq. 7), shown on the input mesh's vertices or on
/// the Sec. 5.3 triangulation of the surface nodes.
/// Timing: "precompute" is everything up to the graph and its transfers (once per mesh); a frame is what
/// a change of light or material redoes (irradiance, assembly, solve, mapping, shading).
#include <chrono>

#include <lucent/quadgraph/surface_mapping.hpp>
#include <lucent/reference/vertex_radiosity.hpp>

#include "../io/vtk_quadgraph.hpp"
#include "../raycast/embree_ray_caster.hpp"
#include "../util/tbb_parallel.hpp"
#include "density_field.hpp"
#include "methods.hpp"
#include "quadgraph_pipeline.hpp"

namespace lucent::render {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

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
      {"medium", "", "heterogeneous medium: the material's sigma_a and sigma_s' times a density, noise:F, "
                     "FILE.vdb[:GRID] or FILE.vti[:ARRAY] (fitted to the bounding box); empty = homogeneous"},
      {"display", "mesh", "mesh (node values mapped to the input mesh's vertices) or nodes (Sec. 5.3: the surface "
                          "nodes triangulated and rendered)"},
      {"vtu", "", "write the finest graph with flux per channel, kappa and mu to this .vtu file"}};
  return {"quadgraph", "QuadGraph: the diffusion equation solved on a tetrahedralization's dual graph (quadgraph-diffusion)",
          knobs, [](const cli::Scene& scene, const Knobs& knobs, bool progress) {
            RenderResult out;
            const auto start = Clock::now();
            QuadGraphOptions options;
            options.levels = knobs.integer("levels", 1, 6);
            options.gradingK = knobs.numberIn("K", 0, 100);
            options.quality = knobs.numberIn("quality", 1.1, 10);
            options.relaxIterations = knobs.integer("relax", 0, 50);
            options.packing = knobs.choice<std::string>("packing", {{"blocks", "blocks"}, {"random", "random"}, {"none", "none"}});
            options.blockSide = std::size_t(knobs.integer("block", 1, 1024));
            options.solver = knobs.choice<quadgraph::Solver>(
                "solver", {{"jacobi", quadgraph::Solver::Jacobi}, {"sor", quadgraph::Solver::Sor},
                           {"cg", quadgraph::Solver::ConjugateGradient}});
            options.stencil = knobs.choice<quadgraph::Stencil>(
                "stencil", {{"fv", quadgraph::Stencil::FiniteVolume}, {"paper", quadgraph::Stencil::Paper}});
            options.solve.tolerance = knobs.numberIn("tolerance", 1e-14, 1);
            options.solve.maxIterations = knobs.integer("iterations", 1, 10000000);
            options.solve.omega = knobs.numberIn("omega", 0.01, 1.99);
            options.environmentStrata = knobs.integer("env-strata", 1, 256);
            const bool showNodes = knobs.choice<bool>("display", {{"mesh", false}, {"nodes", true}});
            const DensityField density = parseDensityField("quadgraph", "medium", knobs.text("medium"), scene.mesh.bounds());
            if (density) out.notes.push_back("medium: " + density.description);
            const optics::Material& material = scene.material;
            const MediumField medium = [&](const glm::dvec3& p, int c) {
              const double d = density ? density.at(p) : 1.0;
              // A density of 0 leaves no medium; keep a trace so the diffusion coefficient stays finite.
              const double scale = std::max(d, 1e-6);
              return std::pair<double, double>{scale * material.sigmaA[c], scale * material.sigmaSPrime[c]};
            };

            // --- precompute: levels, transfers, barycentrics on the input mesh ---
            auto t = Clock::now();
            const QuadGraphPipeline pipeline(scene.mesh, scene.meshName, options, out.notes, progress);
            const quadgraph::QuadGraph& fine = pipeline.finest();
            out.figures["precompute_seconds"] = since(t);
            out.figures["levels"] = double(pipeline.levels().size());
            out.figures["nodes"] = double(fine.nodeCount());
            out.figures["surface_nodes"] = double(fine.surfaceCount());
            out.figures["inner_nodes"] = double(fine.innerCount());
            out.figures["tets"] = double(pipeline.levels().back().tets);
            out.figures["solver_bytes"] = pipeline.solverBytes();

            // --- frame: irradiance at the surface nodes, then every channel solved ---
            t = Clock::now();
            const auto q = pipeline.irradiance(scene.mesh, scene.vertexNormals, scene.lights, *scene.caster, material.eta);
            out.figures["irradiance_seconds"] = since(t);
            QuadGraphFrame frame = pipeline.solve(q, medium, material.eta, progress);
            for (int c = 0; c < 3; ++c) {
              const auto& reports = frame.reports[std::size_t(c)];
              for (std::size_t h = 0; h < reports.size(); ++h) {
                out.figures["iterations_level" + std::to_string(h) + "_" + "rgb"[c]] = reports[h].iterations;
                if (!reports[h].converged)
                  out.notes.push_back("quadgraph: level " + std::to_string(h) + " channel " + "RGB"[c] +
                                      " stopped at the iteration limit with residual " +
                                      std::to_string(reports[h].relativeResidual) + "; raise iterations");
              }
              out.figures[std::string("residual_") + "rgb"[c]] = reports.back().relativeResidual;
            }
            out.figures["assemble_seconds"] = frame.assembleSeconds;
            out.figures["solve_seconds"] = frame.solveSeconds;
            out.figures["negative_exitance_nodes"] = double(frame.clampedNodes);
            if (frame.clampedNodes > 0)
              out.notes.push_back("quadgraph: " + std::to_string(frame.clampedNodes) +
                                  " surface node values had phi < 2q (Eq. 7 negative) and were set to 0: the tets are "
                                  "coarse for this absorption; lower K or refine the mesh");

            // --- frame: shade the input mesh (values mapped to its vertices) or the node surface ---
            t = Clock::now();
            if (showNodes) {
              const scene::TriangleMesh nodeMesh = pipeline.nodeSurface().mesh(fine);
              const raycast::EmbreeRayCaster nodeCaster(nodeMesh);
              const auto normals = nodeMesh.vertexNormals();
              const reference::VertexRadiosity shading(nodeMesh, frame.radiosity, material.eta);
              const auto hits = reference::primaryHits(scene.camera, nodeMesh, normals, nodeCaster, util::tbbFor);
              out.image = reference::renderTruth(shading, scene.camera, hits, util::tbbFor);
              out.figures["display_triangles"] = double(nodeMesh.triangles.size());
            } else {
              std::vector<glm::dvec3> vertexB(scene.mesh.positions.size(), glm::dvec3(0));
              for (int c = 0; c < 3; ++c) {
                std::vector<double> values(frame.radiosity.size());
                for (std::size_t s = 0; s < values.size(); ++s) values[s] = frame.radiosity[s][c];
                const auto v = quadgraph::nodesToVertices(fine, scene.mesh, pipeline.sourceBarycentrics(), values);
                for (std::size_t i = 0; i < v.size(); ++i) vertexB[i][c] = v[i];
              }
              const reference::VertexRadiosity shading(scene.mesh, std::move(vertexB), material.eta);
              const auto hits =
                  reference::primaryHits(scene.camera, scene.mesh, scene.vertexNormals, *scene.caster, util::tbbFor);
              out.image = reference::renderTruth(shading, scene.camera, hits, util::tbbFor);
            }
            out.figures["evaluation_seconds"] = since(t);
            out.figures["frame_seconds"] = out.figures["irradiance_seconds"] + frame.assembleSeconds +
                                           frame.solveSeconds + out.figures["evaluation_seconds"];

            if (const std::string& path = knobs.text("vtu"); !path.empty()) {
              std::map<std::string, std::vector<double>> fields{
                  {"flux_r", frame.flux[0]}, {"flux_g", frame.flux[1]}, {"flux_b", frame.flux[2]},
                  {"kappa_r", frame.kappa[0]}, {"mu_r", frame.mu[0]}};
              io::writeQuadGraphVtu(path, fine, fields);
            }
            out.seconds = since(start);
            return out;
          }};
}

}  // namespace lucent::render
