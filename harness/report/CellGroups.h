#pragma once
// One mistake, one entry: cells whose report text is the same once each cell's own
// identity is taken out (a bad binding fails alike on every backend, path and shape) are
// listed together with a count, instead of once per cell.
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed {

// `text` with what names the cell itself replaced by placeholders: its
// language-backend-path file stem, its backend/path and its shape (as a word). Two cells'
// texts that are equal after this differ only by which cell they are about.
std::string without_cell_identity(std::string text, const CellResult& r);

// What a failure is, without which cell it is and without its numbers: case, variant and
// language, how it ended (failed, known, error), the message with the cell's identity and
// every number taken out ("interior max error # > #"), the attribution, the name of the
// fitting explanation and the line where a port departs. A bug in one shader fails its 12
// cells (3 paths x 4 shapes) with different maxima but one key; the HTML report shows them
// as one card, the console as one entry.
std::string failure_key(const CellResult& r);

// Cells with the same case and the same key, in first-seen order (key_of(r) should
// already be without_cell_identity).
template <class KeyOf>
std::vector<std::vector<const CellResult*>> group_cells(const std::vector<const CellResult*>& cells, KeyOf&& key_of);

// Who a group is about: "case variant language" with every variant and language it
// spans ("lambert pixel, vertex hlsl").
std::string group_where(const std::vector<const CellResult*>& cells);

// Which cells, compactly: "12 cells: vulkan/spirv, gl/spirv, gl/cross × cone, cube, sphere,
// torus" when they are every path of group_where() on every shape; else the cells by
// path: "3 cells: pixel hlsl vulkan/spirv cone, cube; vertex glsl gl/glsl sphere".
std::string group_cells_text(const std::vector<const CellResult*>& cells);

// ---- implementation --------------------------------------------------------------------

template <class KeyOf>
std::vector<std::vector<const CellResult*>> group_cells(const std::vector<const CellResult*>& cells, KeyOf&& key_of) {
  std::vector<std::vector<const CellResult*>> groups;
  std::vector<std::string> keys;
  for (const CellResult* r : cells) {
    const std::string key = r->case_name + '\x1f' + key_of(*r);
    size_t i = 0;
    while (i < keys.size() && keys[i] != key) ++i;
    if (i == keys.size()) {
      keys.push_back(key);
      groups.emplace_back();
    }
    groups[i].push_back(r);
  }
  return groups;
}

}  // namespace shaderbed
