// QuadGraph accuracy and cost, measured in one run (docs/accuracy/quadgraph.md):
//  1. a ~100k-node graph: preprocessing time, memory, time per iteration, iterations and time to 1 % error
//     against the exact (Eigen) solve per solver, with and without multi-resolution;
//  2. one Jacobi iteration's bandwidth against a STREAM-like copy, for node orders none/random/blocks
//     (Sec. 5.1's packing speed-up), in double and float;
//  3. sweeps written as CSV + PNG: K against the analytic sphere (physical error of the discretization),
//     tolerance per solver against the exact solve (solver error).
// Usage: quadgraph_bench OUT_DIR   (about 5 minutes on 2 cores)
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include <lucent/quadgraph/block_packing.hpp>
#include <lucent/quadgraph/multiresolution.hpp>
#include <lucent/reference/diffusion_sphere.hpp>
#include <lucent/scene/shapes.hpp>

#include "plot/line_chart.hpp"
#include "quadgraph/exact_solve.hpp"
#include "tetgen/tetrahedralize.hpp"
#include "util/tbb_parallel.hpp"

using namespace lucent;
using Clock = std::chrono::steady_clock;

namespace {
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
double peakMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

// skin1, red channel (Jensen 2001), a 20 mm sphere lit from +z: the running example.
constexpr double kSigmaA = 0.032, kSigmaS = 0.74, kEta = 1.3, kRadius = 10;

quadgraph::NodeMedium skin(const quadgraph::QuadGraph& g) {
  return quadgraph::sampleMedium(g, [](const glm::dvec3&) { return std::pair<double, double>{kSigmaA, kSigmaS}; });
}
std::vector<double> lightFromZ(const quadgraph::QuadGraph& g) {
  std::vector<double> q(g.surfaceCount());
  for (std::size_t s = 0; s < q.size(); ++s) q[s] = std::max(0.0, g.positions[g.innerCount() + s].z / kRadius);
  return q;
}
template <class T>
double relErr(const std::vector<T>& a, const std::vector<double>& b) {
  double e = 0, n = 0;
  for (std::size_t i = 0; i < b.size(); ++i) e += (double(a[i]) - b[i]) * (double(a[i]) - b[i]), n += b[i] * b[i];
  return std::sqrt(e / n);
}

quadgraph::QuadGraph buildGraph(int sphereLevel, double K, double* seconds = nullptr, std::size_t* tets = nullptr) {
  const auto t = Clock::now();
  tetgen::TetOptions o;
  o.gradingK = K;
  const auto tm = tetgen::tetrahedralize(scene::shapes::sphere(kRadius, sphereLevel), o);
  auto g = quadgraph::buildQuadGraph(tm);
  quadgraph::relax(g, 3);
  quadgraph::packBlocks(g);
  if (seconds) *seconds = since(t);
  if (tets) *tets = tm.tets.size();
  return g;
}

/// Fresh runs of `run(phi, n)` (n iterations from the start guess) with n growing by 10 % until the error
/// vs exact is <= target; returns {n, seconds of that run}. Fresh runs, not chunks: restarting CG every
/// few iterations would measure a weaker method.
std::pair<int, double> timeToError(const std::function<void(std::vector<double>&, int)>& run,
                                   const std::vector<double>& exact, double target, int limit) {
  for (int n = 5; n <= limit; n = std::max(n + 5, int(n * 1.1))) {
    std::vector<double> phi;
    const auto t = Clock::now();
    run(phi, n);
    const double seconds = since(t);
    if (relErr(phi, exact) <= target) return {n, seconds};
  }
  return {-1, 0.0};
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: quadgraph_bench OUT_DIR\n");
    return 2;
  }
  const std::string out = argv[1];
  const auto par = util::tbbFor;

  // ---------------- 1. the ~100k-node graph ----------------
  double prepSeconds = 0;
  std::size_t tets = 0;
  const double memBefore = peakMiB();
  const quadgraph::QuadGraph g = buildGraph(4, 0.07, &prepSeconds, &tets);
  const auto sys = quadgraph::assemble<double>(g, skin(g), kEta);
  const auto b = sys.rhs(lightFromZ(g));
  std::printf("# ~100k-node graph: 20 mm sphere (5120 triangles), K = 0.07\n");
  std::printf("nodes %zu (inner %zu, surface %zu), tets %zu\n", g.nodeCount(), g.innerCount(), g.surfaceCount(), tets);
  std::printf("preprocessing (TetGen + graph + relax + packing): %.2f s, peak RSS growth %.0f MiB\n", prepSeconds,
              peakMiB() - memBefore);
  const double solverBytes = double(sys.nodeCount) * (4 * 4 + 4 * 8 + 8 + 8 + 2 * 8);
  std::printf("solver arrays (double): %.1f MiB\n", solverBytes / 1048576.0);
  auto t = Clock::now();
  const auto exact = quadgraph::exactSolve(sys, b);
  std::printf("exact solve (Eigen SimplicialLDLT): %.2f s, residual %.1e\n", since(t), sys.relativeResidual(exact, b));

