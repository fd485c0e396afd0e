#pragma once
/// @file transfer_function.hpp
/// @brief A scan's values turned into the object's medium, for every front end that takes a scan
/// (the CLI's `--volume --transfer`, vtkLucentVolumeFilter):
///  - "labels:V=MATERIAL,V=MATERIAL,...": a label map; each label (the value rounded) is a measured
///    material or "none" (no medium: outside, or a cavity). The object's surface is then where the
///    labels with a material meet the others (the mask, contoured at 1/2); a label in the scan with
///    no entry is an error naming it.
///  - "points:V/SA/SS;V/SA/SS;...": piecewise linear in the value between control points (sorted by
///    V, held beyond the ends), SA = sigma_a and SS = sigma_s' as R,G,B in mm^-1, e.g.
///    points:100/0.01,0.02,0.05/0.5,0.6,0.7;400/0.1,0.2,0.3/2,2,2.
///  - none given: the values normalised to [0, 1] over their range scale the material (a density).
/// Positions are the scan's own (its origin and spacing); errors are RequestError naming `what`.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../optics/materials.hpp"
#include "../scene/voxel_grid.hpp"
#include "knob.hpp"
#include "scene.hpp"
#include "validity.hpp"

namespace lucent::technique {

struct ScanMedium {
  CoefficientField field;   ///< in the scan's coordinates
  glm::dvec3 maxSigmaT{0};  ///< sigma_a + sigma_s' never above, per channel
  std::string description;
  /// Labels: 1 where the label has a material, 0 elsewhere (contoured at 1/2 for the surface).
  std::shared_ptr<const scene::VoxelGrid> mask;
  /// The coefficients everywhere inside, when the function is constant there (one point, points
  /// that all agree, or labels that all name one material): a homogeneous medium, which every
  /// dipole technique takes.
  std::optional<Coefficients> uniform;
};

namespace transfer {
inline std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);)
    if (!part.empty()) out.push_back(part);
  return out;
}

inline double number(const std::string& text, const std::string& what) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (text.empty() || end == begin || *end != '\0' || !std::isfinite(v))
    throw RequestError(what + ": '" + text + "' is not a number; write e.g. 1.5 or 2e-3");
  return v;
}

/// R,G,B (or one value for all three).
inline glm::dvec3 triple(const std::string& text, const std::string& what) {
  const auto parts = split(text, ',');
  if (parts.size() == 1) return glm::dvec3(number(parts[0], what));
  if (parts.size() != 3)
    throw RequestError(what + ": '" + text + "' needs 3 comma-separated numbers R,G,B");
  return {number(parts[0], what), number(parts[1], what), number(parts[2], what)};
}

/// The largest label: scans hold float values, which are whole numbers exactly up to 2^24.
inline constexpr double kMaxLabel = 16777216;
/// Distinct labels a label map may hold (atlases have hundreds).
inline constexpr std::size_t kMaxLabelsPresent = 65536;

/// A label held by a voxel (rounded: resampled label maps hold fractions at their seams) or, with
/// `whole`, as written in the spec: within +-kMaxLabel.
inline long labelOf(double value, bool whole, const std::string& what, const std::string& where) {
  if (!(std::fabs(value) <= kMaxLabel && (!whole || value == std::floor(value))))
    throw RequestError(what + ": " + where + " " + numberText(value) + " is not a label (a " +
                       (whole ? "whole " : "") + "number within +-" +
                       std::to_string(long(kMaxLabel)) +
                       "); give labels of a label map, or a points: transfer function for a scan "
                       "of measurements");
  return std::lround(value);
}

/// The nearest voxel's value: labels are categories, not interpolated.
inline double nearestValue(const scene::VoxelGrid& g, const glm::dvec3& p) {
  const glm::ivec3 v =
      glm::clamp(glm::ivec3(glm::round((p - g.origin) / g.spacing)), glm::ivec3(0), g.dims - 1);
  return g.at(v.x, v.y, v.z);
}

