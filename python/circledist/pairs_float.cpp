// The float instantiations of every pair and policy (one translation unit per precision).
#include "pairs.hpp"

namespace circledist::python {
void register_float(PairTables& t) { register_precision<float>(t.table[kFloat]); }
}  // namespace circledist::python