  // Iterations and time to 1 % error, per solver; multi-resolution from a coarser sphere (1280 triangles).
  const quadgraph::QuadGraph gc = buildGraph(3, 0.07);
  const auto sysC = quadgraph::assemble<double>(gc, skin(gc), kEta);
  const auto bC = sysC.rhs(lightFromZ(gc));
  const auto transfer = quadgraph::levelTransfer(gc, g);
  const auto colours = quadgraph::colourRows(sys), coloursC = quadgraph::colourRows(sysC);
  std::printf("\n| solver | levels | iterations to 1%% | time to 1%% (s) | time per iteration (ms) |\n|---|---|---|---|---|\n");
  for (auto solver : {quadgraph::Solver::Jacobi, quadgraph::Solver::Sor, quadgraph::Solver::ConjugateGradient}) {
    for (int levels : {1, 2}) {
      quadgraph::SolveOptions o;
      o.tolerance = 0;  // run exactly `step` iterations per call
      double coarseSeconds = 0;
      std::vector<double> start(sys.nodeCount, 0.0);
      if (levels == 2) {
        // The coarse level to 1e-3 residual, then resampled (Eq. 10): its time counts.
        const auto tc = Clock::now();
        std::vector<double> phiC;
        quadgraph::SolveOptions oc;
        oc.tolerance = 1e-3;
        quadgraph::solve(solver, sysC, coloursC, bC, phiC, oc, par);
        start = quadgraph::prolong(transfer, sysC, phiC, sys);
        coarseSeconds = since(tc);
      }
      const auto [its, secs] = timeToError(
          [&](std::vector<double>& phi, int n) {
            phi = start;
            quadgraph::SolveOptions s = o;
            s.maxIterations = n;
            s.residualEvery = n;
            quadgraph::solve(solver, sys, colours, b, phi, s, par);
          },
          exact, 0.01, 200000);
      std::printf("| %s | %d | %d | %.3f | %.3f |\n", quadgraph::solverName(solver), levels, its, secs + coarseSeconds,
                  its > 0 ? 1000 * secs / its : 0.0);
    }
  }

  // ---------------- 2. bandwidth and packing ----------------
  std::printf("\n| node order | precision | Jacobi iteration (ms) | bytes/iteration (MiB) | GB/s | vs STREAM copy |\n|---|---|---|---|---|---|\n");
  auto copyBandwidth = [&](std::size_t bytes) {
    std::vector<double> a(bytes / 8, 1.0), c(bytes / 8, 0.0);
    double best = 1e30;
    for (int r = 0; r < 20; ++r) {
      const auto tc = Clock::now();
      par(a.size(), [&](std::size_t begin, std::size_t end) { std::copy(a.begin() + long(begin), a.begin() + long(end), c.begin() + long(begin)); });
      best = std::min(best, since(tc));
    }
    return 2.0 * double(a.size()) * 8 / best / 1e9;  // read + write
  };
  double copy = 0;
  tetgen::TetOptions o;
  o.gradingK = 0.07;
  const auto rawMesh = tetgen::tetrahedralize(scene::shapes::sphere(kRadius, 4), o);
  for (const std::string order : {"none", "random", "blocks"}) {
    auto go = quadgraph::buildQuadGraph(rawMesh);
    if (order == "random") quadgraph::shuffleNodes(go);
    if (order == "blocks") quadgraph::packBlocks(go);
    auto timeJacobi = [&](auto zero) {
      using T = decltype(zero);
      const auto s = quadgraph::assemble<T>(go, skin(go), kEta);
      const auto bb = s.rhs(lightFromZ(go));
      std::vector<T> phi(s.nodeCount, T(0)), next(s.nodeCount);
      for (int w = 0; w < 5; ++w) quadgraph::jacobiSweep(s, bb, phi, next, par), phi.swap(next);
      const int reps = 200;
      const auto tj = Clock::now();
      for (int r = 0; r < reps; ++r) quadgraph::jacobiSweep(s, bb, phi, next, par), phi.swap(next);
      const double per = since(tj) / reps;
      // Streamed per node: 4 indices, 4 weights, diagonal, rhs, the new value; gathered: 4 neighbour values
      // (counted once each, the best case of a perfect cache).
      const double bytes = double(s.nodeCount) * (4 * 4 + 4 * sizeof(T) + 3 * sizeof(T) + 4 * sizeof(T));
      if (copy == 0) copy = copyBandwidth(std::size_t(bytes));
      std::printf("| %s | %s | %.3f | %.1f | %.2f | %.2f |\n", order.c_str(), sizeof(T) == 8 ? "double" : "float",
                  1000 * per, bytes / 1048576.0, bytes / per / 1e9, bytes / per / 1e9 / copy);
      return per;
    };
    timeJacobi(double(0));
    timeJacobi(float(0));
  }
  std::printf("STREAM-like copy of the same bytes (TBB, in cache like the iteration): %.2f GB/s; of 512 MiB (DRAM): %.2f GB/s\n",
              copy, copyBandwidth(std::size_t(512) << 20));

