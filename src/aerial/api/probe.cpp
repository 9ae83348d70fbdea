// aerial::Probe (include/aerial/probe.h) over ProbeTables.
#include "aerial/api/impl.h"
#include "aerial/probe.h"
#include "aerial/probe/table_probe.h"

namespace aerial {

std::vector<ProbeResult> Probe(const Tables& tables, std::span<const ProbeQuery> queries) {
  return ProbeTables(tables.impl().tables(), queries);
}

}  // namespace aerial
