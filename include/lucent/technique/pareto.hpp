#pragma once
/// @file pareto.hpp
/// @brief The Pareto front of (time, error) results: the settings no other setting beats on both
/// at once. The accuracy-cost report draws it; a planner chooses on it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace lucent::technique {

struct CostPoint {
  double seconds = 0;
  double error = 0;
};

/// Indices of the non-dominated points, by increasing time (hence decreasing error). A point is
/// dominated when another is no slower and no less accurate, and better in one of the two; of
/// exact ties the first is kept. Points with a non-finite or negative coordinate are left out.
inline std::vector<std::size_t> paretoFront(const std::vector<CostPoint>& points) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::isfinite(points[i].seconds) && std::isfinite(points[i].error) &&
        points[i].seconds >= 0 && points[i].error >= 0)
      order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].seconds != points[b].seconds) return points[a].seconds < points[b].seconds;
    return points[a].error < points[b].error;
  });
  std::vector<std::size_t> front;
  for (std::size_t i : order)  // by time: a point joins when it is more accurate than all before
    if (front.empty() || points[i].error < points[front.back()].error) front.push_back(i);
  return front;
}

}  // namespace lucent::technique
