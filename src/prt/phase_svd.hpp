#pragma once
/// @file phase_svd.hpp
/// @brief The Henyey-Greenstein phase function factored into K separable terms (Wang, Tran, Luebke
/// 2005, Sec. 3, Eq. 9; Kautz and McCool 1999's separable decomposition): tabulated between the
/// texel centres of a 6 x size x size cube of directions, weighted by the square roots of the
/// texels' solid angles so that the factorisation is optimal in L2 over the sphere, and decomposed
/// (the table is symmetric, so its SVD is its eigen-decomposition; Eigen). The terms come in order
/// of |eigenvalue|; HG's are g^l with multiplicity 2l + 1 (its spherical-harmonic expansion), the
/// independent check of the tests.
#include <vector>

#include <lucent/prt/single_transport.hpp>

namespace lucent::prt {

struct PhaseDecomposition {
  PhaseFactors factors;             ///< the first K terms
  std::vector<double> eigenvalues;  ///< all of them, by decreasing |value|
};

/// @param size directions' cube texels across (the paper's 16); @param terms K
PhaseDecomposition factorPhase(double g, int size, int terms);

/// The RMS error of the K-term table against the HG table, relative to the table's RMS, both
/// weighted by the solid angles of the texel pairs (by reconstruction, not from the eigenvalues).
double phaseFactorError(const PhaseFactors& factors, double g);

}  // namespace lucent::prt
