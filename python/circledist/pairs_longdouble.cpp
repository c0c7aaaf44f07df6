// The long double instantiations of every pair and policy (one translation unit per precision).
#include "pairs.hpp"

namespace circledist::python {
void register_long_double(PairTables& t) { register_precision<long double>(t.table[kLongDouble]); }
}  // namespace circledist::python
