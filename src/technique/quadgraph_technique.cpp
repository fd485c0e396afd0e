/// The QuadGraph diffusion technique (Wang et al. 2010): prepare is a QuadGraphPipeline (TetGen,
/// levels, transfers: once per mesh); a frame is irradiance at the surface nodes, the per-channel
/// solve and Eq. 7, mapped to the requested points or shown on the Sec. 5.3 triangulation of the
/// surface nodes. An adapter (it links the AGPL TetGen target and VTK for the .vtu export),
/// registered by app_registry.cpp.
#include <lucent/reference/vertex_radiosity.hpp>
#include <lucent/technique/technique.hpp>
#include <lucent/technique/validity.hpp>

#include "../io/vtk_quadgraph.hpp"
#include "../render/quadgraph_pipeline.hpp"
#include "techniques.hpp"

namespace lucent::technique {

namespace {

/// The finest surface's triangle budget: the knob, but never so few that the mean edge exceeds one
/// diffusion length of the material (a regular triangle of edge l has area l^2 sqrt(3) / 4), which
/// keeps a decimated surface inside the technique's valid range (edges of at most 2 lengths).
std::size_t surfaceTriangles(const SceneDescription& scene, const KnobValues& knobs) {
  const auto asked = std::size_t(knobs.integer("surface-triangles"));
  if (asked == 0) return 0;
  // At least the 64 triangles a coarser level keeps (multiresolution stops below them).
  const std::size_t budget = std::max<std::size_t>(64, asked);
  const double length = opticalScales(scene.medium.material).shortestDiffusionLength;
  const double needed = scene.mesh.surfaceArea() / (length * length * std::sqrt(3.0) / 4);
  return std::isfinite(needed) ? std::max(budget, std::size_t(std::min(needed, 1e9))) : budget;
}

render::QuadGraphOptions pipelineOptions(const SceneDescription& scene, const KnobValues& knobs) {
  render::QuadGraphOptions o;
  o.surfaceTriangles = surfaceTriangles(scene, knobs);
  o.levels = int(knobs.integer("levels"));
  o.gradingK = knobs.real("K");
  o.quality = knobs.real("quality");
  o.relaxIterations = int(knobs.integer("relax"));
  o.packing = knobs.pick<std::string>(
      "packing", {{"blocks", "blocks"}, {"random", "random"}, {"none", "none"}});
  o.blockSide = std::size_t(knobs.integer("block"));
  o.solver =
      knobs.pick<quadgraph::Solver>("solver", {{"jacobi", quadgraph::Solver::Jacobi},
                                               {"sor", quadgraph::Solver::Sor},
                                               {"cg", quadgraph::Solver::ConjugateGradient}});
  o.stencil = knobs.pick<quadgraph::Stencil>(
      "stencil", {{"fv", quadgraph::Stencil::FiniteVolume}, {"paper", quadgraph::Stencil::Paper}});
  o.solve.tolerance = knobs.real("tolerance");
  o.solve.maxIterations = int(knobs.integer("iterations"));
  o.solve.omega = knobs.real("omega");
  o.environmentStrata = int(knobs.integer("env-strata"));
  return o;
}

/// sigma_a, sigma_s' at a point: the inclusion that contains it, else the object's medium, times
/// its density.
render::MediumField mediumField(const SceneDescription& scene) {
  return [&scene](const glm::dvec3& p, int c) {
    const Medium* m = &scene.medium;
    for (const auto& inc : scene.inclusions)
      if (inc.contains && inc.contains(p)) m = &inc.medium;
    // No medium (a density of 0, a zero coefficient) keeps a trace, so the diffusion coefficient
    // stays finite.
    if (m->coefficients) {
      const Coefficients k = m->coefficients(p);
      const double floor = 1e-6 * (m->material.sigmaA[c] + m->material.sigmaSPrime[c]);
      return std::pair<double, double>{std::max(k.sigmaA[c], 0.0),
                                       std::max(k.sigmaSPrime[c], floor)};
    }
    const double scale = m->density ? std::max(m->density(p), 1e-6) : 1.0;
    return std::pair<double, double>{scale * m->material.sigmaA[c],
                                     scale * m->material.sigmaSPrime[c]};
  };
}

void solveFigures(const render::QuadGraphFrame& frame, Statistics& stats) {
  for (int c = 0; c < 3; ++c) {
    const auto& reports = frame.reports[std::size_t(c)];
    for (std::size_t h = 0; h < reports.size(); ++h) {
      stats.figures["iterations_level" + std::to_string(h) + "_" + "rgb"[c]] =
          reports[h].iterations;
      if (!reports[h].converged)
        stats.warnings.push_back("quadgraph: level " + std::to_string(h) + " channel " + "RGB"[c] +
                                 " stopped at the iteration limit with residual " +
                                 numberText(reports[h].relativeResidual) + "; raise iterations");
    }
    stats.figures[std::string("residual_") + "rgb"[c]] = reports.back().relativeResidual;
  }
  stats.frameSeconds.emplace_back("assemble", frame.assembleSeconds);
  stats.frameSeconds.emplace_back("solve", frame.solveSeconds);
  stats.figures["negative_exitance_nodes"] = double(frame.clampedNodes);
  if (frame.clampedNodes > 0)
    stats.warnings.push_back(
        "quadgraph: " + std::to_string(frame.clampedNodes) +
        " surface node values had phi < 2q (Eq. 7 negative) and were set to 0: the tets are "
        "coarse for this absorption; lower K or refine the mesh");
}

class QuadGraphTechnique final : public Prepared {
 public:
  QuadGraphTechnique(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats)
      : Prepared(knobs), mPipeline(stats.timePrepare("graph", [&] {
          return render::QuadGraphPipeline(scene.mesh, scene.meshName,
                                           pipelineOptions(scene, knobs), stats.warnings,
                                           bool(scene.progress));
        })) {
    const quadgraph::QuadGraph& fine = mPipeline.finest();
    stats.samples = double(fine.nodeCount());
    stats.sampleUnit = "graph nodes";
    stats.bytes = mPipeline.solverBytes();
    stats.figures["levels"] = double(mPipeline.levels().size());
    stats.figures["nodes"] = double(fine.nodeCount());
    stats.figures["surface_nodes"] = double(fine.surfaceCount());
    stats.figures["inner_nodes"] = double(fine.innerCount());
    stats.figures["tets"] = double(mPipeline.levels().back().tets);
    stats.figures["graph_surface_triangles"] = double(mPipeline.surfaceTriangles());
    stats.figures["solver_bytes"] = mPipeline.solverBytes();
  }

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    const double eta = scene.medium.material.eta;
    const auto q = stats.timeFrame("irradiance", [&] {
      return mPipeline.irradiance(scene.mesh, scene.vertexNormals, scene.lights, *scene.caster,
                                  eta);
    });
    scene.checkCancelled();
    const render::QuadGraphFrame frame =
        mPipeline.solve(q, mediumField(scene), eta, bool(scene.progress));
    solveFigures(frame, stats);
    FrameResult out;
    out.radiosity = stats.timeFrame("evaluation", [&] {
      return mKnobs.pick<bool>("display", {{"mesh", false}, {"nodes", true}})
                 ? onNodeSurface(scene, request, frame, stats)
                 : onMesh(scene, request, frame);
    });
    if (const std::string& path = mKnobs.text("vtu"); !path.empty())
      io::writeQuadGraphVtu(path, mPipeline.finest(),
                            {{"flux_r", frame.flux[0]},
                             {"flux_g", frame.flux[1]},
                             {"flux_b", frame.flux[2]},
                             {"kappa_r", frame.kappa[0]},
                             {"mu_r", frame.mu[0]}});
    return out;
  }

