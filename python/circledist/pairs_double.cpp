// The double instantiations of every pair and policy (one translation unit per precision).
#include "pairs.hpp"

namespace circledist::python {
void register_double(PairTables& t) { register_precision<double>(t.table[kDouble]); }
}  // namespace circledist::python
