// condition ? if_true : if_false, without a jump.
//
// Why: over a batch the conditions of a closed-form query (which axis a frame starts from, which
// side of a rim a point lies) are as often true as false, and a mispredicted jump costs about as
// much as the arithmetic of a point query. GCC 12 compiles a conditional expression between two
// computed doubles into a jump; an index into a pair of values it cannot (a store and a load,
// which the processor forwards). Exact for every value, infinities and NaN included, unlike a
// blend by products with 0 and 1.
#pragma once

#include "../primitives.hpp"  // CIRCLEDIST_INLINE

namespace circledist::detail {

template <class Real> CIRCLEDIST_INLINE Real select(bool condition, Real if_true, Real if_false) {
  const Real choices[2] = {if_false, if_true};
  return choices[condition];
}

}  // namespace circledist::detail
