#include "quadgraph_pipeline.hpp"

#include <algorithm>
#include <chrono>

#include <lucent/quadgraph/block_packing.hpp>
#include <lucent/quadgraph/surface_mapping.hpp>
#include <lucent/scene/irradiance.hpp>
#include <lucent/util/nearest_points.hpp>

#include "../io/vtk_quadgraph.hpp"
#include "../tetgen/tetrahedralize.hpp"
#include "../util/error.hpp"
#include "../util/progress_bar.hpp"
#include "../util/tbb_parallel.hpp"

namespace lucent::render {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::vector<glm::dvec3> surfacePositions(const quadgraph::QuadGraph& g) {
  return {g.positions.begin() + std::ptrdiff_t(g.innerCount()), g.positions.end()};
}

glm::dvec3 centroid(const scene::TriangleMesh& mesh, std::size_t t) {
  const glm::uvec3 v = mesh.triangles[t];
  return (glm::dvec3(mesh.positions[v.x]) + glm::dvec3(mesh.positions[v.y]) +
          glm::dvec3(mesh.positions[v.z])) /
         3.0;
}
}  // namespace

QuadGraphPipeline::Level QuadGraphPipeline::buildLevel(const scene::TriangleMesh& surface, int h,
                                                       std::vector<std::string>& notes) const {
  tetgen::TetOptions tet;
  tet.gradingK = mOptions.gradingK;
  tet.radiusEdgeRatio = mOptions.quality;
  tetgen::TetReport report;
  const scene::TetMesh tm = tetgen::tetrahedralize(surface, tet, &report);
  Level level;
  level.tets = tm.tets.size();
  if (report.budgetLimited())
    notes.push_back(
        "quadgraph: level " + std::to_string(h) + ": TetGen stopped at its point budget (" +
        std::to_string(report.steinerBudget) +
        "); the sizes K asks for are not met near the "
        "smallest surface triangles (remesh the surface more evenly, e.g. vtkQuadricDecimation)");
  level.graph = quadgraph::buildQuadGraph(tm);
  if (mOptions.relaxIterations > 0) quadgraph::relax(level.graph, mOptions.relaxIterations);
  if (mOptions.packing == "blocks") quadgraph::packBlocks(level.graph, mOptions.blockSide);
  if (mOptions.packing == "random") quadgraph::shuffleNodes(level.graph);
  return level;
}

QuadGraphPipeline::QuadGraphPipeline(const scene::TriangleMesh& mesh, const std::string& meshName,
                                     const QuadGraphOptions& options,
                                     std::vector<std::string>& notes, bool progress)
    : mOptions(options) {
  util::ProgressBar bar("tetrahedralize + QuadGraph", progress);
  const std::size_t finestTarget = options.surfaceTriangles > 0
                                       ? std::min(options.surfaceTriangles, mesh.triangles.size())
                                       : mesh.triangles.size();
  mFinestIsInput = finestTarget == mesh.triangles.size();
  scene::TriangleMesh previous;  // the last decimated level's surface
  if (!mFinestIsInput) {
    try {  // quadric decimation can make a thin part intersect itself: then the mesh as it is
      previous = io::decimate(mesh, finestTarget);
      mLevels.push_back(buildLevel(previous, 0, notes));
    } catch (const std::exception& e) {
      notes.push_back("quadgraph: the mesh decimated to " + std::to_string(finestTarget) +
                      " triangles failed (" + e.what() +
                      "); the graph is built on the mesh as it is (surface-triangles=0)");
      mFinestIsInput = true, previous = {};
    }
  }
  if (mFinestIsInput) {
    try {
      mLevels.push_back(buildLevel(mesh, 0, notes));
    } catch (const std::exception& e) {
      throw InputError(std::string(e.what()) + " (mesh " + meshName + ")");
    }
  }
  mSurfaceTriangles = mFinestIsInput ? mesh.triangles.size() : previous.triangles.size();
  bar.update(1.0 / options.levels);
  for (int h = 1; h < options.levels; ++h) {
    // Each coarser level has about a quarter of the triangles (Sec. 4.3), decimated from the one
    // before (a decimation of 167k contour triangles costs seconds).
    const std::size_t target = finestTarget >> (2 * h);
    if (target < 64) {
      notes.push_back("quadgraph: stopped at " + std::to_string(h) +
                      " levels (a coarser surface would have < 64 triangles)");
      break;
    }
    try {
      previous = io::decimate(previous.triangles.empty() ? mesh : previous, target);
      mLevels.push_back(buildLevel(previous, h, notes));
    } catch (const std::exception& e) {
      notes.push_back("quadgraph: level " + std::to_string(h) +
                      " dropped: its decimated surface failed (" + e.what() + "); using " +
                      std::to_string(h) + " levels");
      break;
    }
    bar.update(double(h + 1) / options.levels);
  }
  bar.finish();
  std::reverse(mLevels.begin(), mLevels.end());
  for (const auto& level : mLevels)
    mRestVertices.emplace_back(
        level.graph.vertices.begin(),
        level.graph.vertices.begin() + std::ptrdiff_t(level.graph.inputVertexCount));
  computeTransfers();
  if (mFinestIsInput)
    mBary = quadgraph::sourceBarycentrics(finest(), mesh);
  else
    mapInputMesh(mesh);
  mNodeSurface = quadgraph::triangulateSurfaceNodes(finest());
  if (mNodeSurface.openFans > 0)
    notes.push_back("quadgraph: " + std::to_string(mNodeSurface.openFans) +
                    " boundary vertices have an open fan of faces; the node surface "
                    "(display=nodes) has holes there");
}

