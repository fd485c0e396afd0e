#pragma once
/// @file materials.hpp
/// @brief Measured scattering coefficients (mm^-1) and user-defined materials.
///
/// Jensen, Marschner, Levoy, Hanrahan 2001, "A Practical Model for Subsurface Light Transport",
/// Fig. 5 (eta = 1.3), and Narasimhan, Gupta, Donner, Ramamoorthi, Nayar, Jensen 2006, "Acquiring
/// Scattering Properties of Participating Media by Dilution", Table 1, as reduced scattering and
/// absorption (the names are those pbrt uses). Narasimhan et al. did not measure eta; water's 1.33
/// is used.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "constants.hpp"
#include "rgb.hpp"

namespace lucent::optics {

/// @brief A homogeneous scattering material: what the dipole needs, per channel.
struct Material {
  std::string name;
  Rgb<double> sigmaSPrime{0.0};  ///< reduced scattering coefficient (mm^-1)
  Rgb<double> sigmaA{0.0};       ///< absorption coefficient (mm^-1)
  double eta = 1.3;              ///< relative index of refraction
  std::string source;            ///< where the numbers come from
};

struct MeasuredEntry {
  std::string_view name;
  std::array<double, 3> sigmaSPrime, sigmaA;
  double eta;
  std::string_view source;
};

inline constexpr std::string_view kJensen2001 = "Jensen et al. 2001";
inline constexpr std::string_view kNarasimhan2006 = "Narasimhan et al. 2006";

// One material a line reads best.
// clang-format off
inline constexpr std::array<MeasuredEntry, 47> kMeasuredMaterials{{
    {"Apple", {2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}, 1.3, kJensen2001},
    {"Chicken1", {0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}, 1.3, kJensen2001},
    {"Chicken2", {0.19, 0.25, 0.32}, {0.018, 0.088, 0.20}, 1.3, kJensen2001},
    {"Cream", {7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}, 1.3, kJensen2001},
    {"Ketchup", {0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}, 1.3, kJensen2001},
    {"Marble", {2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}, 1.3, kJensen2001},
    {"Potato", {0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}, 1.3, kJensen2001},
    {"Skimmilk", {0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}, 1.3, kJensen2001},
    {"Skin1", {0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3, kJensen2001},
    {"Skin2", {1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}, 1.3, kJensen2001},
    {"Spectralon", {11.6, 20.4, 14.9}, {0.00, 0.00, 0.00}, 1.3, kJensen2001},
    {"Wholemilk", {2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}, 1.3, kJensen2001},
    {"Lowfat Milk", {0.89187, 1.5136, 2.532}, {0.002875, 0.00575, 0.0115}, 1.33, kNarasimhan2006},
    {"Reduced Milk", {2.4858, 3.1669, 4.5214}, {0.0025556, 0.0051111, 0.012778}, 1.33, kNarasimhan2006},
    {"Regular Milk", {4.5513, 5.8294, 7.136}, {0.0015333, 0.0046, 0.019933}, 1.33, kNarasimhan2006},
    {"Espresso", {0.72378, 0.84557, 1.0247}, {4.7984, 6.5751, 8.8493}, 1.33, kNarasimhan2006},
    {"Mint Mocha Coffee", {0.31602, 0.38538, 0.48131}, {3.772, 5.8228, 7.82}, 1.33, kNarasimhan2006},
    {"Lowfat Soy Milk", {0.30576, 0.34233, 0.61664}, {0.0014375, 0.0071875, 0.035937}, 1.33, kNarasimhan2006},
    {"Regular Soy Milk", {0.59223, 0.73866, 1.4693}, {0.0019167, 0.0095833, 0.065167}, 1.33, kNarasimhan2006},
    {"Lowfat Chocolate Milk", {0.64925, 0.83916, 1.1057}, {0.0115, 0.0368, 0.1564}, 1.33, kNarasimhan2006},
    {"Regular Chocolate Milk", {1.4585, 2.1289, 2.9527}, {0.010063, 0.043125, 0.14375}, 1.33, kNarasimhan2006},
    {"Coke", {8.9053e-05, 8.372e-05, 0}, {0.10014, 0.16503, 0.2468}, 1.33, kNarasimhan2006},
    {"Pepsi", {6.1697e-05, 4.2564e-05, 0}, {0.091641, 0.14158, 0.20729}, 1.33, kNarasimhan2006},
    {"Sprite", {6.0306e-06, 6.4139e-06, 6.5504e-06}, {0.001886, 0.0018308, 0.0020025}, 1.33, kNarasimhan2006},
    {"Gatorade", {0.0024574, 0.003007, 0.0037325}, {0.024794, 0.019289, 0.008878}, 1.33, kNarasimhan2006},
    {"Chardonnay", {1.7982e-05, 1.3758e-05, 1.2023e-05}, {0.010782, 0.011855, 0.023997}, 1.33, kNarasimhan2006},
    {"White Zinfandel", {1.7501e-05, 1.9069e-05, 1.288e-05}, {0.012072, 0.016184, 0.019843}, 1.33, kNarasimhan2006},
    {"Merlot", {2.1129e-05, 0, 0}, {0.11632, 0.25191, 0.29434}, 1.33, kNarasimhan2006},
    {"Budweiser Beer", {2.4356e-05, 2.4079e-05, 1.0564e-05}, {0.011492, 0.024911, 0.057786}, 1.33, kNarasimhan2006},
    {"Coors Light Beer", {5.0922e-05, 4.301e-05, 0}, {0.006164, 0.013984, 0.034983}, 1.33, kNarasimhan2006},
    {"Clorox", {0.0024035, 0.0031373, 0.003991}, {0.0033542, 0.014892, 0.026297}, 1.33, kNarasimhan2006},
    {"Apple Juice", {0.00013612, 0.00015836, 0.000227}, {0.012957, 0.023741, 0.052184}, 1.33, kNarasimhan2006},
    {"Cranberry Juice", {0.00010402, 0.00011646, 7.8139e-05}, {0.039437, 0.094223, 0.12426}, 1.33, kNarasimhan2006},
    {"Grape Juice", {5.382e-05, 0, 0}, {0.10404, 0.23958, 0.29325}, 1.33, kNarasimhan2006},
    {"Ruby Grapefruit Juice", {0.011002, 0.010927, 0.011036}, {0.085867, 0.18314, 0.25262}, 1.33, kNarasimhan2006},
    {"White Grapefruit Juice", {0.22826, 0.23998, 0.32748}, {0.0138, 0.018831, 0.056781}, 1.33, kNarasimhan2006},
    {"Shampoo", {0.0007176, 0.0008303, 0.0009016}, {0.014107, 0.045693, 0.061717}, 1.33, kNarasimhan2006},
    {"Strawberry Shampoo", {0.00015671, 0.00015947, 1.518e-05}, {0.01449, 0.05796, 0.075823}, 1.33, kNarasimhan2006},
    {"Head & Shoulders Shampoo", {0.023805, 0.028804, 0.034306}, {0.084621, 0.15688, 0.20365}, 1.33, kNarasimhan2006},
    {"Lemon Tea Powder", {0.040224, 0.045264, 0.051081}, {2.4288, 4.5757, 7.2127}, 1.33, kNarasimhan2006},
    {"Orange Powder", {0.00015617, 0.00017482, 0.0001762}, {0.001449, 0.003441, 0.007863}, 1.33, kNarasimhan2006},
    {"Pink Lemonade Powder", {0.00012103, 0.00013073, 0.00012528}, {0.001165, 0.002366, 0.003195}, 1.33, kNarasimhan2006},
    {"Cappuccino Powder", {1.8436, 2.5851, 2.1662}, {35.844, 49.547, 61.084}, 1.33, kNarasimhan2006},
    {"Salt Powder", {0.027333, 0.032451, 0.031979}, {0.28415, 0.3257, 0.34148}, 1.33, kNarasimhan2006},
    {"Sugar Powder", {0.00022272, 0.00025513, 0.000271}, {0.012638, 0.031051, 0.050124}, 1.33, kNarasimhan2006},
    {"Suisse Mocha Powder", {2.7979, 3.5452, 4.3365}, {17.502, 27.004, 35.433}, 1.33, kNarasimhan2006},
    {"Pacific Ocean Surface Water", {0.0001764, 0.00032095, 0.00019617}, {0.031845, 0.031324, 0.030147}, 1.33, kNarasimhan2006},
}};
// clang-format on

namespace detail {
/// "Skin1", "skin1", "lowfat-milk", "Lowfat_Milk", "lowfat milk" all name the same entry.
inline std::string materialKey(std::string_view name) {
  std::string key;
  for (char ch : name)
    if (std::isalnum(static_cast<unsigned char>(ch)))
      key += char(std::tolower(static_cast<unsigned char>(ch)));
  return key;
}
}  // namespace detail

inline Material toMaterial(const MeasuredEntry& e) {
  return Material{std::string(e.name),
                  {e.sigmaSPrime[0], e.sigmaSPrime[1], e.sigmaSPrime[2]},
                  {e.sigmaA[0], e.sigmaA[1], e.sigmaA[2]},
                  e.eta,
                  std::string(e.source)};
}

/// @brief The measured material of that name (case, spaces, '-' and '_' ignored), if there is one.
inline std::optional<Material> findMaterial(std::string_view name) {
  const std::string key = detail::materialKey(name);
  for (const auto& e : kMeasuredMaterials)
    if (detail::materialKey(e.name) == key) return toMaterial(e);
  return std::nullopt;
}

/// @brief The measured materials' names, comma-separated: what an error about an unknown name
/// lists.
inline std::string measuredMaterialNames() {
  std::string names;
  for (const auto& e : kMeasuredMaterials)
    names += (names.empty() ? "" : ", ") + std::string(e.name);
  return names;
}

/// The largest coefficient a material may have: a mean free path of 1 nm, far below anything that
/// scatters light diffusely, and far from where sigma_t^2 products overflow.
inline constexpr double kMaxCoefficient = 1e6;  // mm^-1

/// @brief Why a material cannot be simulated, or an empty string when it can.
/// Coefficients must lie in [0, kMaxCoefficient], some channel must scatter, and eta must lie in
/// the range of the Fdr fit.
inline std::string validateMaterial(const Material& m) {
  for (int c = 0; c < kChannels; ++c) {
    if (!(m.sigmaA[c] >= 0 && m.sigmaA[c] <= kMaxCoefficient))
      return "sigma_a must lie in [0, 1e6] mm^-1 in every channel";
    if (!(m.sigmaSPrime[c] >= 0 && m.sigmaSPrime[c] <= kMaxCoefficient))
      return "sigma_s' must lie in [0, 1e6] mm^-1 in every channel";
  }
  if (!(m.sigmaSPrime[0] > 0 || m.sigmaSPrime[1] > 0 || m.sigmaSPrime[2] > 0))
    return "sigma_s' is 0 in every channel: nothing scatters below the surface";
  if (!(m.eta >= kEtaMin && m.eta <= kEtaMax))
    return "eta must lie in [" + std::to_string(kEtaMin).substr(0, 3) + ", " +
           std::to_string(kEtaMax).substr(0, 3) + "], the range of the diffuse Fresnel fit";
  return {};
}

}  // namespace lucent::optics
