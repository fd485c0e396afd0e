#include "phase_svd.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Dense>

#include <lucent/optics/phase_hg.hpp>
#include <lucent/scene/cube_map.hpp>

namespace lucent::prt {

namespace {
struct Directions {
  std::vector<glm::dvec3> centre;
  std::vector<double> solidAngle;
};

Directions cubeDirections(int size) {
  Directions d;
  const std::size_t n = std::size_t(6) * size * size;
  for (std::size_t i = 0; i < n; ++i) {
    d.centre.push_back(scene::cube::texelCentre(i, size));
    d.solidAngle.push_back(scene::cube::texelSolidAngle(int(i / size % size), int(i % size), size));
  }
  return d;
}
}  // namespace

PhaseDecomposition factorPhase(double g, int size, int terms) {
  const Directions d = cubeDirections(size);
  const Eigen::Index n = Eigen::Index(d.centre.size());
  // A = W^1/2 P W^1/2, P_io = p(w_i . w_o): symmetric.
  Eigen::MatrixXd a(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index o = 0; o < n; ++o)
      a(i, o) = std::sqrt(d.solidAngle[i] * d.solidAngle[o]) *
                optics::phaseHG(glm::dot(d.centre[i], d.centre[o]), g);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(a);
  const Eigen::VectorXd& values = solver.eigenvalues();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index(0));
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index x, Eigen::Index y) {
    return std::abs(values[x]) > std::abs(values[y]);
  });
  PhaseDecomposition out;
  out.factors.size = size;
  for (Eigen::Index k : order) out.eigenvalues.push_back(values[k]);
  // P_io ~ sum_k (lambda_k u_k(i) / sqrt w_i) (u_k(o) / sqrt w_o).
  for (int k = 0; k < std::min<int>(terms, int(n)); ++k) {
    const Eigen::Index column = order[std::size_t(k)];
    std::vector<float> light(static_cast<std::size_t>(n)), view(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      const double u = solver.eigenvectors()(i, column) / std::sqrt(d.solidAngle[i]);
      light[std::size_t(i)] = float(values[column] * u);
      view[std::size_t(i)] = float(u);
    }
    out.factors.light.push_back(std::move(light));
    out.factors.view.push_back(std::move(view));
  }
  return out;
}

double phaseFactorError(const PhaseFactors& factors, double g) {
  const Directions d = cubeDirections(factors.size);
  double error = 0, norm = 0;
  for (std::size_t i = 0; i < d.centre.size(); ++i)
    for (std::size_t o = 0; o < d.centre.size(); ++o) {
      const double p = optics::phaseHG(glm::dot(d.centre[i], d.centre[o]), g);
      double approx = 0;
      for (std::size_t k = 0; k < factors.terms(); ++k)
        approx += double(factors.light[k][i]) * factors.view[k][o];
      const double w = d.solidAngle[i] * d.solidAngle[o];
      error += w * (p - approx) * (p - approx), norm += w * p * p;
    }
  return std::sqrt(error / norm);
}

}  // namespace lucent::prt
