/// `lucent materials`: the measured materials with the dipole quantities derived from them.
#include <cstdio>
#include <iostream>

#include <lucent/optics/dipole.hpp>
#include <lucent/optics/materials.hpp>

#include "args.hpp"
#include "commands.hpp"

namespace lucent::cli {

int runMaterials(int argc, char** argv) {
  Args args("materials", "lucent materials [--csv]", {{"csv", "", "machine-readable CSV instead of a table"}});
  args.parse(argc, argv, 2);
  if (args.helpRequested()) {
    std::cout << args.helpText()
              << "\ncoefficients in mm^-1 per channel R,G,B; mfp = 1/sigma_t' (mm); Rd_total = total diffuse reflectance\n";
    return 0;
  }
  if (!args.positional().empty()) args.fail("unexpected argument '" + args.positional().front() + "'");
  const bool csv = args.has("csv");
  if (csv)
    std::printf("name,sigma_s_prime_r,sigma_s_prime_g,sigma_s_prime_b,sigma_a_r,sigma_a_g,sigma_a_b,eta,"
                "mfp_r,mfp_g,mfp_b,rd_total_r,rd_total_g,rd_total_b,source\n");
  else
    std::printf("%-27s %-26s %-29s %-5s %-23s %-20s %s\n", "name", "sigma_s' (R,G,B)", "sigma_a (R,G,B)", "eta",
                "mfp mm (R,G,B)", "Rd_total (R,G,B)", "source");
  for (const auto& e : optics::kMeasuredMaterials) {
    const optics::Material m = optics::toMaterial(e);
    const auto d = optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
    const auto total = d.total();
    double mfp[3];
    for (int c = 0; c < 3; ++c) mfp[c] = 1.0 / (m.sigmaA[c] + m.sigmaSPrime[c]);
    if (csv) {
      std::printf("%s,%g,%g,%g,%g,%g,%g,%g,%g,%g,%g,%.6g,%.6g,%.6g,%s\n", m.name.c_str(), m.sigmaSPrime.x,
                  m.sigmaSPrime.y, m.sigmaSPrime.z, m.sigmaA.x, m.sigmaA.y, m.sigmaA.z, m.eta, mfp[0], mfp[1], mfp[2],
                  total.x, total.y, total.z, m.source.c_str());
    } else {
      char a[64], b[64], c[64], r[64];
      std::snprintf(a, sizeof a, "%.4g,%.4g,%.4g", m.sigmaSPrime.x, m.sigmaSPrime.y, m.sigmaSPrime.z);
      std::snprintf(b, sizeof b, "%.4g,%.4g,%.4g", m.sigmaA.x, m.sigmaA.y, m.sigmaA.z);
      std::snprintf(c, sizeof c, "%.3g,%.3g,%.3g", mfp[0], mfp[1], mfp[2]);
      std::snprintf(r, sizeof r, "%.3f,%.3f,%.3f", total.x, total.y, total.z);
      std::printf("%-27s %-26s %-29s %-5.2f %-23s %-20s %s\n", m.name.c_str(), a, b, m.eta, c, r, m.source.c_str());
    }
  }
  return 0;
}

}  // namespace lucent::cli
