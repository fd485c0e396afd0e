#pragma once
/// @file solvers.hpp
/// @brief Iterative solvers for a DiffusionSystem, all stopping on the relative residual
/// ||b - M phi|| / ||b|| <= tolerance:
///  - jacobi: the paper's relaxation (Eq. 8-9), two buffers, every node from the previous iterate;
///  - sor: multi-colour successive over-relaxation (nodes of one colour share no edge, so each colour is
///    updated in parallel in place; a degree-4 graph needs at most 5 colours);
///  - cg: conjugate gradients with the diagonal as preconditioner, on the symmetric positive definite
///    system (a_i >= 0; the Paper stencil on a heterogeneous medium can break that, and cg says so).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "../util/parallel.hpp"
#include "diffusion_system.hpp"

namespace lucent::quadgraph {

enum class Solver { Jacobi, Sor, ConjugateGradient };

inline const char* solverName(Solver s) {
  switch (s) {
    case Solver::Jacobi: return "jacobi";
    case Solver::Sor: return "sor";
    case Solver::ConjugateGradient: return "cg";
  }
  return "?";
}

struct SolveOptions {
  double tolerance = 1e-4;  ///< relative residual to stop at
  int maxIterations = 100000;
  double omega = 1.6;       ///< SOR relaxation factor in (0, 2)
  int residualEvery = 4;    ///< SOR checks the residual (one extra sweep) this often
};

struct SolveReport {
  int iterations = 0;
  double relativeResidual = 0;
  bool converged = false;
};

/// Greedy graph colouring of a system's rows: colourOrder lists rows colour by colour, colourStart[c] is
/// where colour c begins (colourStart.back() = row count).
struct Colouring {
  std::vector<std::uint32_t> colourOrder;
  std::vector<std::size_t> colourStart;
};

template <class T>
Colouring colourRows(const DiffusionSystem<T>& sys) {
  std::vector<int> colour(sys.nodeCount, -1);
  int colours = 0;
  for (std::size_t i = 0; i < sys.nodeCount; ++i) {
    unsigned used = 0;
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t j = sys.neighbour[4 * i + std::size_t(k)];
      if (j != i && colour[j] >= 0) used |= 1u << colour[j];
    }
    int c = 0;
    while (used & (1u << c)) ++c;
    colour[i] = c;
    colours = std::max(colours, c + 1);
  }
  Colouring out;
  out.colourStart.assign(std::size_t(colours) + 1, 0);
  for (int c : colour) ++out.colourStart[std::size_t(c) + 1];
  for (int c = 0; c < colours; ++c) out.colourStart[std::size_t(c) + 1] += out.colourStart[std::size_t(c)];
  out.colourOrder.resize(sys.nodeCount);
  std::vector<std::size_t> fill(out.colourStart.begin(), out.colourStart.end() - 1);
  for (std::size_t i = 0; i < sys.nodeCount; ++i) out.colourOrder[fill[std::size_t(colour[i])]++] = std::uint32_t(i);
  return out;
}

namespace detail {
/// sum over [0, n) of part(begin, end), with the ranges run by parallelFor.
template <class Part>
double parallelSum(const util::ParallelFor& parallelFor, std::size_t n, const Part& part) {
  std::mutex lock;
  double total = 0;
  parallelFor(n, [&](std::size_t begin, std::size_t end) {
    const double s = part(begin, end);
    std::lock_guard<std::mutex> guard(lock);
    total += s;
  });
  return total;
}
}  // namespace detail

/// One Jacobi sweep (Eq. 8-9) from `phi` into `next`; returns the squared residual of `phi`
/// (r_i = diagonal_i (next_i - phi_i), free with the sweep).
template <class T>
double jacobiSweep(const DiffusionSystem<T>& sys, const std::vector<T>& b, const std::vector<T>& phi,
                   std::vector<T>& next, const util::ParallelFor& parallelFor) {
  return detail::parallelSum(parallelFor, sys.nodeCount, [&](std::size_t begin, std::size_t end) {
    const std::uint32_t* nb = sys.neighbour.data();
    const T* w = sys.weight.data();
    const T* diag = sys.diagonal.data();
    const T* x = phi.data();
    const T* rhs = b.data();
    T* out = next.data();
    double rr = 0;
#pragma omp simd reduction(+ : rr)
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t o = 4 * i;
      const T sum = w[o] * x[nb[o]] + w[o + 1] * x[nb[o + 1]] + w[o + 2] * x[nb[o + 2]] + w[o + 3] * x[nb[o + 3]];
      const T v = (sum + rhs[i]) / diag[i];
      const double r = double(diag[i]) * double(v - x[i]);
      rr += r * r;
      out[i] = v;
    }
    return rr;
  });
}

template <class T>
double squaredNorm(const std::vector<T>& v) {
  double s = 0;
  for (const T& x : v) s += double(x) * double(x);
  return s;
}

template <class T>
SolveReport solveJacobi(const DiffusionSystem<T>& sys, const std::vector<T>& b, std::vector<T>& phi,
                        const SolveOptions& opt, const util::ParallelFor& parallelFor = util::serialFor) {
  SolveReport rep;
  const double bb = std::max(squaredNorm(b), std::numeric_limits<double>::min());
  std::vector<T> next(phi.size());
  for (rep.iterations = 0; rep.iterations < opt.maxIterations; ++rep.iterations) {
    const double rr = jacobiSweep(sys, b, phi, next, parallelFor);
    rep.relativeResidual = std::sqrt(rr / bb);
    if (rep.relativeResidual <= opt.tolerance) {
      rep.converged = true;
      return rep;  // phi (not next) is the iterate whose residual was measured
    }
    phi.swap(next);
  }
  rep.relativeResidual = sys.relativeResidual(phi, b);
  rep.converged = rep.relativeResidual <= opt.tolerance;
  return rep;
}

