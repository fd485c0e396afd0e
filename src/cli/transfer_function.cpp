#include "transfer_function.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <lucent/optics/materials.hpp>

#include "../util/error.hpp"
#include "args.hpp"

namespace lucent::cli {

namespace {
std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);)
    if (!part.empty()) out.push_back(part);
  return out;
}

/// The nearest voxel's value: labels are categories, not interpolated.
double nearestValue(const scene::VoxelGrid& g, const glm::dvec3& p) {
  const glm::ivec3 v =
      glm::clamp(glm::ivec3(glm::round((p - g.origin) / g.spacing)), glm::ivec3(0), g.dims - 1);
  return g.at(v.x, v.y, v.z);
}

ScanMedium labels(const std::string& what, const std::string& list,
                  std::shared_ptr<const scene::VoxelGrid> scan) {
  std::map<long, std::optional<optics::Material>> table;
  for (const auto& entry : split(list, ',')) {
    const auto eq = entry.find('=');
    if (eq == std::string::npos)
      throw InputError(what + ": '" + entry + "' is not LABEL=MATERIAL (or LABEL=none)");
    const long label = std::lround(parseNumber(entry.substr(0, eq), what));
    const std::string name = entry.substr(eq + 1);
    if (name == "none") {
      table[label] = std::nullopt;
      continue;
    }
    const auto m = optics::findMaterial(name);
    if (!m)
      throw InputError(what + ": '" + name + "' is not a material; `lucent materials` lists them");
    table[label] = *m;
  }
  std::set<long> present;
  for (float v : scan->values) present.insert(std::lround(v));
  std::string missing;
  for (long l : present)
    if (!table.count(l)) missing += (missing.empty() ? "" : ", ") + std::to_string(l);
  if (!missing.empty())
    throw InputError(what + ": the scan has labels " + missing +
                     " with no material; give each as LABEL=MATERIAL or LABEL=none");
  ScanMedium out;
  auto mask = std::make_shared<scene::VoxelGrid>(*scan);
  for (float& v : mask->values) v = table.at(std::lround(v)) ? 1.f : 0.f;
  out.mask = mask;
  std::map<long, technique::Coefficients> coefficients;
  for (const auto& [label, m] : table) {
    technique::Coefficients c;
    if (m) c = {glm::dvec3(m->sigmaA), glm::dvec3(m->sigmaSPrime)};
    coefficients[label] = c;
    out.maxSigmaT = glm::max(out.maxSigmaT, c.sigmaA + c.sigmaSPrime);
  }
  out.field = [scan, coefficients](const glm::dvec3& p) {
    const auto it = coefficients.find(std::lround(nearestValue(*scan, p)));
    return it == coefficients.end() ? technique::Coefficients{} : it->second;
  };
  out.description = "label map: " + list;
  return out;
}

ScanMedium points(const std::string& what, const std::string& list,
                  std::shared_ptr<const scene::VoxelGrid> scan) {
  struct Point {
    double value;
    technique::Coefficients c;
  };
  std::vector<Point> pts;
  for (const auto& entry : split(list, ';')) {
    const auto parts = split(entry, '/');
    if (parts.size() != 3)
      throw InputError(what + ": '" + entry + "' is not VALUE/SA_R,SA_G,SA_B/SS_R,SS_G,SS_B");
    Point p{parseNumber(parts[0], what),
            {parseTriple(parts[1], what), parseTriple(parts[2], what)}};
    for (int k = 0; k < 3; ++k)
      if (!(p.c.sigmaA[k] >= 0 && p.c.sigmaSPrime[k] >= 0))
        throw InputError(what + ": the point at " + parts[0] +
                         " gives a negative coefficient; sigma_a and sigma_s' must be >= 0");
    pts.push_back(p);
  }
  if (pts.empty()) throw InputError(what + ": give at least one VALUE/SA/SS point");
  std::sort(pts.begin(), pts.end(),
            [](const Point& a, const Point& b) { return a.value < b.value; });
  ScanMedium out;
  for (const auto& p : pts) out.maxSigmaT = glm::max(out.maxSigmaT, p.c.sigmaA + p.c.sigmaSPrime);
  out.field = [scan, pts](const glm::dvec3& x) {
    const double v = scan->sample(x);
    if (v <= pts.front().value) return pts.front().c;
    if (v >= pts.back().value) return pts.back().c;
    const auto hi = std::upper_bound(pts.begin(), pts.end(), v,
                                     [](double a, const Point& b) { return a < b.value; });
    const auto lo = hi - 1;
    const double t = (v - lo->value) / (hi->value - lo->value);
    return technique::Coefficients{glm::mix(lo->c.sigmaA, hi->c.sigmaA, t),
                                   glm::mix(lo->c.sigmaSPrime, hi->c.sigmaSPrime, t)};
  };
  out.description = "piecewise-linear transfer function: " + list;
  return out;
}
}  // namespace

ScanMedium parseTransfer(const std::string& what, const std::string& spec,
                         std::shared_ptr<const scene::VoxelGrid> scan) {
  if (spec.rfind("labels:", 0) == 0) return labels(what, spec.substr(7), std::move(scan));
  if (spec.rfind("points:", 0) == 0) return points(what, spec.substr(7), std::move(scan));
  throw InputError(what +
                   ": give labels:V=MATERIAL,... or points:V/SA/SS;... (lucent render --help)");
}

}  // namespace lucent::cli
