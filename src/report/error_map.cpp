#include "error_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <lucent/image/tonemap.hpp>

namespace lucent::report {

namespace {
/// The ramp at t in [0, 1]: five stops of matplotlib's "inferno", linearly between them.
glm::vec4 ramp(double t) {
  constexpr std::array<std::array<float, 3>, 5> stops{{{0.00f, 0.00f, 0.02f},
                                                       {0.34f, 0.06f, 0.43f},
                                                       {0.73f, 0.22f, 0.33f},
                                                       {0.98f, 0.55f, 0.04f},
                                                       {0.99f, 1.00f, 0.64f}}};
  const double u = std::clamp(t, 0.0, 1.0) * double(stops.size() - 1);
  const std::size_t i = std::min(std::size_t(u), stops.size() - 2);
  const float f = float(u - double(i));
  glm::vec4 c(1);
  for (int k = 0; k < 3; ++k) c[k] = stops[i][k] * (1 - f) + stops[i + 1][k] * f;
  return c;
}
}  // namespace

image::Image relativeErrorMap(const image::Image& test, const image::Image& reference,
                              double fullScale) {
  image::Image out(reference.width, reference.height);
  const double mean = image::meanCoveredLuminance(reference);
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    const bool a = i < test.pixels.size() && test.pixels[i].a > 0;
    const bool b = reference.pixels[i].a > 0;
    if (!a && !b) {
      out.pixels[i] = glm::vec4(1);
      continue;
    }
    if (a != b || !(mean > 0) || !(fullScale > 0)) {
      out.pixels[i] = ramp(1);
      continue;
    }
    const double e =
        std::abs(double(image::luminance(test.pixels[i])) - image::luminance(reference.pixels[i]));
    out.pixels[i] = ramp(e / mean / fullScale);
  }
  return out;
}

}  // namespace lucent::report
