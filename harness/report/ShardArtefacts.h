#pragma once
// `merge --html` shows the images and sources a shard's cells name, and a shard is a file
// anyone can edit: an artefact path may name any file on the machine. Each path is
// resolved inside the shard's own folder (the folder its results file is in, where
// `run --out DIR --json DIR/x.json` and a CI artifact put the images); what resolves
// elsewhere (an absolute path, `../`, a symlink out) is dropped, never read.
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed {

// Rewrites every artefact path of `r` (from the shard `results_file`, whose recorded run
// folder is `out_dir`) to the canonical path it resolves to inside the shard's folder, or
// to "" when it resolves outside. A relative path is tried under the shard's folder, then
// with the run folder's prefix taken off (`out/case/x.png` of a shard in `out/`), then from
// the current folder. Returns the dropped paths as "FILE: PATH".
std::vector<std::string> confine_artefacts(CellResult& r, const std::string& results_file, const std::string& out_dir);

}  // namespace shaderbed