  // ---------------- 3. sweeps ----------------
  // K against the analytic sphere (uniform light): B error at the surface nodes and the solve time.
  {
    std::ofstream csv(out + "/quadgraph-K.csv");
    csv << "K,nodes,B_rel_rms,phi_inner_rel_rms,prep_seconds,solve_seconds\n";
    plot::Series err{"B error vs analytic (fv)", {}, {}}, errPaper{"B error vs analytic (paper stencil)", {}, {}};
    errPaper.rgb[0] = 214, errPaper.rgb[1] = 39, errPaper.rgb[2] = 40;
    const reference::DiffusionSphere exactSphere(kRadius, kSigmaA, kSigmaS, kEta, 1.0);
    std::printf("\n| K | nodes | B rel. RMS (fv) | B rel. RMS (paper) | prep (s) | cg solve to 1e-6 (s) |\n|---|---|---|---|---|---|\n");
    for (double K : {2.0, 1.0, 0.5, 0.3, 0.1, 0.0}) {
      double prep = 0;
      const auto gk = buildGraph(4, K, &prep);
      double errs[2] = {0, 0}, innerErr = 0, solveSeconds = 0;
      for (int st = 0; st < 2; ++st) {
        const auto sk = quadgraph::assemble<double>(gk, skin(gk), kEta, st ? quadgraph::Stencil::Paper : quadgraph::Stencil::FiniteVolume);
        const std::vector<double> q(gk.surfaceCount(), 1.0);
        std::vector<double> phi;
        quadgraph::SolveOptions so;
        so.tolerance = 1e-6;
        const auto ts = Clock::now();
        quadgraph::solve(quadgraph::Solver::ConjugateGradient, sk, {}, sk.rhs(q), phi, so, par);
        if (st == 0) solveSeconds = since(ts);
        const auto bs = quadgraph::surfaceRadiosity(sk, phi, q);
        errs[st] = relErr(bs, std::vector<double>(bs.size(), exactSphere.surfaceRadiosity()));
        if (st == 0) {
          std::vector<double> ex;
          for (std::size_t i = 0; i < gk.innerCount(); ++i) ex.push_back(exactSphere.flux(glm::length(gk.positions[i])));
          innerErr = relErr(phi, ex);
        }
      }
      std::printf("| %.1f | %zu | %.4f | %.4f | %.2f | %.3f |\n", K, gk.nodeCount(), errs[0], errs[1], prep, solveSeconds);
      csv << K << "," << gk.nodeCount() << "," << errs[0] << "," << innerErr << "," << prep << "," << solveSeconds << "\n";
      err.x.push_back(double(gk.nodeCount())), err.y.push_back(errs[0]);
      errPaper.x.push_back(double(gk.nodeCount())), errPaper.y.push_back(errs[1]);
    }
    if (plot::chartsAvailable())
      plot::writeLineChart(out + "/quadgraph-K.png",
                           {"QuadGraph vs the analytic sphere, K = 2 ... 0 (20 mm skin1 red)", "nodes", "relative RMS of B", true, true},
                           {err, errPaper});
  }
  // Tolerance per solver against the exact solve (the 100k graph): solver error and time.
  {
    std::ofstream csv(out + "/quadgraph-tolerance.csv");
    csv << "solver,tolerance,iterations,seconds,error_vs_exact\n";
    std::vector<plot::Series> series;
    const unsigned char colour[3][3] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}};
    int c = 0;
    for (auto solver : {quadgraph::Solver::Jacobi, quadgraph::Solver::Sor, quadgraph::Solver::ConjugateGradient}) {
      plot::Series s{quadgraph::solverName(solver), {}, {}};
      std::copy(colour[c], colour[c] + 3, s.rgb);
      ++c;
      for (double tol : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
        std::vector<double> phi;
        quadgraph::SolveOptions so;
        so.tolerance = tol;
        const auto ts = Clock::now();
        const auto rep = quadgraph::solve(solver, sys, colours, b, phi, so, par);
        const double secs = since(ts), e = relErr(phi, exact);
        csv << quadgraph::solverName(solver) << "," << tol << "," << rep.iterations << "," << secs << "," << e << "\n";
        s.x.push_back(secs), s.y.push_back(e);
      }
      series.push_back(s);
    }
    if (plot::chartsAvailable())
      plot::writeLineChart(out + "/quadgraph-tolerance.png",
                           {"Solver error vs time (tolerance 1e-1 ... 1e-6), ~100k nodes", "seconds", "relative RMS error vs exact solve", true, true},
                           series);
  }
  std::printf("\nCSV and PNG in %s\n", out.c_str());
  return 0;
}
