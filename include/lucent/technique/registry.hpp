#pragma once
/// @file registry.hpp
/// @brief The techniques every front end lists and runs. A technique is added once
/// (core_techniques.hpp for the header-only ones, an adapter for those that need a heavy library);
/// front ends never name one.
#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "properties.hpp"
#include "technique.hpp"

namespace lucent::technique {

/// The result of one prepare and one frame.
struct Rendered {
  FrameResult frame;
  Statistics stats;
  double seconds = 0;  ///< wall time of prepare + frame
};

/// Each requirement of `scene` shaded at `request` that `t` cannot take, as a phrase ("a
/// heterogeneous medium (density field)"); empty when it takes them all.
inline std::vector<std::string> unmetBy(const Technique& t, const SceneDescription& scene,
                                        const ShadeRequest& request) {
  return unmet(t.capabilities, requirementsOf(scene, request));
}

class Registry {
 public:
  /// Adds a technique; its name must be new, its default knobs valid, and its knob names unique
  /// also in their CamelCase form (the VTK property names).
  void add(Technique t) {
    if (find(t.name)) throw std::logic_error("technique '" + t.name + "' is registered twice");
    for (std::size_t i = 0; i < t.knobs.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (camelCase(t.knobs[i].name) == camelCase(t.knobs[j].name))
          throw std::logic_error("technique '" + t.name + "': knobs " + t.knobs[i].name + " and " +
                                 t.knobs[j].name + " have the same CamelCase name");
    t.values();  // the defaults must pass their own checks
    for (const auto& [k, max] : t.capabilities.gpuTwinKnobs)
      if (!t.knob(k))
        throw std::logic_error("technique '" + t.name + "': its GPU twin's knob " + k +
                               " is not its knob");
    for (const auto& other : mAll)
      for (const auto& k : t.knobs)
        for (const auto& ok : other.knobs)
          if (propertyName(t, k) == propertyName(other, ok))
            throw std::logic_error("technique '" + t.name + "' knob " + k.name +
                                   " and technique '" + other.name + "' knob " + ok.name +
                                   " have the same property name " + propertyName(t, k));
    mAll.push_back(std::move(t));
  }
  /// In the order added; references stay valid as techniques are added (adapters register later).
  const std::deque<Technique>& all() const { return mAll; }
  const Technique* find(const std::string& name) const {
    for (const auto& t : mAll)
      if (t.name == name) return &t;
    return nullptr;
  }
  /// Throws RequestError listing the techniques when `name` is unknown.
  const Technique& get(const std::string& name) const {
    if (const Technique* t = find(name)) return *t;
    throw RequestError("unknown technique '" + name +
                       "'; available: " + names([](const Technique&) { return true; }));
  }

  /// Fails before any work when the technique cannot serve the scene and request, naming those that
  /// can.
  void check(const Technique& t, const SceneDescription& scene, const ShadeRequest& request) const {
    const auto missing = unmetBy(t, scene, request);
    if (missing.empty()) return;
    std::string what;
    for (const auto& m : missing) what += (what.empty() ? "" : ", ") + m;
    const std::string able =
        names([&](const Technique& o) { return unmetBy(o, scene, request).empty(); });
    throw RequestError("technique '" + t.name + "' cannot take " + what +
                       "; techniques that can: " + (able.empty() ? "none" : able));
  }

  /// Fails before any work when the scene lies outside the technique's valid range with these
  /// knobs (Technique::validity), with the reason, the fix and the techniques whose range holds
  /// (with `request`: only those that can also take the scene, e.g. a scan's density field).
  void checkRange(const Technique& t, const SceneDescription& scene, const KnobValues& knobs,
                  const ShadeRequest* request = nullptr) const {
    const std::string why = t.validity ? t.validity(scene, knobs) : "";
    if (why.empty()) return;
    const std::string able = names([&](const Technique& o) {
      return &o != &t && (!request || unmetBy(o, scene, *request).empty()) &&
             (!o.validity || o.validity(scene, o.values()).empty());
    });
    throw RequestError("technique '" + t.name + "' is outside its valid range here: " + why +
                       " (valid for: " + t.validRange + "; techniques valid here with their " +
                       "defaults: " + (able.empty() ? "none" : able) + ")");
  }

  /// check and checkRange, then the technique's prepare.
  std::unique_ptr<Prepared> prepare(const Technique& t, const SceneDescription& scene,
                                    const KnobValues& knobs, const ShadeRequest& request,
                                    Statistics& stats) const {
    check(t, scene, request);
    checkRange(t, scene, knobs, &request);
    std::unique_ptr<Prepared> prepared = t.prepare(scene, knobs, stats);
    scene.checkCancelled();
    return prepared;
  }

  /// One frame on what prepare built, radiance completed from radiosity.
  static FrameResult frame(Prepared& prepared, const SceneDescription& scene,
                           const ShadeRequest& request, Statistics& stats) {
    FrameResult out = prepared.frame(scene, request, stats);
    completeRadiance(out, request, scene.medium.material.eta);
    return out;
  }

  /// prepare and one frame.
  Rendered render(const Technique& t, const SceneDescription& scene, const KnobValues& knobs,
                  const ShadeRequest& request) const {
    Rendered out;
    const Stopwatch clock;
    const std::unique_ptr<Prepared> prepared = prepare(t, scene, knobs, request, out.stats);
    out.frame = frame(*prepared, scene, request, out.stats);
    out.seconds = clock.seconds();
    return out;
  }

  /// The first ground-truth technique that shades any surface point without a camera: what front
  /// ends run and measure against when none is named.
  const Technique& defaultReference() const {
    for (const auto& t : mAll)
      if (t.capabilities.groundTruth && !t.capabilities.needsCamera) return t;
    throw RequestError("no ground-truth technique is registered");
  }

  /// The ground truth of `model` (the technique its techniques converge to), or null when the model
  /// has none.
  const Technique* truthOf(const std::string& model) const {
    for (const auto& t : mAll)
      if (t.capabilities.groundTruth && t.model == model) return &t;
    return nullptr;
  }
  /// The physical truth (kPhysicalModel), or null when none is registered.
  const Technique* physicalTruth() const { return truthOf(kPhysicalModel); }

  /// Names of the techniques `keep` accepts, comma-separated.
  template <class Keep>
  std::string names(const Keep& keep) const {
    std::string s;
    for (const auto& t : mAll)
      if (keep(t)) s += (s.empty() ? "" : ", ") + t.name;
    return s;
  }

 private:
  std::deque<Technique> mAll;
};

/// The techniques a per-vertex, camera-less front end (the VTK filter) offers, in registry order.
inline std::vector<const Technique*> vertexTechniques(const Registry& registry) {
  std::vector<const Technique*> out;
  for (const auto& t : registry.all())
    if (shadesVertices(t)) out.push_back(&t);
  return out;
}

/// (technique, knob) of every property of the offered techniques, in order.
inline std::vector<std::pair<const Technique*, const KnobSpec*>> knobProperties(
    const Registry& registry) {
  std::vector<std::pair<const Technique*, const KnobSpec*>> out;
  for (const Technique* t : vertexTechniques(registry))
    for (const auto& k : t->knobs)
      if (isProperty(k)) out.emplace_back(t, &k);
  return out;
}

}  // namespace lucent::technique