inline ScanMedium labels(const std::string& what, const std::string& list,
                         std::shared_ptr<const scene::VoxelGrid> scan) {
  std::map<long, std::optional<optics::Material>> table;
  for (const auto& entry : split(list, ',')) {
    const auto eq = entry.find('=');
    if (eq == std::string::npos)
      throw RequestError(what + ": '" + entry + "' is not LABEL=MATERIAL (or LABEL=none)");
    const long label = labelOf(number(entry.substr(0, eq), what), true, what, "the label");
    if (table.count(label))
      throw RequestError(what + ": label " + std::to_string(label) +
                         " is given twice; give each label one material");
    const std::string name = entry.substr(eq + 1);
    if (name == "none") {
      table[label] = std::nullopt;
      continue;
    }
    const auto m = optics::findMaterial(name);
    if (!m)
      throw RequestError(what + ": '" + name +
                         "' is not a material; `lucent materials` lists them");
    table[label] = *m;
  }
  std::set<long> present;
  for (float v : scan->values) {
    present.insert(labelOf(v, false, what, "the scan holds the value"));
    if (present.size() > kMaxLabelsPresent)
      throw RequestError(what + ": the scan holds more than " + std::to_string(kMaxLabelsPresent) +
                         " distinct values, so it is no label map; use a points: transfer "
                         "function or --iso");
  }
  std::string missing;
  for (long l : present)
    if (!table.count(l)) missing += (missing.empty() ? "" : ", ") + std::to_string(l);
  if (!missing.empty())
    throw RequestError(what + ": the scan has labels " + missing +
                       " with no material; give each as LABEL=MATERIAL or LABEL=none");
  ScanMedium out;
  auto mask = std::make_shared<scene::VoxelGrid>(*scan);
  for (float& v : mask->values) v = table.at(std::lround(v)) ? 1.f : 0.f;
  out.mask = mask;
  std::map<long, Coefficients> coefficients;
  for (const auto& [label, m] : table) {
    Coefficients c;
    if (m) c = {glm::dvec3(m->sigmaA), glm::dvec3(m->sigmaSPrime)};
    coefficients[label] = c;
    out.maxSigmaT = glm::max(out.maxSigmaT, c.sigmaA + c.sigmaSPrime);
  }
  std::optional<Coefficients> only;  // the one material every labelled voxel has, if so
  bool one = true;
  for (const auto& [label, m] : table) {
    if (!m) continue;
    const Coefficients c{glm::dvec3(m->sigmaA), glm::dvec3(m->sigmaSPrime)};
    one = one && (!only || *only == c);
    only = c;
  }
  if (one && only) out.uniform = only;
  out.field = [scan, coefficients](const glm::dvec3& p) {
    const auto it = coefficients.find(std::lround(nearestValue(*scan, p)));
    return it == coefficients.end() ? Coefficients{} : it->second;
  };
  out.description = "label map: " + list;
  return out;
}

