// One precision and root policy of every pair (pairs.hpp, CIRCLEDIST_PAIR_UNITS): CMakeLists.txt
// compiles this file once per unit, naming it by CIRCLEDIST_UNIT_REAL and CIRCLEDIST_UNIT_ROOTS,
// so the units build in parallel and none holds more than its share.
#include "pairs.hpp"

namespace circledist::python {
template void register_pairs<CIRCLEDIST_UNIT_REAL, CIRCLEDIST_UNIT_ROOTS>(PairTables&);
}  // namespace circledist::python
