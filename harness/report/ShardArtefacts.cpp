#include "report/ShardArtefacts.h"

#include <filesystem>

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

// `path` (made canonical as far as it exists) when it lies inside `root` (canonical), else "".
fs::path inside(const fs::path& path, const fs::path& root) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return {};
  const fs::path rel = canonical.lexically_relative(root);
  if (rel.empty() || rel.is_absolute() || *rel.begin() == "..") return {};
  return canonical;
}

}  // namespace

std::vector<std::string> confine_artefacts(CellResult& r, const std::string& results_file, const std::string& out_dir) {
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(fs::absolute(fs::path(results_file), ec).parent_path(), ec);
  std::vector<std::string> dropped;
  CellArtefacts& a = r.artefacts;
  for (std::string* field : {&a.render_exr, &a.render_png, &a.error_exr, &a.error_png, &a.reference_png, &a.vertex_spirv,
                             &a.fragment_spirv, &a.vertex_cross_glsl, &a.fragment_cross_glsl, &a.stored_exr}) {
    if (field->empty()) continue;
    const fs::path recorded(*field);
    std::vector<fs::path> candidates;
    if (recorded.is_absolute()) {
      candidates.push_back(recorded);
    } else {
      candidates.push_back(root / recorded);
      if (!out_dir.empty())
        if (const fs::path under = recorded.lexically_relative(fs::path(out_dir));
            !under.empty() && *under.begin() != ".." && !under.is_absolute())
          candidates.push_back(root / under);
      candidates.push_back(fs::absolute(recorded, ec));
    }
    // The first that exists inside the folder; else the first that would be inside (the
    // page shows it as missing); else none.
    fs::path found, missing;
    for (const fs::path& c : candidates) {
      const fs::path in = inside(c, root);
      if (in.empty()) continue;
      if (fs::exists(in, ec)) {
        found = in;
        break;
      }
      if (missing.empty()) missing = in;
    }
    if (found.empty()) found = missing;
    if (found.empty()) dropped.push_back(results_file + ": " + *field);
    *field = found.string();
  }
  return dropped;
}

}  // namespace shaderbed
