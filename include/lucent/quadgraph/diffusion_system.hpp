#pragma once
/// @file diffusion_system.hpp
/// @brief The discretized diffusion equation on a QuadGraph (Wang et al. 2010 Sec. 4.2), one colour
/// channel, in a symmetric form every solver shares:
///   inner node i:   (sum_j c_ij + a_i) phi_i - sum_j c_ij phi_j = 0
///   surface node s: (c_sk + b_s) phi_s - c_sk phi_k = b_s Q_s,   Q_s = 4 q_s / (1 - Fdr)   (Eq. 2, 6)
/// with c_ij = c_ji. Two stencils fill c, a and b:
///  - Paper: Eq. 5-6 multiplied through by kappa_i: c_ij = kappa_i kappa_j / d_ij^2, a_i = kappa_i (w kappa_i
///    + mu_i) - sum_j c_ij, b_s = c_sk d_sk / (2 A kappa_s). Jacobi on this system is exactly Eq. 8-9.
///  - FiniteVolume (default): the flux kappa_f A_f (phi_j - phi_i) / d_f through each shared tet face, d_f the
///    distance between the nodes along the face normal, kappa_f the harmonic mean; a_i = mu_i V_i. Why: with
///    four neighbours, sum_j (phi_j - phi_i) / d^2 tends to (2/3) lap(phi), not lap(phi) (sum_j e_j e_j^T =
///    (4 d^2 / 3) I for an isotropic star), so Eq. 5 diffuses with 2/3 of kappa, and for heterogeneous media
///    it discretizes lap(kappa phi) rather than div(kappa grad phi). The two agree on what Eq. 8-9 compute
///    structurally; the finite-volume weights converge to the diffusion equation (tested on the sphere).
#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "../optics/diffusion_boundary.hpp"
#include "../util/number_text.hpp"
#include "quad_graph.hpp"

namespace lucent::quadgraph {

enum class Stencil { FiniteVolume, Paper };

/// kappa and mu at every node (inner then surface), one channel, in mm and mm^-1.
struct NodeMedium {
  std::vector<double> kappa, mu;
};

/// kappa = 1 / (3 (sigma_a + sigma_s')) (Eq. 1; the extracted text lost the parentheses).
inline double diffusionCoefficient(double sigmaA, double sigmaSPrime) { return 1.0 / (3.0 * (sigmaA + sigmaSPrime)); }

/// Samples a medium at every node: field(position) -> {sigma_a, sigma_s'} (mm^-1) for this channel.
template <class Field>
NodeMedium sampleMedium(const QuadGraph& g, const Field& field) {
  NodeMedium m;
  m.kappa.resize(g.nodeCount());
  m.mu.resize(g.nodeCount());
  for (std::size_t n = 0; n < g.nodeCount(); ++n) {
    const auto [sigmaA, sigmaSPrime] = field(g.positions[n]);
    if (!(sigmaA >= 0) || !(sigmaSPrime >= 0) || !(sigmaA + sigmaSPrime > 0) || !std::isfinite(sigmaA + sigmaSPrime))
      throw std::invalid_argument("QuadGraph medium: sigma_a = " + std::to_string(sigmaA) + ", sigma_s' = " +
                                  std::to_string(sigmaSPrime) + " at a node; both must be >= 0, finite, and not both 0");
    m.kappa[n] = diffusionCoefficient(sigmaA, sigmaSPrime);
    m.mu[n] = sigmaA;
  }
  return m;
}

template <class T>
struct DiffusionSystem {
  std::size_t innerCount = 0, nodeCount = 0;
  /// Four neighbour slots per node. A surface node uses slot 0 (its inner node); its other slots point at
  /// itself with weight 0, so every row has the same shape (one vectorisable loop, one GPU texture layout).
  std::vector<std::uint32_t> neighbour;
  std::vector<T> weight;    ///< c_ij, 4 per node
  std::vector<T> diagonal;  ///< sum_j c_ij + a_i (+ b_s)
  std::vector<T> robin;     ///< b_s at surface nodes, 0 at inner nodes
  double sourceScale = 0;   ///< Q = sourceScale * q (Eq. 2)
  double fdr = 0;
  Stencil stencil = Stencil::FiniteVolume;

  /// The right-hand side for transmitted irradiance q at the surface nodes (Eq. 3).
  std::vector<T> rhs(const std::vector<double>& q) const {
    if (q.size() != nodeCount - innerCount)
      throw std::invalid_argument("DiffusionSystem::rhs: expected " + std::to_string(nodeCount - innerCount) +
                                  " surface values, got " + std::to_string(q.size()));
    std::vector<T> b(nodeCount, T(0));
    for (std::size_t s = 0; s < q.size(); ++s) b[innerCount + s] = T(double(robin[innerCount + s]) * sourceScale * q[s]);
    return b;
  }

  /// (M phi)_i = diagonal_i phi_i - sum_k weight_ik phi_neighbour(ik).
  T apply(const std::vector<T>& phi, std::size_t i) const {
    const std::size_t o = 4 * i;
    return diagonal[i] * phi[i] - (weight[o] * phi[neighbour[o]] + weight[o + 1] * phi[neighbour[o + 1]] +
                                   weight[o + 2] * phi[neighbour[o + 2]] + weight[o + 3] * phi[neighbour[o + 3]]);
  }

  /// ||b - M phi||_2 / ||b||_2 (0 when b = 0 and phi solves it).
  double relativeResidual(const std::vector<T>& phi, const std::vector<T>& b) const {
    double rr = 0, bb = 0;
    for (std::size_t i = 0; i < nodeCount; ++i) {
      const double r = double(b[i]) - double(apply(phi, i));
      rr += r * r;
      bb += double(b[i]) * double(b[i]);
    }
    return bb > 0 ? std::sqrt(rr / bb) : std::sqrt(rr);
  }