 private:
  /// Node values mapped to the input mesh's vertices, interpolated at the points.
  std::vector<glm::dvec3> onMesh(const SceneDescription& scene, const ShadeRequest& request,
                                 const render::QuadGraphFrame& frame) const {
    std::vector<glm::dvec3> vertexB(scene.mesh.positions.size(), glm::dvec3(0));
    for (int c = 0; c < 3; ++c) {
      std::vector<double> values(frame.radiosity.size());
      for (std::size_t s = 0; s < values.size(); ++s) values[s] = frame.radiosity[s][c];
      const auto v = mPipeline.toInputVertices(scene.mesh, values);
      for (std::size_t i = 0; i < v.size(); ++i) vertexB[i][c] = v[i];
    }
    std::vector<glm::dvec3> b(request.points.size());
    for (std::size_t i = 0; i < b.size(); ++i)
      b[i] = reference::interpolateAtHit(scene.mesh, vertexB, request.points[i]);
    return b;
  }

  /// Sec. 5.3: the surface nodes triangulated; each pixel's camera ray shades the node surface it
  /// meets.
  std::vector<glm::dvec3> onNodeSurface(const SceneDescription& scene, const ShadeRequest& request,
                                        const render::QuadGraphFrame& frame,
                                        Statistics& stats) const {
    if (!request.camera)
      throw RequestError(
          "technique 'quadgraph' knob display=nodes shows the node surface through a camera; "
          "use display=mesh for per-vertex output");
    const scene::TriangleMesh nodeMesh = mPipeline.nodeSurface().mesh(mPipeline.finest());
    const auto caster = scene.makeRayCaster(nodeMesh);
    stats.figures["display_triangles"] = double(nodeMesh.triangles.size());
    // Where a pixel's ray misses the (inscribed) node surface, the value mapped to the mesh stands
    // in.
    std::vector<glm::dvec3> b = onMesh(scene, request, frame);
    for (std::size_t i = 0; i < b.size(); ++i) {
      const std::size_t pixel = request.pixels[i];
      const scene::Ray ray =
          request.camera->primaryRay(double(pixel % std::size_t(request.camera->width)),
                                     double(pixel / std::size_t(request.camera->width)));
      if (const auto hit = caster->intersect(ray.origin, ray.direction, 0,
                                             std::numeric_limits<double>::infinity())) {
        reference::ShadingPoint p;
        p.triangle = hit->triangle, p.u = hit->u, p.v = hit->v;
        b[i] = reference::interpolateAtHit(nodeMesh, frame.radiosity, p);
      }
    }
    return b;
  }

