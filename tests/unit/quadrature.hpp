#pragma once
// Adaptive Simpson quadrature: the tests' own integrator, independent of anything in lucent.
#include <cmath>
#include <functional>

namespace lucent::test {

inline double simpsonStep(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
                          double whole, double tol, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tol) return left + right + (left + right - whole) / 15;
  return simpsonStep(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) + simpsonStep(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}

inline double integrate(const std::function<double(double)>& f, double a, double b, double tol = 1e-12) {
  const double fa = f(a), fb = f(b), fm = f(0.5 * (a + b));
  return simpsonStep(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), tol, 50);
}

}  // namespace lucent::test
