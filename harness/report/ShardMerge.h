#pragma once
// Joins the results of a run's shards (or a CI matrix's jobs) into one report in the
// canonical order of one whole run. Shards of different runs (another run id) are refused;
// a missing shard, or a shard that was interrupted, leaves the merged report incomplete
// (RunReport::interruption says which), so it cannot pass unnoticed.
#include <string>
#include <vector>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// `paths` name the parts in errors. A cell in two parts, or parts of different runs, is an
// Error; results written before run ids existed merge as before.
Result<RunReport> merge_shards(std::vector<RunReport> parts, const std::vector<std::string>& paths);

}  // namespace shaderbed
