// `lucent plan` and `lucent render --method auto` as a user meets them, on the calibration data in
// the repository (data/planner): a plan with its reasons, the same choice in render, and one-line
// errors with exit code 2 for a hard budget no plan meets and for bad options or data.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <lucent/plan/scene_features.hpp>

#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace {
using lucent::test::contains;
using lucent::test::lucentCli;
using lucent::test::Run;
using lucent::test::slurp;

const std::string kSmall = "--width 32 --height 32 ";

/// The technique of the line "plan: NAME (KNOBS): ..." (empty when there is none).
std::string plannedTechnique(const std::string& out) {
  const auto at = out.find("plan: ");
  if (at == std::string::npos) return "";
  const auto end = out.find(" (", at);
  return out.substr(at + 6, end - at - 6);
}
}  // namespace

TEST_CASE("lucent plan: terms, a technique with its predicted time and error, and the reasons") {
  lucent::test::TempDir dir;
  const Run p = lucentCli("plan " + kSmall, dir);
  REQUIRE(p.code == 0);
  CHECK(contains(p.out, "terms: "));
  const std::string chosen = plannedTechnique(p.out);
  CHECK_FALSE(chosen.empty());
  CHECK(contains(p.out, "against the physical truth"));

  // The default scene is lit from behind through parts thinner than skin's diffusion length.
  const Run e = lucentCli("plan --explain " + kSmall, dir);
  REQUIRE(e.code == 0);
  CHECK(contains(e.out, "  + multiple scattering, global"));
  CHECK(contains(e.out, "  because: time t = "));
  CHECK(contains(e.out, "calibration scenes"));

  // render --method auto renders what the plan chose.
  const Run r = lucentCli("render --method auto --quiet " + kSmall + "--out " + dir / "a.exr" +
                              " --stats " + dir / "a.json",
                          dir);
  REQUIRE(r.code == 0);
  CHECK(contains(r.err, "lucent render: auto: " + chosen + " ("));
  CHECK(contains(slurp(dir / "a.json"), "\"method\": \"" + chosen + "\""));
}

TEST_CASE("lucent plan --features: the columns the calibration files are labelled with") {
  lucent::test::TempDir dir;
  const Run f = lucentCli("plan --features --shape sphere " + kSmall, dir);
  REQUIRE(f.code == 0);
  std::string header;
  for (const char* name : lucent::plan::kFeatureNames)
    header += (header.empty() ? "" : ",") + std::string(name);
  CHECK(f.out.rfind(header + "\n", 0) == 0);
}

TEST_CASE(
    "lucent plan: a hard budget no plan meets, and bad options or data, exit 2 naming the fix") {
  lucent::test::TempDir dir;
  const Run hard = lucentCli("plan --budget-ms 0.001 --hard-limit " + kSmall, dir);
  CHECK(hard.code == 2);
  CHECK(contains(hard.err, "no technique meets the budget (time 1e-06 s); closest: "));
  const Run soft = lucentCli("plan --budget-ms 0.001 " + kSmall, dir);
  CHECK(soft.code == 0);
  CHECK(contains(soft.out, "closest plan (budget not met): "));

  const Run missing = lucentCli("plan --calibration " + dir / "none " + kSmall, dir);
  CHECK(missing.code == 2);
  CHECK(contains(missing.err, dir / "none/settings.csv' cannot be read"));
  CHECK(contains(missing.err, "bench/calibrate_planner.py"));

  const std::string png = dir / "x.png";
  for (const std::string& bad :
       std::vector<std::string>{"plan --hard-limit", "plan --max-error -1",
                                "render --method auto --knob samples=4 --out " + png,
                                "render --method tsis --budget-ms 5 --out " + png}) {
    const Run r = lucentCli(bad + " " + kSmall, dir);
    INFO(bad);
    CHECK(r.code == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  CHECK_FALSE(std::filesystem::exists(dir / "x.png"));
}
