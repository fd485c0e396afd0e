#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include <lucent/optics/fast_exp.hpp>

TEST_CASE("expNonPositive matches std::exp to 3e-7 relative on [-87, 0]") {
  double worst = 0;
  for (int i = 0; i <= 2000000; ++i) {
    const float x = -87.0f * float(i) / 2000000.0f;
    const double exact = std::exp(double(x));
    worst = std::max(worst, std::abs(double(lucent::optics::expNonPositive(x)) - exact) / exact);
  }
  INFO("worst relative error " << worst);
  CHECK(worst < 3e-7);
}

TEST_CASE("expNonPositive saturates instead of producing garbage outside its range") {
  using lucent::optics::expNonPositive;
  CHECK(expNonPositive(0.0f) == 1.0f);
  CHECK(expNonPositive(5.0f) == 1.0f);
  CHECK(expNonPositive(-1000.0f) > 0.0f);
  CHECK(expNonPositive(-1000.0f) < 1e-37f);
  CHECK(std::isfinite(expNonPositive(-std::numeric_limits<float>::infinity())));
}
