#include "report/ShardMerge.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "report/CellVerdict.h"

namespace shaderbed {
namespace {

// "I/N" -> (I, N); (0, 0) when the part is no shard.
std::pair<int, int> shard_of(const std::string& text) {
  const size_t slash = text.find('/');
  int index = 0, count = 0;
  if (slash == std::string::npos) return {0, 0};
  std::from_chars(text.data(), text.data() + slash, index);
  std::from_chars(text.data() + slash + 1, text.data() + text.size(), count);
  return {index, count};
}

// The first tool of `part` whose version differs from `merged`'s (both known), or "". A GL-only
// job knows no Vulkan driver, so a version only one side has is no difference; it joins.
std::string join_tools(ToolVersions& merged, const ToolVersions& part) {
  const std::pair<const char*, std::string ToolVersions::*> tools[] = {
      {"glslang", &ToolVersions::glslang},           {"SPIRV-Tools", &ToolVersions::spirv_tools},
      {"SPIRV-Cross", &ToolVersions::spirv_cross},   {"the Vulkan driver", &ToolVersions::vulkan_driver},
      {"the GL driver", &ToolVersions::gl_driver},   {"LLVM", &ToolVersions::llvm},
      {"the Vulkan device", &ToolVersions::vulkan_device}, {"the GL platform", &ToolVersions::gl_platform}};
  for (const auto& [name, field] : tools) {
    std::string& have = merged.*field;
    const std::string& other = part.*field;
    if (other.empty()) continue;
    if (have.empty()) have = other;
    else if (have != other) return fmt::format("{} is {} here, {} in the files before it", name, other, have);
  }
  return "";
}

// Judges a cell read from a shard again from its own metrics and tolerance, by the rules the
// run judged it with (report/CellVerdict.h), so a hand-edited status cannot pass. A cell
// whose status disagrees becomes a failure that says so; returns that note ("" = agrees).
std::string rejudge(CellResult& r) {
  std::string said, found;
  if (r.status == CellStatus::pass || r.status == CellStatus::fail) {
    const std::vector<std::string> failures = rejudge_failures(r);
    if (r.status == CellStatus::pass && !failures.empty())
      said = "pass", found = fmt::format("its metrics fail: {}", fmt::join(failures, "; "));
    else if (r.status == CellStatus::fail && failures.empty())
      said = r.known_failure ? "known failure" : "fail", found = "its metrics pass";
    else if (r.status == CellStatus::fail && r.known_failure && r.known_reason.empty())
      // The expectations file is not in the results, but every entry of it has a reason.
      said = "known failure", found = "without the reason every expectation has";
  } else if (r.status == CellStatus::skipped &&
             (r.metrics.interior_pixels || r.metrics.covered_pixels || r.metrics.bad_pixels)) {
    // A skipped cell is never compared, so it has no pixels counted.
    said = "skipped", found = "it has the metrics of a compared cell";
  }
  if (said.empty()) return "";
  const std::string note = fmt::format("shard said {}; {}", said, found);
  r.status = CellStatus::fail;
  r.known_failure = false;
  r.known_reason.clear();
  r.message = r.message.empty() ? note : note + " (its message: " + r.message + ")";
  return note;
}

}  // namespace

Result<RunReport> merge_shards(std::vector<RunReport> parts, const std::vector<std::string>& paths,
                               std::vector<std::string>* rejudged) {
  RunReport merged;
  std::set<std::string> seen;
  std::map<int, std::string> shards;   // index -> the file that holds it
  int shard_count = 0;
  std::vector<std::string> interrupted;
  for (size_t i = 0; i < parts.size(); ++i) {
    RunReport& part = parts[i];
    const std::string& path = paths[i];
    const auto bad = [&](std::string message) {
      return std::unexpected(Error{.message = std::move(message), .file = path, .stage = ErrorStage::merge});
    };
    // Without an identity a file would join any run.
    if (part.run_id.empty())
      return bad("no run_id: not results as 'shaderbed run --json' writes them (or from a version before run ids); "
                 "merge the results of one run");
    if (merged.run_id.empty()) merged.run_id = part.run_id;
    else if (merged.run_id != part.run_id)
      return bad(fmt::format("run {} is not the run of the files before it ({}): another image size, mesh density, "
                             "precision, reference, --param or compiler; merge the results of one run",
                             part.run_id, merged.run_id));
    for (const auto& [name, digest] : part.case_digests)
      if (const auto [it, added] = merged.case_digests.emplace(name, digest); !added && it->second != digest)
        return bad(fmt::format("case {} was read from another case file than in the files before it (digest {}, "
                               "before {}); merge the results of one run",
                               name, digest, it->second));
    if (const std::string differs = join_tools(merged.tools, part.tools); !differs.empty())
      return bad(fmt::format("another toolchain: {}; merge the results of one run", differs));
    if (const auto [index, count] = shard_of(part.shard); count > 0) {
      if (shard_count && count != shard_count)
        return bad(fmt::format("shard {} is one of {}, the files before it of {}", part.shard, count, shard_count));
      shard_count = count;
      if (const auto [it, added] = shards.emplace(index, path); !added)
        return bad(fmt::format("shard {} is also in {}", part.shard, it->second));
    }
    if (part.interruption) interrupted.push_back(path + ": " + part.interruption->reason);
    merged.wall_ms += part.wall_ms;
    for (CellResult& r : part.results) {
      if (!seen.insert(r.id()).second) return bad("cell " + r.id() + " is already in an earlier file");
      if (const std::string note = rejudge(r); !note.empty() && rejudged)
        rejudged->push_back(fmt::format("{}: {}: {}", path, r.id(), note));
      merged.results.push_back(std::move(r));
    }
  }
  std::vector<std::string> missing;
  for (int i = 1; i <= shard_count; ++i)
    if (!shards.contains(i)) missing.push_back(fmt::format("{}/{}", i, shard_count));
  std::string incomplete;
  if (!missing.empty()) incomplete = fmt::format("shard{} {} missing", missing.size() > 1 ? "s" : "", fmt::join(missing, ", "));
  for (const std::string& line : interrupted) incomplete += (incomplete.empty() ? "" : "; ") + line;
  if (!incomplete.empty()) merged.interruption = Interruption{0, incomplete};
  std::stable_sort(merged.results.begin(), merged.results.end(),
                   [](const CellResult& a, const CellResult& b) { return a.id() < b.id(); });
  return merged;
}

}  // namespace shaderbed