template <class T>
SolveReport solveSor(const DiffusionSystem<T>& sys, const Colouring& colours, const std::vector<T>& b,
                     std::vector<T>& phi, const SolveOptions& opt, const util::ParallelFor& parallelFor = util::serialFor) {
  if (!(opt.omega > 0 && opt.omega < 2)) throw std::invalid_argument("SOR: omega must be in (0, 2)");
  SolveReport rep;
  const double bb = std::max(squaredNorm(b), std::numeric_limits<double>::min());
  const T omega = T(opt.omega);
  auto residual = [&] {
    return std::sqrt(detail::parallelSum(parallelFor, sys.nodeCount, [&](std::size_t begin, std::size_t end) {
                       double rr = 0;
                       for (std::size_t i = begin; i < end; ++i) {
                         const double r = double(b[i]) - double(sys.apply(phi, i));
                         rr += r * r;
                       }
                       return rr;
                     }) / bb);
  };
  for (rep.iterations = 0; rep.iterations < opt.maxIterations;) {
    if (rep.iterations % std::max(1, opt.residualEvery) == 0) {
      rep.relativeResidual = residual();
      if (rep.relativeResidual <= opt.tolerance) return rep.converged = true, rep;
    }
    for (std::size_t c = 0; c + 1 < colours.colourStart.size(); ++c) {
      const std::size_t first = colours.colourStart[c], count = colours.colourStart[c + 1] - first;
      parallelFor(count, [&](std::size_t begin, std::size_t end) {
        const std::uint32_t* order = colours.colourOrder.data() + first;
        const std::uint32_t* nb = sys.neighbour.data();
        const T* w = sys.weight.data();
        T* x = phi.data();
        for (std::size_t r = begin; r < end; ++r) {
          const std::size_t i = order[r], o = 4 * i;
          const T sum = w[o] * x[nb[o]] + w[o + 1] * x[nb[o + 1]] + w[o + 2] * x[nb[o + 2]] + w[o + 3] * x[nb[o + 3]];
          // A surface row's padding slots point at the row itself with weight 0: harmless in place.
          x[i] += omega * ((sum + b[i]) / sys.diagonal[i] - x[i]);
        }
      });
    }
    ++rep.iterations;
  }
  rep.relativeResidual = residual();
  rep.converged = rep.relativeResidual <= opt.tolerance;
  return rep;
}

template <class T>
SolveReport solveConjugateGradient(const DiffusionSystem<T>& sys, const std::vector<T>& b, std::vector<T>& phi,
                                   const SolveOptions& opt, const util::ParallelFor& parallelFor = util::serialFor) {
  const std::size_t n = sys.nodeCount;
  SolveReport rep;
  const double bb = std::max(squaredNorm(b), std::numeric_limits<double>::min());
  std::vector<T> r(n), z(n), p(n), q(n);
  auto forRange = [&](const auto& body) { parallelFor(n, body); };
  forRange([&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) r[i] = b[i] - sys.apply(phi, i), z[i] = r[i] / sys.diagonal[i], p[i] = z[i];
  });
  auto dot = [&](const std::vector<T>& x, const std::vector<T>& y) {
    return detail::parallelSum(parallelFor, n, [&](std::size_t begin, std::size_t end) {
      double s = 0;
      for (std::size_t i = begin; i < end; ++i) s += double(x[i]) * double(y[i]);
      return s;
    });
  };
  double rz = dot(r, z);
  for (rep.iterations = 0; rep.iterations < opt.maxIterations; ++rep.iterations) {
    rep.relativeResidual = std::sqrt(dot(r, r) / bb);
    if (rep.relativeResidual <= opt.tolerance) return rep.converged = true, rep;
    forRange([&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) q[i] = sys.apply(p, i);
    });
    const double pq = dot(p, q);
    if (!(pq > 0))
      throw std::invalid_argument("cg: the system is not positive definite (p.Mp = " + std::to_string(pq) +
                                  "); the Paper stencil on a heterogeneous medium can do that: use the fv stencil or "
                                  "jacobi/sor");
    const T alpha = T(rz / pq);
    forRange([&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) phi[i] += alpha * p[i], r[i] -= alpha * q[i], z[i] = r[i] / sys.diagonal[i];
    });
    const double rzNext = dot(r, z);
    const T beta = T(rzNext / rz);
    rz = rzNext;
    forRange([&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) p[i] = z[i] + beta * p[i];
    });
  }
  rep.relativeResidual = sys.relativeResidual(phi, b);
  rep.converged = rep.relativeResidual <= opt.tolerance;
  return rep;
}

/// Runs the chosen solver (the colouring is only used by SOR; pass one from colourRows).
template <class T>
SolveReport solve(Solver solver, const DiffusionSystem<T>& sys, const Colouring& colours, const std::vector<T>& b,
                  std::vector<T>& phi, const SolveOptions& opt, const util::ParallelFor& parallelFor = util::serialFor) {
  if (phi.size() != sys.nodeCount) phi.assign(sys.nodeCount, T(0));
  switch (solver) {
    case Solver::Jacobi: return solveJacobi(sys, b, phi, opt, parallelFor);
    case Solver::Sor: return solveSor(sys, colours, b, phi, opt, parallelFor);
    case Solver::ConjugateGradient: return solveConjugateGradient(sys, b, phi, opt, parallelFor);
  }
  return {};
}

}  // namespace lucent::quadgraph
