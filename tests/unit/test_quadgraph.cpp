// The QuadGraph core without TetGen: a box cut into Kuhn tets (6 per cell) is a valid tet mesh
// whose corners and edges give tets with 2 and 3 boundary faces, so the split of Fig. 4 is
// exercised.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <lucent/optics/materials.hpp>
#include <lucent/quadgraph/block_packing.hpp>
#include <lucent/quadgraph/multiresolution.hpp>
#include <lucent/quadgraph/node_surface.hpp>
#include <lucent/reference/diffusion_sphere.hpp>
#include <lucent/scene/voxel_grid.hpp>

using namespace lucent;

namespace {

/// n^3 cells of size h, 6 tets each; boundary faces get source = the box side (0-5).
scene::TetMesh kuhnBox(int n, double h) {
  scene::TetMesh m;
  auto id = [n](int i, int j, int k) { return unsigned((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.positions.push_back(glm::dvec3(i, j, k) * h);
  static const int kPaths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& path : kPaths) {
          glm::ivec3 c(i, j, k);
          glm::uvec4 t;
          t[0] = id(c.x, c.y, c.z);
          for (int s = 0; s < 3; ++s) c[path[s]] += 1, t[s + 1] = id(c.x, c.y, c.z);
          m.tets.push_back(t);
          if (m.volume(m.tets.size() - 1) < 0) std::swap(m.tets.back().z, m.tets.back().w);
        }
  // Boundary faces: faces of exactly one tet.
  std::map<std::array<unsigned, 3>, int> count;
  for (const auto& t : m.tets)
    for (int f = 0; f < 4; ++f) ++count[quadgraph::detail::sortedKey(quadgraph::tetFace(t, f))];
  for (const auto& [key, c] : count)
    if (c == 1) {
      const glm::dvec3 centre =
          (m.positions[key[0]] + m.positions[key[1]] + m.positions[key[2]]) / 3.0;
      std::uint32_t side = 0;
      for (int a = 0; a < 3; ++a) {
        if (centre[a] < 1e-9) side = std::uint32_t(2 * a);
        if (centre[a] > n * h - 1e-9) side = std::uint32_t(2 * a + 1);
      }
      m.boundaryFaces.push_back({key[0], key[1], key[2]});
      m.boundarySource.push_back(side);
    }
  return m;
}

quadgraph::NodeMedium homogeneous(const quadgraph::QuadGraph& g, double sigmaA,
                                  double sigmaSPrime) {
  return quadgraph::sampleMedium(g, [&](const glm::dvec3&) {
    return std::pair<double, double>{sigmaA, sigmaSPrime};
  });
}

std::vector<double> solveTight(const quadgraph::DiffusionSystem<double>& sys,
                               const std::vector<double>& b) {
  std::vector<double> phi(sys.nodeCount, 0.0);
  quadgraph::SolveOptions o;
  o.tolerance = 1e-12;
  quadgraph::solveConjugateGradient(sys, b, phi, o);
  return phi;
}

/// |sum_s b_s (Q_s - phi_s)| / sum_s b_s Q_s: what enters minus what leaves, relative; 0 when mu =
/// 0.
double energyImbalance(const quadgraph::DiffusionSystem<double>& sys, const std::vector<double>& q,
                       const std::vector<double>& phi) {
  double inflow = 0, balance = 0;
  for (std::size_t s = 0; s < q.size(); ++s) {
    const double rs = sys.robin[sys.innerCount + s];
    inflow += rs * sys.sourceScale * q[s];
    balance += rs * (sys.sourceScale * q[s] - phi[sys.innerCount + s]);
  }
  return std::abs(balance) / inflow;
}

}  // namespace

TEST_CASE(
    "QuadGraph of a box: every tet keeps at most one boundary face, inner nodes have 4 "
    "neighbours") {
  const auto mesh = kuhnBox(4, 2.5);
  const auto g = quadgraph::buildQuadGraph(mesh);
  CHECK(g.splitParents.size() > 0);  // the box's corner and edge tets were split
  double volume = 0;
  for (std::size_t i = 0; i < g.innerCount(); ++i) {
    REQUIRE(g.cellVolume[i] > 0);
    volume += g.cellVolume[i];
    int surface = 0;
    for (std::uint32_t j : g.neighbours[i]) {
      REQUIRE(j < g.nodeCount());
      if (g.isSurface(j)) {
        ++surface;
        CHECK(g.surfaceInner[j - g.innerCount()] == i);
      } else {
        // Inner links are symmetric.
        const auto& back = g.neighbours[j];
        CHECK(std::count(back.begin(), back.end(), std::uint32_t(i)) == 1);
      }
    }
    CHECK(surface <= 1);
  }
  CHECK(volume == doctest::Approx(1000.0).epsilon(1e-12));
  double area = 0;
  for (std::size_t s = 0; s < g.surfaceCount(); ++s) {
    area += g.faceArea[4 * g.surfaceInner[s] + g.surfaceSlot[s]];
    CHECK(g.surfaceSource[s] < 6);
    const glm::dvec3 p = g.positions[g.innerCount() + s];
    const double toSide = std::min({p.x, p.y, p.z, 10 - p.x, 10 - p.y, 10 - p.z});
    CHECK(toSide == doctest::Approx(0).epsilon(1e-12));  // on the box's surface
  }
  CHECK(area == doctest::Approx(600.0).epsilon(1e-12));
  CHECK(g.minFaceDistanceRatio() > 0);
}

TEST_CASE(
    "Both stencils give a symmetric system, the finite-volume one conserves energy when mu = 0") {
  auto g = quadgraph::buildQuadGraph(kuhnBox(5, 2.0));
  quadgraph::relax(g, 3);
  CHECK(g.minFaceDistanceRatio() > 0);
  // Light on one side only, varying across it: a non-uniform source.
  std::vector<double> q(g.surfaceCount(), 0.0);
  for (std::size_t s = 0; s < q.size(); ++s)
    if (g.surfaceSource[s] == 5) q[s] = 1 + g.positions[g.innerCount() + s].x;
  for (auto stencil : {quadgraph::Stencil::FiniteVolume, quadgraph::Stencil::Paper}) {
    const auto sys = quadgraph::assemble(g, homogeneous(g, 0.0, 1.0), 1.3, stencil);
    std::map<std::pair<std::uint32_t, std::uint32_t>, double> w;
    for (std::size_t i = 0; i < sys.nodeCount; ++i)
      for (int k = 0; k < 4; ++k)
        if (sys.neighbour[4 * i + k] != i)
          w[{std::uint32_t(i), sys.neighbour[4 * i + k]}] = sys.weight[4 * i + k];
    for (const auto& [edge, c] : w)
      CHECK(c == doctest::Approx(w.at({edge.second, edge.first})).epsilon(1e-12));
    CHECK(sys.diagonalDominanceMargin() >=
          -1e-12);  // spectralon-like: Laplace's equation, weakly dominant

    const auto b = sys.rhs(q);
    const auto phi = solveTight(sys, b);
    if (stencil == quadgraph::Stencil::FiniteVolume) {
      // No absorption: what enters leaves. Sum_s b_s (Q_s - phi_s) = 0, and b_s = A_f / (2A) here,
      // so the area-weighted mean of phi over the surface equals that of Q.
      CHECK(energyImbalance(sys, q, phi) < 1e-8);
      // And the radiosity Eq. 7 hands to the renderer carries exactly that light out: sum A B = sum
      // A q. (Eq. 7 as printed, without the transmitted fraction 1 - Fdr, would give 1.8x at
      // eta 1.3.)
      const auto radiosity = quadgraph::surfaceRadiosity(sys, phi, q);
      double in = 0, out = 0;
      for (std::size_t s = 0; s < q.size(); ++s) {
        const double area = g.faceArea[4 * g.surfaceInner[s] + g.surfaceSlot[s]];
        in += area * q[s];
        out += area * radiosity[s];
      }
      CHECK(out == doctest::Approx(in).epsilon(1e-8));
    }
  }
}

TEST_CASE("Jacobi, SOR and CG reach the same solution, the residual bound holds") {
  auto g = quadgraph::buildQuadGraph(kuhnBox(5, 2.0));
  const auto sys = quadgraph::assemble(g, homogeneous(g, 0.05, 1.0), 1.4);
  std::vector<double> q(g.surfaceCount());
  for (std::size_t s = 0; s < q.size(); ++s) q[s] = g.surfaceSource[s] == 2 ? 2.0 : 0.1;
  const auto b = sys.rhs(q);
  const auto exact = solveTight(sys, b);
  CHECK(sys.relativeResidual(exact, b) < 1e-11);
  const auto colours = quadgraph::colourRows(sys);
  CHECK(colours.colourStart.size() - 1 <= 5);  // degree <= 4
  for (std::size_t c = 0; c + 1 < colours.colourStart.size(); ++c)
    for (std::size_t r = colours.colourStart[c]; r < colours.colourStart[c + 1]; ++r) {
      const std::uint32_t i = colours.colourOrder[r];
      for (int k = 0; k < 4; ++k) {
        const std::uint32_t j = sys.neighbour[4 * i + k];
        if (j == i) continue;
        const auto pos = std::find(colours.colourOrder.begin(), colours.colourOrder.end(), j) -
                         colours.colourOrder.begin();
        CHECK_FALSE((std::size_t(pos) >= colours.colourStart[c] &&
                     std::size_t(pos) < colours.colourStart[c + 1]));
      }
    }
  for (auto solver :
       {quadgraph::Solver::Jacobi, quadgraph::Solver::Sor, quadgraph::Solver::ConjugateGradient}) {
    std::vector<double> phi;
    quadgraph::SolveOptions o;
    o.tolerance = 1e-9;
    const auto rep = quadgraph::solve(solver, sys, colours, b, phi, o);
    INFO(quadgraph::solverName(solver) << ": " << rep.iterations << " iterations");
    CHECK(rep.converged);
    CHECK(sys.relativeResidual(phi, b) <= 1e-9 * 1.0001);
    double err = 0, norm = 0;
    for (std::size_t i = 0; i < phi.size(); ++i)
      err += (phi[i] - exact[i]) * (phi[i] - exact[i]), norm += exact[i] * exact[i];
    CHECK(std::sqrt(err / norm) < 1e-6);
  }
}

TEST_CASE(
    "Extreme media stay diagonally dominant and finite: spectralon, dense cream at 100 mm, Coke's "
    "zero scattering") {
  for (const char* name : {"spectralon", "cream", "coke"}) {
    const optics::Material mat = *optics::findMaterial(name);
    for (double size : {0.01, 100.0}) {
      auto g = quadgraph::buildQuadGraph(kuhnBox(4, size / 4));
      for (int c = 0; c < 3; ++c) {
        const auto sys =
            quadgraph::assemble(g, homogeneous(g, mat.sigmaA[c], mat.sigmaSPrime[c]), mat.eta);
        INFO(name << " " << size << " mm channel " << c);
        CHECK(sys.diagonalDominanceMargin() >= -1e-12);
        std::vector<double> q(g.surfaceCount(), 1.0), phi;
        quadgraph::SolveOptions o;
        o.tolerance = 1e-8;
        const auto rep =
            quadgraph::solve(quadgraph::Solver::ConjugateGradient, sys, {}, sys.rhs(q), phi, o);
        CHECK(rep.converged);
        for (double v : phi) REQUIRE(std::isfinite(v));
        std::size_t clamped = 0;
        for (double v : quadgraph::surfaceRadiosity(sys, phi, q, &clamped))
          REQUIRE((std::isfinite(v) && v >= 0));
      }
    }
  }
}

TEST_CASE("Deforming the vertices recomputes the geometry as a rebuild would") {
  auto mesh = kuhnBox(3, 1.0);
  auto g = quadgraph::buildQuadGraph(mesh);
  std::vector<glm::dvec3> moved(mesh.positions.size());
  for (std::size_t v = 0; v < moved.size(); ++v) {
    const glm::dvec3 p = mesh.positions[v];
    moved[v] = glm::dvec3(2 * p.x + 0.1 * p.y * p.y, 1.5 * p.y,
                          p.z + 0.2 * p.x);  // a smooth shear + stretch
  }
  g.deform(moved);
  mesh.positions = moved;
  const auto rebuilt = quadgraph::buildQuadGraph(mesh);
  REQUIRE(rebuilt.nodeCount() == g.nodeCount());
  for (std::size_t n = 0; n < g.innerCount(); ++n)
    CHECK(glm::distance(g.positions[n], rebuilt.positions[n]) < 1e-12);
  for (std::size_t e = 0; e < g.faceArea.size(); ++e)
    CHECK(g.faceArea[e] == doctest::Approx(rebuilt.faceArea[e]).epsilon(1e-12));
  CHECK_THROWS_AS(g.deform({glm::dvec3(0)}), std::invalid_argument);
}

TEST_CASE("Block packing and shuffling renumber the nodes without changing the solution") {
  auto g = quadgraph::buildQuadGraph(kuhnBox(4, 1.0));
  auto solveAt = [](const quadgraph::QuadGraph& graph) {
    const auto sys = quadgraph::assemble(graph, homogeneous(graph, 0.1, 1.0), 1.3);
    std::vector<double> q(graph.surfaceCount());
    for (std::size_t s = 0; s < q.size(); ++s) q[s] = 1 + graph.positions[graph.innerCount() + s].z;
    const auto phi = solveTight(sys, sys.rhs(q));
    std::map<std::tuple<long, long, long>, double>
        byPosition;  // position -> flux, order independent
    for (std::size_t n = 0; n < phi.size(); ++n) {
      const glm::dvec3 p = graph.positions[n] * 1e6;
      byPosition[{std::lround(p.x), std::lround(p.y), std::lround(p.z)}] = phi[n];
    }
    return byPosition;
  };
  const auto before = solveAt(g);
  auto packed = g;
  quadgraph::packBlocks(packed, 4);
  auto shuffled = g;
  quadgraph::shuffleNodes(shuffled, 7);
  for (const auto* other : {&packed, &shuffled}) {
    const auto after = solveAt(*other);
    REQUIRE(after.size() == before.size());
    for (const auto& [key, value] : before)
      CHECK(after.at(key) == doctest::Approx(value).epsilon(1e-9));
  }
}

TEST_CASE("Nearest points and Shepard weights (Eq. 10)") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  std::vector<glm::dvec3> pts(2000);
  for (auto& p : pts) p = {u(rng), u(rng), 0.1 * u(rng)};  // flat cloud: uneven grid cells
  const util::NearestPoints grid(pts);
  for (int trial = 0; trial < 50; ++trial) {
    const glm::dvec3 q(2 * u(rng), 2 * u(rng), u(rng));  // some queries outside the cloud
    auto brute = pts;
    std::vector<std::pair<double, std::uint32_t>> d;
    for (std::uint32_t i = 0; i < pts.size(); ++i) d.push_back({glm::distance(pts[i], q), i});
    std::sort(d.begin(), d.end());
    const auto near = grid.nearest(q, 8);
    REQUIRE(near.size() == 8);
    for (int k = 0; k < 8; ++k) CHECK(near[std::size_t(k)].first == d[std::size_t(k)].second);
  }
  const auto w = util::shepardWeights(pts, {pts[5], glm::dvec3(0.3, 0.2, 0)}, 4);
  CHECK(w.weight[0] == 1.0);  // a coincident point takes that value
  double sum = 0;
  for (int k = 0; k < 4; ++k) sum += w.weight[4 + std::size_t(k)];
  CHECK(sum == doctest::Approx(1.0));
}

TEST_CASE("The analytic diffusion sphere satisfies its ODE and boundary condition") {
  for (double sigmaA : {0.0, 0.002, 0.05, 3.0}) {
    const double R = 10, sigmaS = 1.2, eta = 1.3, q = 2.0;
    const reference::DiffusionSphere s(R, sigmaA, sigmaS, eta, q);
    const double kappa = 1 / (3 * (sigmaA + sigmaS));
    const double Q = 4 * q / (1 - optics::diffuseFresnelReflectance(eta));
    INFO("sigma_a " << sigmaA);
    // kappa (phi'' + 2 phi' / r) = mu phi, by central differences at interior radii.
    for (double r : {2.0, 5.0, 9.0}) {
      const double h = 1e-3;
      const double d1 = (s.flux(r + h) - s.flux(r - h)) / (2 * h);
      const double d2 = (s.flux(r + h) - 2 * s.flux(r) + s.flux(r - h)) / (h * h);
      CHECK(kappa * (d2 + 2 * d1 / r) ==
            doctest::Approx(sigmaA * s.flux(r)).epsilon(1e-4).scale(Q * 1e-6));
    }
    const double h = 1e-5;
    const double dR = (s.flux(R) - s.flux(R - h)) / h;
    CHECK(s.flux(R) + 2 * optics::boundaryMismatch(eta) * kappa * dR ==
          doctest::Approx(Q).epsilon(1e-3));
    if (sigmaA == 0) CHECK(s.flux(3.0) == doctest::Approx(Q).epsilon(1e-12));
    CHECK(std::isfinite(s.flux(0)));
  }
  // Dense and huge: no overflow.
  const reference::DiffusionSphere huge(1000, 5.0, 50.0, 1.3, 1.0);
  CHECK(std::isfinite(huge.flux(0)));
  CHECK(std::isfinite(huge.surfaceRadiosity()));
}

TEST_CASE(
    "A scanned volume as the medium: sigma from a VoxelGrid, energy still conserved, both halves "
    "differ") {
  auto g = quadgraph::buildQuadGraph(kuhnBox(6, 1.0));
  scene::VoxelGrid density;  // 2 x 1 x 1 voxels over the box: left half 1, right half 8 (denser)
  density.dims = {2, 1, 1};
  density.origin = {2.5, 3, 3};
  density.spacing = glm::dvec3(1.0);
  density.values = {1.0f, 8.0f};
  const auto medium = quadgraph::sampleMedium(g, [&](const glm::dvec3& p) {
    const double d = density.sample(p);
    return std::pair<double, double>{0.0,
                                     0.5 * d};  // no absorption: a heterogeneous Laplace problem
  });
  CHECK(*std::max_element(medium.kappa.begin(), medium.kappa.end()) >
        7 * *std::min_element(medium.kappa.begin(), medium.kappa.end()));
  const auto sys = quadgraph::assemble(g, medium, 1.3);
  CHECK(sys.diagonalDominanceMargin() >= -1e-12);
  std::vector<double> q(g.surfaceCount(), 0.0);
  for (std::size_t s = 0; s < q.size(); ++s)
    q[s] = g.surfaceSource[s] == 0 ? 1.0 : 0.0;  // light on x = 0
  const auto phi = solveTight(sys, sys.rhs(q));
  CHECK(energyImbalance(sys, q, phi) < 1e-8);
  for (double v : phi) REQUIRE((std::isfinite(v) && v >= 0));
}

TEST_CASE(
    "Sec. 5.3 display surface: the surface nodes triangulated, closed, outward, genus kept, "
    "follows deform()") {
  auto g = quadgraph::buildQuadGraph(kuhnBox(3, 2.0));
  quadgraph::relax(g, 2);
  const auto surface = quadgraph::triangulateSurfaceNodes(g);
  CHECK(surface.openFans == 0);
  // Euler: F nodes, 2F - 4 triangles for a genus-0 boundary; every edge in exactly two triangles,
  // once in each direction (a closed, consistently oriented 2-manifold).
  const std::size_t nodes = g.surfaceCount();
  CHECK(surface.triangles.size() == 2 * nodes - 4);
  std::map<std::pair<unsigned, unsigned>, int> directed;
  for (const auto& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) {
      REQUIRE(t[k] < nodes);
      ++directed[{t[k], t[(k + 1) % 3]}];
    }
    CHECK((t.x != t.y && t.y != t.z && t.x != t.z));
  }
  for (const auto& [edge, count] : directed) {
    CHECK(count == 1);
    CHECK(directed.count({edge.second, edge.first}) == 1);
  }
  // Outward: the enclosed volume is positive and a little below the box's 216 mm^3 (nodes sit on
  // faces, the dual surface cuts the corners), and every vertex is a node on the box's surface.
  const auto volumeOf = [](const scene::TriangleMesh& m) {
    double v = 0;
    for (const auto& t : m.triangles)
      v += glm::dot(glm::dvec3(m.positions[t.x]),
                    glm::cross(glm::dvec3(m.positions[t.y]), glm::dvec3(m.positions[t.z]))) /
           6;
    return v;
  };
  const auto mesh = surface.mesh(g);
  const double volume = volumeOf(mesh);
  CHECK(volume > 0.8 * 216);
  CHECK(volume < 216);
  // After a deformation (a stretch by 2 along x) the same triangles at the moved nodes enclose
  // twice the volume.
  std::vector<glm::dvec3> moved(g.vertices.begin(),
                                g.vertices.begin() + std::ptrdiff_t(g.inputVertexCount));
  for (auto& p : moved) p.x *= 2;
  g.deform(moved);
  CHECK(volumeOf(surface.mesh(g)) == doctest::Approx(2 * volume).epsilon(1e-9));
}

