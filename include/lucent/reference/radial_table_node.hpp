#pragma once
/// @file radial_table_node.hpp
/// @brief One node of a radial table as one 32-byte record: the three channels' values and the
/// slopes to the next node, so that a term's linear lookup is one aligned load.
#include <cstddef>

namespace lucent::reference {

struct alignas(32) RadialTableNode {
  float value[3] = {0, 0, 0};
  float slope[3] = {0, 0, 0};  ///< value at the next node minus this one's (0 at the last)
  float unused[2] = {0, 0};
};
static_assert(sizeof(RadialTableNode) == 32, "a node is one 256-bit load");

/// Terms summed in float before their sum is added in double (every table sum's numerics).
constexpr std::size_t kTableSumBlock = 1024;

}  // namespace lucent::reference
