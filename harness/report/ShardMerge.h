#pragma once
// Joins the results of a run's shards (or a CI matrix's jobs) into one report in the
// canonical order of one whole run. Shards of different runs (another run id), or without a
// run id, are refused; a missing shard, or a shard that was interrupted, leaves the merged
// report incomplete (RunReport::interruption says which), so it cannot pass unnoticed. Each
// compared cell is judged again from its metrics and tolerance (report/CellVerdict.h): a
// status that disagrees with them (an edited file) becomes a failure that says so.
#include <string>
#include <vector>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// `paths` name the parts in errors. A cell in two parts, parts of different runs, or a part
// without a run id, is an Error. `rejudged` (when given) receives one line per cell whose
// status disagreed with its metrics: "FILE: CELL: shard said pass; its metrics fail: ...".
Result<RunReport> merge_shards(std::vector<RunReport> parts, const std::vector<std::string>& paths,
                               std::vector<std::string>* rejudged = nullptr);

}  // namespace shaderbed