  render::QuadGraphPipeline mPipeline;
};

}  // namespace

Technique quadgraphTechnique() {
  Technique t;
  t.name = "quadgraph";
  t.summary =
      "QuadGraph: the diffusion equation solved on a tetrahedralization's dual graph "
      "(Wang et al. 2010)";
  t.paper =
      "Wang et al. 2010, Eq. 1-2 (diffusion), Eq. 5-9 (graph stencil and relaxation), Eq. 7 "
      "(exitance), Sec. 4.3";
  t.requiredLibrary = "TetGen (AGPL-3.0, src/tetgen)";
  const Phase P = Phase::Prepare;
  t.knobs = {
      KnobSpec::real(
          "K", "1", 0, 100, "",
          "tet size growth with depth: h(x) = h_surface + K * distance to the surface (Sec. 4.1)",
          P),
      KnobSpec::integer(
          "surface-triangles", 20000, 0, 100000000,
          "the finest graph's surface: the mesh decimated to this many triangles (VTK's quadric "
          "decimation; at least 64; never coarser than one diffusion length per edge), irradiance "
          "and exitance "
          "passed between it and the mesh; 0 = the mesh as it is (contoured meshes' sliver "
          "triangles make TetGen slow)",
          P),
      KnobSpec::integer(
          "levels", 2, 1, 6,
          "multi-resolution levels (Sec. 4.3): each coarser level has 1/4 of the surface triangles",
          P),
      KnobSpec::choice("solver", {"jacobi", "sor", "cg"},
                       "jacobi (the paper's Eq. 8-9), sor (multi-colour over-relaxation) or cg "
                       "(conjugate gradients)",
                       P, "cg"),
      KnobSpec::real("tolerance", "1e-4", 1e-14, 1, "",
                     "stop each level at this relative residual ||b - M phi|| / ||b||", P),
      KnobSpec::integer("iterations", 20000, 1, 10000000, "most iterations per level", P),
      KnobSpec::real("omega", "1.6", 0.01, 1.99, "", "SOR relaxation factor in (0, 2)", P),
      KnobSpec::choice("stencil", {"fv", "paper"},
                       "fv (finite-volume face fluxes) or paper (Eq. 5's 1/d^2 weights; see "
                       "diffusion_system.hpp)",
                       P),
      KnobSpec::integer("relax", 3, 0, 50,
                        "bounded relaxation iterations of the inner nodes toward even spacing", P),
      KnobSpec::real("quality", "2.0", 1.1, 10, "",
                     "TetGen radius-edge bound (-q): smaller = rounder tets, more of them", P),
      KnobSpec::choice(
          "packing", {"blocks", "random", "none"},
          "node order: blocks (BFS blocks, Sec. 5.1), random (the paper's baseline) or none", P),
      KnobSpec::integer("block", 32, 1, 1024, "block side r (r x r nodes per block)", P),
      detail::envStrataKnob("surface node", P),
      KnobSpec::choice("display", {"mesh", "nodes"},
                       "mesh (node values mapped to the input mesh's vertices) or nodes (Sec. 5.3: "
                       "the surface nodes triangulated and rendered)"),
      KnobSpec::outputFile(
          "vtu", ".vtu",
          "write the finest graph with flux per channel, kappa and mu to this .vtu file")};
  Capabilities& c = t.capabilities;
  c.heterogeneousMedia = c.inclusions = true;
  c.dynamicShape = true;
  c.precomputeScaling = "TetGen: O(tets log tets); graph and transfers O(nodes)";
  c.frameScaling = "O(nodes x iterations) per channel";
  t.defaultSweep = {{"K", {"2", "1", "0.5"}}};
  t.quickKnobs = {{"levels", "1"}, {"env-strata", "4"}};
  t.model = "diffusion";
  t.validRange = validity::thickRange() +
                 ", a reduced albedo of at least 0.5 in every channel that scatters, and mesh "
                 "edges (the surface nodes' spacing) of at most 2 diffusion lengths 1/sigma_tr of "
                 "the base material";
  t.validity = [](const SceneDescription& scene, const KnobValues&) {
    const std::string thick = validity::opticallyThick(scene.mesh, scene.medium.material);
    if (!thick.empty()) return thick;
    // Measured on a fine sphere (edges 0.015 mm) of espresso (albedo 0.13) under a uniform sky:
    // 4-9 times the dipole; the graph's exitance (Eq. 7) does not hold where absorption rules.
    const optics::Material& m = scene.medium.material;
    for (int c = 0; c < 3; ++c)
      if (m.sigmaSPrime[c] > 0 && m.sigmaSPrime[c] < m.sigmaA[c])
        return "channel " + std::to_string(c) + " has a reduced albedo of " +
               numberText(m.sigmaSPrime[c] / (m.sigmaA[c] + m.sigmaSPrime[c])) +
               ", below 0.5: absorption rules and the graph's exitance (Eq. 7) comes out several "
               "times too bright; use reference or pathtrace";
    const double edge = meanEdgeLength(scene.mesh);
    const double length = opticalScales(scene.medium.material).shortestDiffusionLength;
    if (edge <= 2 * length) return std::string();
    // Coarse tets smear the absorption near the surface: a low-albedo material came out up to
    // 90 times too bright (tests/integration/test_hard_cases.cpp).
    return "the mesh's mean edge is " + lengthText(edge) + ", more than 2 diffusion lengths (" +
           lengthText(length) +
           "): the graph does not resolve the absorption and the image comes out too bright; "
           "subdivide the mesh (e.g. vtkLinearSubdivisionFilter) to edges below " +
           lengthText(2 * length) + ", or use reference";
  };
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    return std::make_unique<QuadGraphTechnique>(scene, knobs, stats);
  };
  return t;
}

}  // namespace lucent::technique
