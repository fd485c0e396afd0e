#pragma once
/// @file quadgraph_pipeline.hpp
/// @brief QuadGraph split the way the paper runs it (Wang et al. 2010 Sec. 5, Fig. 9): what is
/// built once per mesh (tetrahedralization, graph, levels, transfers), and what a frame redoes when
/// the light, the material or the shape changes (irradiance at the surface nodes, assembly, the
/// solve, Eq. 7). Nothing in a frame rebuilds the tets: a new material reassembles, a deformation
/// recomputes geometric weights only.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <lucent/quadgraph/diffusion_system.hpp>
#include <lucent/quadgraph/multiresolution.hpp>
#include <lucent/quadgraph/node_surface.hpp>
#include <lucent/quadgraph/solvers.hpp>
#include <lucent/scene/irradiance.hpp>
#include <lucent/scene/light.hpp>
#include <lucent/scene/ray_caster.hpp>

namespace lucent::render {

struct QuadGraphOptions {
  int levels = 2;
  double gradingK = 1;
  double quality = 2.0;
  int relaxIterations = 3;
  std::string packing = "blocks";  ///< blocks | random | none
  std::size_t blockSide = 32;
  quadgraph::Stencil stencil = quadgraph::Stencil::FiniteVolume;
  quadgraph::Solver solver = quadgraph::Solver::ConjugateGradient;
  quadgraph::SolveOptions solve;
  int environmentStrata = 16;
  /// The finest level's surface: the input decimated to this many triangles (VTK's quadric
  /// decimation; 0 or more than the input's: the input as is). Irradiance and display then pass
  /// between the input mesh and the graph's surface nodes (QuadGraphPipeline::irradiance,
  /// toInputVertices).
  std::size_t surfaceTriangles = 0;
};

/// sigma_a and sigma_s' (mm^-1) at a position, for one colour channel.
using MediumField =
    std::function<std::pair<double, double>(const glm::dvec3& position, int channel)>;

struct QuadGraphFrame {
  std::vector<glm::dvec3> radiosity;           ///< B per finest surface node (L = Ft B / pi)
  std::vector<std::vector<double>> flux;       ///< phi per channel, finest level, every node
  std::vector<std::vector<double>> kappa, mu;  ///< per channel, finest level
  std::vector<std::vector<quadgraph::SolveReport>>
      reports;  ///< per channel, per level (coarsest first)
  std::size_t clampedNodes = 0;
  double assembleSeconds = 0, solveSeconds = 0;
};

class QuadGraphPipeline {
 public:
  struct Level {
    quadgraph::QuadGraph graph;
    std::size_t tets = 0;
  };

  /// Tetrahedralizes `mesh` and its decimated levels. A failing finest level throws InputError
  /// naming `meshName`; a failing coarser level is dropped with a note.
  QuadGraphPipeline(const scene::TriangleMesh& mesh, const std::string& meshName,
                    const QuadGraphOptions& options, std::vector<std::string>& notes,
                    bool progress);

  const quadgraph::QuadGraph& finest() const { return mLevels.back().graph; }
  const std::vector<Level>& levels() const { return mLevels; }
  /// Whether the finest level's surface is the input mesh (not decimated).
  bool finestIsInput() const { return mFinestIsInput; }
  /// Triangles of the finest level's surface.
  std::size_t surfaceTriangles() const { return mSurfaceTriangles; }
  /// The Sec. 5.3 display surface over the finest surface nodes (topology fixed; positions follow
  /// deform()).
  const quadgraph::NodeSurface& nodeSurface() const { return mNodeSurface; }

  /// Transmitted irradiance q at the finest surface nodes (Eq. 3), shading normals from the input
  /// mesh. A decimated surface's node takes the area-weighted mean over the input triangles whose
  /// nearest facing node it is (each triangle's power goes to one node), or Eq. 10's weights from
  /// the nearest triangles where none is.
  std::vector<glm::dvec3> irradiance(const scene::TriangleMesh& mesh,
                                     const std::vector<glm::vec3>& vertexNormals,
                                     const std::vector<scene::Light>& lights,
                                     const scene::RayCaster& caster, double eta) const;
  /// Assembles every level for `medium` and solves each channel, coarse to fine (Fig. 9).
  QuadGraphFrame solve(const std::vector<glm::dvec3>& q, const MediumField& medium, double eta,
                       bool progress) const;
  /// Places every level's tet vertices at `map`(their position when built) (a deformation that
  /// keeps tets positively oriented) and recomputes the geometric weights and the level transfers;
  /// topology and node barycentrics stay. The identity map restores the built shape.
  void deform(const std::function<glm::dvec3(const glm::dvec3&)>& map);

  /// Values at the finest surface nodes spread to the input mesh's vertices: by source triangle and
  /// barycentrics when the surface is the input, else by Eq. 10's weights from the 4 nearest nodes.
  std::vector<double> toInputVertices(const scene::TriangleMesh& mesh,
                                      const std::vector<double>& nodeValues) const;

  /// Bytes one solve reads per iteration over all levels (neighbours, weights, diagonal, rhs, two
  /// buffers).
  double solverBytes() const;

 private:
  void computeTransfers();
  /// Level h's graph on `surface`: TetGen with K's grading, relaxation and packing. Throws on
  /// failure.
  Level buildLevel(const scene::TriangleMesh& surface, int h,
                   std::vector<std::string>& notes) const;
  void mapInputMesh(const scene::TriangleMesh& mesh);
  std::vector<glm::dvec3> irradianceOnInput(const scene::TriangleMesh& mesh,
                                            const std::vector<glm::vec3>& vertexNormals,
                                            const std::vector<scene::Light>& lights,
                                            const scene::RayCaster& caster,
                                            const scene::IrradianceSettings& settings) const;

  QuadGraphOptions mOptions;
  std::vector<Level> mLevels;                          ///< coarsest first
  std::vector<std::vector<glm::dvec3>> mRestVertices;  ///< per level: the tet vertices as built
  std::vector<quadgraph::LevelTransfer> mTransfers;
  std::vector<util::ShepardWeights> mRestrictQ;  ///< finest surface nodes -> level h's
  std::vector<glm::dvec3>
      mBary;  ///< finest surface node s on its source triangle (a surface that is the input)
  bool mFinestIsInput = true;
  std::size_t mSurfaceTriangles = 0;
  std::vector<std::uint32_t>
      mTriangleNode;  ///< decimated: each input triangle's nearest surface node
  util::ShepardWeights
      mNodeFromTriangles;                      ///< decimated: for a node no triangle is nearest to
  util::ShepardWeights mVertexFromNodes;  ///< decimated: input vertices from the surface nodes
  quadgraph::NodeSurface mNodeSurface;
};

}  // namespace lucent::render