void QuadGraphPipeline::computeTransfers() {
  mTransfers.clear();
  for (std::size_t h = 0; h + 1 < mLevels.size(); ++h)
    mTransfers.push_back(quadgraph::levelTransfer(mLevels[h].graph, mLevels[h + 1].graph));
  // Irradiance is evaluated once, at the finest surface nodes; coarser levels get it by Eq. 10's
  // weights from there (b = 4), so shadow rays never start from a decimated surface.
  mRestrictQ.assign(mLevels.size(), {});
  for (std::size_t h = 0; h + 1 < mLevels.size(); ++h)
    mRestrictQ[h] = util::shepardWeights(surfacePositions(finest()),
                                              surfacePositions(mLevels[h].graph), 4);
}


void QuadGraphPipeline::mapInputMesh(const scene::TriangleMesh& mesh) {
  const quadgraph::QuadGraph& fine = finest();
  std::vector<glm::dvec3> nodeNormals(fine.surfaceCount());
  for (std::size_t s = 0; s < nodeNormals.size(); ++s) {
    double area = 0;
    fine.faceGeometry(fine.surfaceInner[s], int(fine.surfaceSlot[s]), nodeNormals[s], area);
  }
  const std::vector<glm::dvec3> nodePositions = surfacePositions(fine);
  const util::NearestPoints nodes(nodePositions);
  std::vector<glm::dvec3> centroids(mesh.triangles.size()), faceNormals(mesh.triangles.size());
  for (std::size_t t = 0; t < centroids.size(); ++t)
    centroids[t] = centroid(mesh, t), faceNormals[t] = mesh.areaVector(t);
  mTriangleNode =
      util::facingShepardWeights(nodes, nodeNormals, centroids, faceNormals, 1, util::tbbFor).index;
  mNodeFromTriangles = util::shepardWeights(centroids, nodePositions, 4);
  const std::vector<glm::vec3> vertexNormals = mesh.vertexNormals();
  mVertexFromNodes = util::facingShepardWeights(
      nodes, nodeNormals, {mesh.positions.begin(), mesh.positions.end()},
      {vertexNormals.begin(), vertexNormals.end()}, 4, util::tbbFor);
}

std::vector<glm::dvec3> QuadGraphPipeline::irradianceOnInput(
    const scene::TriangleMesh& mesh, const std::vector<glm::vec3>& vertexNormals,
    const std::vector<scene::Light>& lights, const scene::RayCaster& caster,
    const scene::IrradianceSettings& settings) const {
  std::vector<glm::dvec3> perTriangle(mesh.triangles.size());
  util::tbbFor(perTriangle.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      const auto tri = std::uint32_t(t);
      if (!(mesh.triangleArea(tri) > 0))
        continue;  // no normal, no power: a degenerate input triangle
      const glm::dvec3 faceN = glm::normalize(mesh.areaVector(tri));
      const glm::dvec3 n = scene::shadingNormal(mesh, vertexNormals, tri, glm::dvec3(1.0 / 3.0));
      perTriangle[t] =
          scene::irradianceAt(centroid(mesh, t), n, faceN, lights, caster, settings, t);
    }
  });
  const std::size_t count = finest().surfaceCount();
  std::vector<glm::dvec3> power(count, glm::dvec3(0));
  std::vector<double> area(count, 0.0);
  for (std::size_t t = 0; t < perTriangle.size(); ++t) {
    const double a = mesh.triangleArea(t);
    power[mTriangleNode[t]] += a * perTriangle[t], area[mTriangleNode[t]] += a;
  }
  const util::ShepardWeights& w = mNodeFromTriangles;
  for (std::size_t s = 0; s < count; ++s) {
    if (area[s] > 0) {
      power[s] /= area[s];
      continue;
    }
    for (std::size_t k = 0; k < w.b; ++k)
      power[s] += w.weight[s * w.b + k] * perTriangle[w.index[s * w.b + k]];
  }
  return power;
}

std::vector<double> QuadGraphPipeline::toInputVertices(
    const scene::TriangleMesh& mesh, const std::vector<double>& nodeValues) const {
  if (mFinestIsInput) return quadgraph::nodesToVertices(finest(), mesh, mBary, nodeValues);
  std::vector<double> out(mesh.positions.size());
  mVertexFromNodes.apply(nodeValues.data(), out.data(), out.size());
  return out;
}

