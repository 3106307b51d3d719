#pragma once
// `shaderbed explain`: one cell of a case drawn and judged as `run` does (in this process),
// then one of its pixels executed line by line by the shader's double twin
// (run/CellDivergence.h), with the cell's divergence when it fails.
#include <optional>
#include <string>

#include "core/Error.h"
#include "report/Results.h"
#include "run/CellDivergence.h"
#include "run/RunOptions.h"

namespace shaderbed {

struct ExplainedCell {
  CellResult cell;
  PixelExplanation pixel;
};

// `cell`: "variant/language/backend/path/shape", or the whole id with the case first.
// options.select names the case (and its folder); the cell's parts become its filters.
Result<ExplainedCell> explain_cell(RunOptions options, const std::string& cell, std::optional<twin::PixelAt> pixel);

}  // namespace shaderbed
