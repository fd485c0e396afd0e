/// @file lucentSmpFor.h
/// @brief vtkSMPTools as the technique layer's parallel loop (lucent/util/parallel.hpp), for every
/// VTK module that runs a technique.
#ifndef lucentSmpFor_h
#define lucentSmpFor_h

#include <cstddef>

#include <vtkSMPTools.h>

#include <lucent/util/parallel.hpp>

namespace lucent::vtkadapter {

inline void smpFor(std::size_t n, const lucent::util::RangeBody& body) {
  vtkSMPTools::For(vtkIdType(0), vtkIdType(n), [&](vtkIdType begin, vtkIdType end) {
    body(std::size_t(begin), std::size_t(end));
  });
}

}  // namespace lucent::vtkadapter

#endif
