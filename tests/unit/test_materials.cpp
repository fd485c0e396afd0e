#include <doctest/doctest.h>

#include <set>

#include <lucent/optics/materials.hpp>

using namespace lucent::optics;

TEST_CASE("Every measured material is valid and uniquely named") {
  std::set<std::string> keys;
  for (const auto& e : kMeasuredMaterials) {
    const Material m = toMaterial(e);
    INFO(m.name);
    CHECK(validateMaterial(m).empty());
    CHECK(keys.insert(lucent::optics::detail::materialKey(m.name)).second);
  }
  CHECK(keys.size() == kMeasuredMaterials.size());
}

TEST_CASE("Materials are found by name regardless of case, spaces, dashes and underscores") {
  CHECK(findMaterial("skin1")->name == "Skin1");
  CHECK(findMaterial("SKIN1")->name == "Skin1");
  CHECK(findMaterial("lowfat-milk")->name == "Lowfat Milk");
  CHECK(findMaterial("Head_&_Shoulders_Shampoo")->name == "Head & Shoulders Shampoo");
  CHECK_FALSE(findMaterial("unobtainium").has_value());
}

TEST_CASE("Jensen et al. 2001: the twelve materials at eta 1.3, skin1 as published") {
  int jensen = 0;
  for (const auto& e : kMeasuredMaterials) jensen += e.source == kJensen2001;
  CHECK(jensen == 12);
  const Material skin1 = *findMaterial("skin1");
  CHECK(skin1.sigmaSPrime.x == 0.74);
  CHECK(skin1.sigmaA.z == 0.48);
  CHECK(skin1.eta == 1.3);
}

TEST_CASE("Invalid user materials are rejected with a reason") {
  Material m{"custom", {1, 1, 1}, {0.01, 0.01, 0.01}, 1.3, "user"};
  CHECK(validateMaterial(m).empty());
  Material neg = m;
  neg.sigmaA.y = -0.1;
  CHECK(validateMaterial(neg).find("sigma_a") != std::string::npos);
  Material none = m;
  none.sigmaSPrime = Rgb<double>(0);
  CHECK(validateMaterial(none).find("nothing scatters") != std::string::npos);
  Material eta = m;
  eta.eta = 0.9;
  CHECK(validateMaterial(eta).find("eta") != std::string::npos);
  eta.eta = 3.5;
  CHECK_FALSE(validateMaterial(eta).empty());
  Material nan = m;
  nan.sigmaSPrime.x = std::nan("");
  CHECK_FALSE(validateMaterial(nan).empty());
}