inline ScanMedium points(const std::string& what, const std::string& list,
                         std::shared_ptr<const scene::VoxelGrid> scan) {
  struct Point {
    double value;
    Coefficients c;
  };
  std::vector<Point> pts;
  for (const auto& entry : split(list, ';')) {
    const auto parts = split(entry, '/');
    if (parts.size() != 3)
      throw RequestError(what + ": '" + entry + "' is not VALUE/SA_R,SA_G,SA_B/SS_R,SS_G,SS_B");
    Point p{number(parts[0], what), {triple(parts[1], what), triple(parts[2], what)}};
    for (int k = 0; k < 3; ++k)
      if (!(p.c.sigmaA[k] >= 0 && p.c.sigmaSPrime[k] >= 0 &&
            p.c.sigmaA[k] + p.c.sigmaSPrime[k] <= optics::kMaxCoefficient))
        throw RequestError(what + ": the point at " + parts[0] +
                           " gives a coefficient outside [0, " +
                           numberText(optics::kMaxCoefficient) +
                           "] mm^-1 (sigma_a and sigma_s' are >= 0, their sum at most that)");
    pts.push_back(p);
  }
  if (pts.empty()) throw RequestError(what + ": give at least one VALUE/SA/SS point");
  std::sort(pts.begin(), pts.end(),
            [](const Point& a, const Point& b) { return a.value < b.value; });
  ScanMedium out;
  for (const auto& p : pts) out.maxSigmaT = glm::max(out.maxSigmaT, p.c.sigmaA + p.c.sigmaSPrime);
  if (std::all_of(pts.begin(), pts.end(), [&](const Point& p) { return p.c == pts.front().c; }))
    out.uniform = pts.front().c;
  out.field = [scan, pts](const glm::dvec3& x) {
    const double v = scan->sample(x);
    if (v <= pts.front().value) return pts.front().c;
    if (v >= pts.back().value) return pts.back().c;
    const auto hi = std::upper_bound(pts.begin(), pts.end(), v,
                                     [](double a, const Point& b) { return a < b.value; });
    const auto lo = hi - 1;
    const double t = (v - lo->value) / (hi->value - lo->value);
    return Coefficients{glm::mix(lo->c.sigmaA, hi->c.sigmaA, t),
                        glm::mix(lo->c.sigmaSPrime, hi->c.sigmaSPrime, t)};
  };
  out.description = "piecewise-linear transfer function: " + list;
  return out;
}
}  // namespace transfer

/// The medium of a transfer-function spec (labels:... or points:...) over `scan`.
inline ScanMedium parseTransfer(const std::string& what, const std::string& spec,
                                std::shared_ptr<const scene::VoxelGrid> scan) {
  if (spec.rfind("labels:", 0) == 0) return transfer::labels(what, spec.substr(7), std::move(scan));
  if (spec.rfind("points:", 0) == 0) return transfer::points(what, spec.substr(7), std::move(scan));
  throw RequestError(what + ": give labels:V=MATERIAL,... or points:V/SA/SS;...");
}

/// With no transfer function: the scan's values normalised to [0, 1] over their range, a density
/// scaling the material (1 everywhere when the values are constant). `scanAt` maps a position of
/// the scene to the scan's coordinates.
template <class ToScan>
void normalisedDensity(std::shared_ptr<const scene::VoxelGrid> scan, const ToScan& scanAt,
                       const std::string& name, Medium& medium) {
  const auto [lo, hi] = std::minmax_element(scan->values.begin(), scan->values.end());
  const double low = *lo, span = double(*hi) - double(*lo);
  medium.density = [scan, low, span, scanAt](const glm::dvec3& p) {
    return span > 0 ? std::clamp((scan->sample(scanAt(p)) - low) / span, 0.0, 1.0) : 1.0;
  };
  medium.densityDescription = name + " (" + std::to_string(scan->dims.x) + "x" +
                              std::to_string(scan->dims.y) + "x" + std::to_string(scan->dims.z) +
                              " voxels, values over [" + valueText(low) + ", " +
                              valueText(low + span) + "] normalised to [0, 1])";
}

/// A transfer function's medium placed in the scene: `scanAt` maps scene positions to the scan's.
template <class ToScan>
void transferMedium(const ScanMedium& tf, const ToScan& scanAt, const std::string& name,
                    Medium& medium) {
  if (tf.uniform) {  // homogeneous: the material is the function's one pair of coefficients
    medium.material.name = "the transfer function's uniform medium";
    medium.material.sigmaA = tf.uniform->sigmaA;
    medium.material.sigmaSPrime = tf.uniform->sigmaSPrime;
    return;
  }
  medium.coefficients = [field = tf.field, scanAt](const glm::dvec3& p) {
    return field(scanAt(p));
  };
  medium.maxSigmaT = tf.maxSigmaT;
  medium.densityDescription = name + " through a " + tf.description;
}

}  // namespace lucent::technique
