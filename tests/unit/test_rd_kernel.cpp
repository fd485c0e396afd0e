#include <doctest/doctest.h>

#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include <lucent/optics/materials.hpp>
#include <lucent/reference/rd_sum_kernel.hpp>

using namespace lucent;

TEST_CASE(
    "The vectorised float Rd sum agrees with a double sum of the exact profile, classic and better "
    "dipole") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(-15.f, 15.f), weight(0.f, 2.f);
  const std::size_t n = 50000;
  std::vector<float> x(n), y(n), z(n), w0(n), w1(n), w2(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = pos(rng), y[i] = pos(rng), z[i] = pos(rng) * 0.1f;
    w0[i] = weight(rng), w1[i] = weight(rng), w2[i] = weight(rng);
  }
  for (const auto model : {optics::ProfileModel::Dipole, optics::ProfileModel::BetterDipole})
    for (const char* name : {"skin1", "spectralon", "ketchup", "cream", "coke"}) {
      const optics::Material m = *optics::findMaterial(name);
      const auto dd = optics::Profile<double>::make(model, m.sigmaA, m.sigmaSPrime, m.eta);
      const auto k = reference::RdKernelConstants::from(dd);
      CHECK(k.fluence == (model == optics::ProfileModel::BetterDipole));
      for (const glm::dvec3 o : {glm::dvec3(0), glm::dvec3(3, -2, 0.5), glm::dvec3(40, 0, 0)}) {
        double fast[3];
        reference::rdSumFloat({x.data(), y.data(), z.data(), w0.data(), w1.data(), w2.data(), n}, k,
                              float(o.x), float(o.y), float(o.z), fast);
        double exact[3] = {0, 0, 0};
        for (std::size_t i = 0; i < n; ++i) {
          const double r = glm::length(glm::dvec3(x[i], y[i], z[i]) - o);
          const auto rd = dd.rd(r);
          exact[0] += w0[i] * rd.x, exact[1] += w1[i] * rd.y, exact[2] += w2[i] * rd.z;
        }
        for (int c = 0; c < 3; ++c) {
          INFO(name << " at (" << o.x << "," << o.y << "," << o.z << ") channel " << c);
          if (exact[c] < 1e-25)
            CHECK(fast[c] < 1e-20);
          else
            CHECK(fast[c] == doctest::Approx(exact[c]).epsilon(2e-5));
        }
      }
    }
}