namespace {
/// A bipyramid over the unit square ABCD (apexes E above, F below) whose two halves split the square
/// along different diagonals, so the flat tet ABCD (zero volume) fills the seam: a sliver as a mesher
/// with exact predicates may leave it. The eight outer faces are the boundary.
scene::TetMesh bipyramidWithFlatTet() {
  scene::TetMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}, {0.5, 0.5, -1}};
  enum { A, B, C, D, E, F };
  // ABDC: the orientation of the sliver with A and C lifted by any epsilon (the seam's top diagonal
  // AC above BD), as exact predicates orient it; its faces then point to the neighbours across them.
  m.tets = {{A, B, C, E}, {A, C, D, E}, {A, B, D, F}, {B, C, D, F}, {A, B, D, C}};
  for (std::size_t t = 0; t + 1 < m.tets.size(); ++t)
    if (m.volume(t) < 0) std::swap(m.tets[t].z, m.tets[t].w);
  m.boundaryFaces = {{A, B, E}, {B, C, E}, {C, D, E}, {D, A, E},
                     {A, B, F}, {B, C, F}, {C, D, F}, {D, A, F}};
  for (std::uint32_t f = 0; f < 8; ++f) m.boundarySource.push_back(f);
  return m;
}
}  // namespace

TEST_CASE(
    "A flat sliver is a node of no volume between its neighbours, the solve stays finite, and an "
    "inside-out tet is refused") {
  scene::TetMesh mesh = bipyramidWithFlatTet();
  CHECK(mesh.volume(4) == 0);
  CHECK_FALSE(mesh.inverted(4));
  const auto g = quadgraph::buildQuadGraph(mesh);
  CHECK(g.innerCount() > 5);  // boundary tets split around their centroids (Fig. 4)
  CHECK(*std::min_element(g.cellVolume.begin(), g.cellVolume.end()) == 0);
  const auto sys = quadgraph::assemble(g, homogeneous(g, 0.1, 1.0), 1.3);
  const std::vector<double> q(g.surfaceCount(), 1.0);
  const auto phi = solveTight(sys, sys.rhs(q));
  for (double v : phi) CHECK((std::isfinite(v) && v > 0));

  std::swap(mesh.tets[0].z, mesh.tets[0].w);  // a tet of volume -1/6 mm^3
  CHECK(mesh.inverted(0));
  CHECK_THROWS_WITH(quadgraph::buildQuadGraph(mesh), doctest::Contains("inside out"));
}
