// Embedding lucent's core headers in another renderer: only the STL and GLM are needed.
// Builds the Rd table a shader would sample (as a 1-D texture indexed by sqrt(r / rMax)) for a material
// scaled to an object, and prints what a renderer needs to size its sampling.
//
//   g++ -std=c++17 -I include examples/embed_dipole.cpp -o embed_dipole && ./embed_dipole
#include <cstdio>

#include <lucent/optics/dipole_lut.hpp>
#include <lucent/optics/materials.hpp>

int main() {
  using namespace lucent::optics;
  const Material skin = *findMaterial("skin1");
  const auto dipole = Dipole<float>::make(Rgb<float>(skin.sigmaA), Rgb<float>(skin.sigmaSPrime), float(skin.eta));
  const float objectDiagonalMm = 30.0f;
  const RdTable<float> table(dipole, objectDiagonalMm, {1e-3f, 1e-6f});
  std::printf("%s: mean free path %.3f mm, total diffuse reflectance (%.3f, %.3f, %.3f)\n", skin.name.c_str(),
              dipole.minMeanFreePath(), dipole.total().x, dipole.total().y, dipole.total().z);
  std::printf("Rd table: %zu texels over [0, %.0f] mm, relative error <= 1e-3\n", table.size(), table.rMax());
  for (float r : {0.0f, 0.5f, 2.0f, 8.0f})
    std::printf("  Rd(%4.1f mm) = (%.5f, %.5f, %.5f) /mm^2\n", r, table(r).x, table(r).y, table(r).z);
  // Half of the light re-emerges within this radius (red channel): a natural sampling radius.
  float lo = 0, hi = objectDiagonalMm;
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (dipole.channel[0].cumulative(mid) < 0.5f * dipole.channel[0].total() ? lo : hi) = mid;
  }
  std::printf("half of the red light leaves within %.2f mm of where it entered\n", hi);
  return 0;
}
