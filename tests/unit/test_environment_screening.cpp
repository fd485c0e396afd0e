// The screening of a real probe's texels: negligible negatives and NaN are clamped with a note,
// anything that carries real energy is refused with the figure (scene/environment_image.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <lucent/scene/environment_image.hpp>

namespace {
using lucent::scene::kNegligibleEnergyShare;
using lucent::scene::screenEnvironmentTexels;

/// A w x h probe of radiance 1 everywhere but the texel values set in `edits`.
struct Probe {
  int w = 64, h = 32;
  std::vector<glm::vec3> texels = std::vector<glm::vec3>(std::size_t(64 * 32), glm::vec3(1));
  auto screen() const {
    return screenEnvironmentTexels(w, h,
                                   [&](int x, int y) { return texels[std::size_t(y * w + x)]; });
  }
};
}  // namespace

TEST_CASE("a probe's tiny negative texels are clamped to zero, with a note") {
  Probe p;
  p.texels[5].x = -4.47e-6f;
  p.texels[700].z = -1e-5f;
  const auto s = p.screen();
  CHECK(s.problem.empty());
  CHECK(s.note.find("clamped 2 texel values to 0: 2 negative") != std::string::npos);
  CHECK(s.radiance[5].x == 0.0f);
  CHECK(s.radiance[700].z == 0.0f);
  CHECK(s.radiance[6] == glm::vec3(1));
  for (const auto& t : s.radiance)
    for (int c = 0; c < 3; ++c) CHECK((std::isfinite(t[c]) && t[c] >= 0));
}

TEST_CASE("the negative share's threshold: below it clamped, above it refused") {
  const double total = 3.0 * 64 * 32;  // positive energy of the probe before the edit
  for (const double factor : {0.5, 2.0}) {
    Probe p;
    // One texel value carries `factor` times the negligible share of the energy, negatively.
    const double v =
        factor * kNegligibleEnergyShare * total / (1 - factor * kNegligibleEnergyShare);
    p.texels[0].y = float(-v);
    const auto s = p.screen();
    INFO("factor " << factor << ": " << s.problem << s.note);
    CHECK(s.problem.empty() == (factor < 1));
    if (factor > 1) CHECK(s.problem.find("% of the map's energy") != std::string::npos);
  }
}

TEST_CASE("a few NaN texels are clamped, while many NaN, an infinite or a huge texel are refused") {
  Probe few;
  few.texels[3].x = std::nanf("");
  CHECK(few.screen().problem.empty());
  CHECK(few.screen().note.find("1 NaN") != std::string::npos);

  Probe all;
  for (auto& t : all.texels) t = glm::vec3(std::nanf(""));
  CHECK(all.screen().problem.find("texel values are NaN") != std::string::npos);

  Probe inf;
  inf.texels[9].z = std::numeric_limits<float>::infinity();
  CHECK(inf.screen().problem.find("texel (9, 0) has radiance inf") != std::string::npos);

  Probe negInf;
  negInf.texels[64].x = -std::numeric_limits<float>::infinity();
  CHECK(negInf.screen().problem.find("texel (0, 1) has radiance -inf") != std::string::npos);

  Probe huge;
  huge.texels[1].x = 3e12f;
  CHECK(huge.screen().problem.find("at most 1e12") != std::string::npos);
}

TEST_CASE("a clean probe passes unchanged and without a note") {
  Probe p;
  p.texels[17] = glm::vec3(0, 1e3f, 2.5f);
  const auto s = p.screen();
  CHECK(s.problem.empty());
  CHECK(s.note.empty());
  CHECK(s.radiance == p.texels);
}