std::vector<glm::dvec3> QuadGraphPipeline::irradiance(const scene::TriangleMesh& mesh,
                                                      const std::vector<glm::vec3>& vertexNormals,
                                                      const std::vector<scene::Light>& lights,
                                                      const scene::RayCaster& caster,
                                                      double eta) const {
  const quadgraph::QuadGraph& fine = finest();
  scene::IrradianceSettings irr;
  irr.eta = eta;
  irr.rayEpsilon = 1e-5 * mesh.bounds().diagonal();
  irr.environmentStrata = mOptions.environmentStrata;
  if (!mFinestIsInput) return irradianceOnInput(mesh, vertexNormals, lights, caster, irr);
  std::vector<glm::dvec3> q(fine.surfaceCount());
  util::tbbFor(q.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) {
      const std::uint32_t tri = fine.surfaceSource[s];
      const glm::dvec3 faceN = glm::normalize(mesh.areaVector(tri));
      const glm::dvec3 n = scene::shadingNormal(mesh, vertexNormals, tri, mBary[s]);
      q[s] = scene::irradianceAt(fine.positions[fine.innerCount() + s], n, faceN, lights, caster,
                                 irr, s);
    }
  });
  return q;
}

QuadGraphFrame QuadGraphPipeline::solve(const std::vector<glm::dvec3>& qFine,
                                        const MediumField& medium, double eta,
                                        bool progress) const {
  const quadgraph::QuadGraph& fine = finest();
  QuadGraphFrame out;
  out.radiosity.assign(fine.surfaceCount(), glm::dvec3(0));
  out.flux.resize(3), out.kappa.resize(3), out.mu.resize(3), out.reports.resize(3);
  util::ProgressBar bar("diffusion solve", progress);
  for (int c = 0; c < 3; ++c) {
    const auto ta = Clock::now();
    const auto field = [&](const glm::dvec3& p) { return medium(p, c); };
    std::vector<quadgraph::DiffusionSystem<double>> systems;
    std::vector<quadgraph::LevelProblem<double>> problems(mLevels.size());
    std::vector<std::vector<double>> q(mLevels.size());
    for (std::size_t h = 0; h < mLevels.size(); ++h) {
      const auto nodeMedium = quadgraph::sampleMedium(mLevels[h].graph, field);
      systems.push_back(
          quadgraph::assemble<double>(mLevels[h].graph, nodeMedium, eta, mOptions.stencil));
      if (h + 1 == mLevels.size())
        out.kappa[std::size_t(c)] = nodeMedium.kappa, out.mu[std::size_t(c)] = nodeMedium.mu;
    }
    for (std::size_t h = 0; h < mLevels.size(); ++h) {
      std::vector<double> qc(fine.surfaceCount());
      for (std::size_t s = 0; s < qc.size(); ++s) qc[s] = qFine[s][c];
      if (h + 1 < mLevels.size()) {
        std::vector<double> coarse(mLevels[h].graph.surfaceCount());
        mRestrictQ[h].apply(qc.data(), coarse.data(), coarse.size());
        qc = std::move(coarse);
      }
      q[h] = std::move(qc);
      problems[h].system = &systems[h];
      problems[h].rhs = systems[h].rhs(q[h]);
      if (mOptions.solver == quadgraph::Solver::Sor)
        problems[h].colours = quadgraph::colourRows(systems[h]);
    }
    out.assembleSeconds += since(ta);
    const auto ts = Clock::now();
    std::vector<double> phi;
    out.reports[std::size_t(c)] = quadgraph::solveMultiresolution(
        mOptions.solver, problems, mTransfers, phi, mOptions.solve, util::tbbFor);
    out.solveSeconds += since(ts);
    std::size_t clamped = 0;
    const auto b = quadgraph::surfaceRadiosity(systems.back(), phi, q.back(), &clamped);
    out.clampedNodes += clamped;
    for (std::size_t s = 0; s < b.size(); ++s) out.radiosity[s][c] = b[s];
    out.flux[std::size_t(c)] = std::move(phi);
    bar.update((c + 1) / 3.0);
  }
  bar.finish();
  return out;
}

void QuadGraphPipeline::deform(const std::function<glm::dvec3(const glm::dvec3&)>& map) {
  for (std::size_t h = 0; h < mLevels.size(); ++h) {
    Level& level = mLevels[h];
    const std::vector<glm::dvec3>& rest = mRestVertices[h];
    std::vector<glm::dvec3> moved(rest.size());
    for (std::size_t v = 0; v < rest.size(); ++v) moved[v] = map(rest[v]);
    level.graph.deform(moved);
  }
  computeTransfers();
}

double QuadGraphPipeline::solverBytes() const {
  double bytes = 0;
  for (const auto& l : mLevels)
    bytes += double(l.graph.nodeCount()) * (4 * 4 + 4 * 8 + 8 + 8 + 2 * 8);
  return bytes;
}

}  // namespace lucent::render
