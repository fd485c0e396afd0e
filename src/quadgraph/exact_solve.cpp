#include "exact_solve.hpp"

#include <stdexcept>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

namespace lucent::quadgraph {

std::vector<double> exactSolve(const DiffusionSystem<double>& sys, const std::vector<double>& b) {
  const Eigen::Index n = Eigen::Index(sys.nodeCount);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(5 * sys.nodeCount);
  for (std::size_t i = 0; i < sys.nodeCount; ++i) {
    entries.emplace_back(Eigen::Index(i), Eigen::Index(i), sys.diagonal[i]);
    for (int k = 0; k < 4; ++k) {
      const std::size_t e = 4 * i + std::size_t(k);
      if (sys.weight[e] != 0) entries.emplace_back(Eigen::Index(i), Eigen::Index(sys.neighbour[e]), -sys.weight[e]);
    }
  }
  Eigen::SparseMatrix<double> m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver(m);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("QuadGraph exact solve: the LDL^T factorization failed (matrix not positive definite)");
  const Eigen::Map<const Eigen::VectorXd> rhs(b.data(), n);
  const Eigen::VectorXd x = solver.solve(rhs);
  if (solver.info() != Eigen::Success) throw std::runtime_error("QuadGraph exact solve: the solve failed");
  return std::vector<double>(x.data(), x.data() + n);
}

}  // namespace lucent::quadgraph