  /// Smallest (diagonal - sum of |off-diagonal|) / diagonal over all rows: >= 0 means (weakly) diagonally
  /// dominant, so Jacobi and Gauss-Seidel converge (strictly at surface rows, and the graph is connected).
  double diagonalDominanceMargin() const {
    double worst = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < nodeCount; ++i) {
      double off = 0;
      for (int k = 0; k < 4; ++k) off += std::abs(double(weight[4 * i + std::size_t(k)]));
      worst = std::min(worst, (double(diagonal[i]) - off) / double(diagonal[i]));
    }
    return worst;
  }
};

/// The two-point distance, kept >= 1e-3 sqrt(face area): a sliver tet (TetGen can leave some) would
/// otherwise give an infinite conductance. Large but finite keeps the matrix symmetric and dominant.
inline double flooredFaceDistance(const QuadGraph& g, std::size_t slot) {
  return std::max(g.faceDistance[slot], 1e-3 * std::sqrt(g.faceArea[slot]));
}

/// Builds the system from the graph's current geometry and a medium; eta is the boundary's relative index.
template <class T = double>
DiffusionSystem<T> assemble(const QuadGraph& g, const NodeMedium& m, double eta, Stencil stencil = Stencil::FiniteVolume) {
  if (m.kappa.size() != g.nodeCount() || m.mu.size() != g.nodeCount())
    throw std::invalid_argument("QuadGraph assemble: the medium has " + std::to_string(m.kappa.size()) +
                                " nodes, the graph " + std::to_string(g.nodeCount()));
  DiffusionSystem<T> sys;
  const std::size_t ni = g.innerCount(), n = g.nodeCount();
  sys.innerCount = ni;
  sys.nodeCount = n;
  sys.stencil = stencil;
  sys.fdr = optics::diffuseFresnelReflectance(eta);
  sys.sourceScale = optics::diffusionBoundarySource(1.0, sys.fdr);
  const double boundaryA = optics::boundaryMismatch(eta);
  sys.neighbour.resize(4 * n);
  sys.weight.assign(4 * n, T(0));
  sys.diagonal.assign(n, T(0));
  sys.robin.assign(n, T(0));

  std::vector<double> diag(n, 0.0);
  for (std::size_t i = 0; i < ni; ++i) {
    double sumC = 0, sumInvD2 = 0;
    for (int k = 0; k < 4; ++k) {
      const std::size_t e = 4 * i + std::size_t(k);
      const std::uint32_t j = g.neighbours[i][std::size_t(k)];
      const double ki = m.kappa[i], kj = m.kappa[j];
      double c;
      if (stencil == Stencil::Paper) {
        const double d2 = g.nodeDistance[e] * g.nodeDistance[e];
        c = ki * kj / d2;
        sumInvD2 += 1 / d2;
      } else {
        c = (2 * ki * kj / (ki + kj)) * g.faceArea[e] / flooredFaceDistance(g, e);
      }
      sys.neighbour[e] = j;
      sys.weight[e] = T(c);
      sumC += c;
      if (g.isSurface(j)) {
        // The surface row: c_sk (phi_s - phi_k) + b_s phi_s = b_s Q_s, Eq. 6 times c_sk d_sk / (2 A kappa_s).
        const std::size_t s = j, o = 4 * s;
        const double d = stencil == Stencil::Paper ? g.nodeDistance[e] : flooredFaceDistance(g, e);
        const double b = c * d / (2 * boundaryA * kj);
        sys.neighbour[o] = std::uint32_t(i);
        sys.weight[o] = T(c);
        for (int pad = 1; pad < 4; ++pad) sys.neighbour[o + std::size_t(pad)] = std::uint32_t(s);
        sys.robin[s] = T(b);
        diag[s] = c + b;
      }
    }
    const double a = stencil == Stencil::Paper ? m.kappa[i] * (sumInvD2 * m.kappa[i] + m.mu[i]) - sumC
                                               : m.mu[i] * g.cellVolume[i];
    diag[i] = sumC + a;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!(diag[i] > 0) || !std::isfinite(diag[i]))
      throw std::invalid_argument("QuadGraph assemble: row " + std::to_string(i) + " has diagonal " +
                                  util::numberText(diag[i]) + " (degenerate geometry or medium)");
    sys.diagonal[i] = T(diag[i]);
  }
  return sys;
}

/// Outgoing radiance factor at the surface nodes, Eq. 7 with the transmitted fraction (1 - Fdr) that the
/// printed equation leaves out (optics/diffusion_boundary.hpp): L_o = Ft(w_o) B_s / pi, as the dipole's.
/// Negative values (possible where the discretization is too coarse for the absorption) are clamped to 0
/// and counted in *clamped.
template <class T>
std::vector<double> surfaceRadiosity(const DiffusionSystem<T>& sys, const std::vector<T>& phi,
                                     const std::vector<double>& q, std::size_t* clamped = nullptr) {
  std::vector<double> b(q.size());
  std::size_t negative = 0;
  for (std::size_t s = 0; s < q.size(); ++s) {
    const double v = optics::diffusionBoundaryRadiosity(double(phi[sys.innerCount + s]), q[s], sys.fdr);
    negative += v < 0;
    b[s] = std::max(0.0, v);
  }
  if (clamped) *clamped = negative;
  return b;
}

}  // namespace lucent::quadgraph
