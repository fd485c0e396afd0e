#pragma once
/// @file exact_solve.hpp
/// @brief The direct sparse solve (Eigen, sparse Cholesky) of a QuadGraph system: the reference that the
/// iterative solvers' error is measured against.
#include <vector>

#include <lucent/quadgraph/diffusion_system.hpp>

namespace lucent::quadgraph {

/// Solves M phi = b exactly (to rounding). Uses LDL^T on the symmetric matrix; throws std::runtime_error
/// if the factorization fails (a matrix that is not positive definite, e.g. the Paper stencil on a strongly
/// heterogeneous medium).
std::vector<double> exactSolve(const DiffusionSystem<double>& system, const std::vector<double>& b);

}  // namespace lucent::quadgraph
