#include "stats/Collect.h"

#include <algorithm>
#include <filesystem>
#include <future>
#include <thread>

#include <fmt/format.h>

#include "compile/SpirvTools.h"
#include "compile/ToolVersions.h"
#include "scene/CaseFile.h"
#include "scene/CaseProgram.h"
#include "scene/NameFilter.h"
#include "stats/OpcodeClass.h"
#include "stats/nir/NirDump.h"

namespace shaderbed::stats {
namespace {

namespace fs = std::filesystem;

int count_lines(const std::string& text) {
  int n = int(std::count(text.begin(), text.end(), '\n'));
  return n + (!text.empty() && text.back() != '\n' ? 1 : 0);
}

}  // namespace

Result<StatsEntry> stage_stats(const CompiledProgram& program, Stage stage) {
  const ShaderModule& m = stage == Stage::vertex ? program.vertex : program.fragment;
  StatsEntry e;
  e.language = to_string(program.language);
  e.stage = to_string(stage);
  auto plain = count_spirv(m.spirv);
  if (!plain) return std::unexpected(plain.error());
  e.spirv = *plain;
  for (auto [level, out] : {std::pair{OptimizeLevel::performance, &e.spirv_opt}, {OptimizeLevel::size, &e.spirv_os}}) {
    auto optimized = optimize_spirv(m.spirv, Target::vulkan, level);
    if (!optimized) return std::unexpected(optimized.error());
    auto counts = count_spirv(*optimized);
    if (!counts) return std::unexpected(counts.error());
    *out = *counts;
  }
  e.glsl_lines = count_lines(stage == Stage::vertex ? program.vertex_cross_glsl : program.fragment_cross_glsl);
  return e;
}

// A compiled program whose two entries (vertex at `first`, fragment next) await NIR counts.
struct PendingNir {
  size_t first;
  CompiledProgram program;
};

// Each reading is a child process that mostly waits on LLVM: run as many at once as
// there are cores. A backend whose method gives nothing leaves its note, not zeros.
void read_driver_counts(const std::vector<PendingNir>& programs, const StatsOptions& options, StatsReport& report,
                        const std::function<void(const std::string&)>& step_done) {
  struct Job {
    const PendingNir* pending;
    NirBackend backend;
  };
  std::vector<Job> jobs;
  for (const PendingNir& p : programs)
    for (NirBackend b : {NirBackend::vulkan, NirBackend::gl}) jobs.push_back({&p, b});
  const size_t width = std::max(2u, std::thread::hardware_concurrency());
  for (size_t start = 0; start < jobs.size(); start += width) {
    std::vector<std::future<Result<NirProgramCounts>>> running;
    for (size_t j = start; j < std::min(jobs.size(), start + width); ++j)
      running.push_back(std::async(std::launch::async, [&, j] {
        return nir_counts(jobs[j].pending->program, NirRequest{.backend = jobs[j].backend,
                                                               .gl_platform = options.gl_platform,
                                                               .gl_device = options.gl_device});
      }));
    for (size_t j = start; j < std::min(jobs.size(), start + width); ++j) {
      auto counts = running[j - start].get();
      const StatsEntry& first = report.entries[jobs[j].pending->first];
      step_done(fmt::format("{}/{}/{} NIR {}", first.case_name, first.variant, first.language, to_string(jobs[j].backend)));
      for (Stage stage : {Stage::vertex, Stage::fragment}) {
        StatsEntry& e = report.entries[jobs[j].pending->first + (stage == Stage::fragment ? 1 : 0)];
        if (!e.nir) e.nir = NirStats{};
        std::optional<NirCounts>& slot = jobs[j].backend == NirBackend::vulkan ? e.nir->vulkan : e.nir->gl;
        if (counts) {
          const auto& c = (*counts)[stage];
          slot = NirCounts{c.alu, c.tex, c.control};
        } else {
          e.nir->note += (e.nir->note.empty() ? "" : "; ") + std::string(to_string(jobs[j].backend)) + ": " +
                         counts.error().message;
        }
      }
    }
  }
}

Result<StatsReport> collect_stats(const StatsOptions& o) {
  auto files = list_case_files(o.cases_dir);
  if (!files) return std::unexpected(files.error());
  std::vector<std::string> case_names;
  for (const std::string& f : *files) case_names.push_back(fs::path(f).stem().string());
  if (auto ok = check_names(o.cases, case_names, "case"); !ok) return std::unexpected(ok.error());
  if (auto ok = check_names(o.languages, {"glsl", "hlsl", "cg"}, "language"); !ok) return std::unexpected(ok.error());

  StatsReport report;
  const CompilerVersions v = compiler_versions();
  report.tool = {{"glslang", v.glslang}, {"spirv_tools", v.spirv_tools}, {"spirv_cross", v.spirv_cross},
                 {"spirv_grammar", grammar_version()}};
  // The programs first, so progress can say how many steps there are.
  struct Program {
    const Case* c;
    const Variant* variant;
    Language language;
  };
  std::vector<Case> loaded;
  for (const std::string& f : *files) {
    if (!wanted(o.cases, fs::path(f).stem().string())) continue;
    auto c = load_case(f);
    if (!c) return std::unexpected(c.error());
    loaded.push_back(std::move(*c));
  }
  std::vector<std::string> variant_names;
  std::vector<Program> selected;
  for (const Case& c : loaded)
    for (const Variant& variant : c.variants) {
      if (std::find(variant_names.begin(), variant_names.end(), variant.name) == variant_names.end())
        variant_names.push_back(variant.name);
      if (!wanted(o.variants, variant.name)) continue;
      for (Language language : {Language::hlsl, Language::cg, Language::glsl})
        if (wanted(o.languages, to_string(language)) && variant.shaders.contains(language))
          selected.push_back({&c, &variant, language});
    }
  const size_t steps = selected.size() * (o.nir ? 3 : 1);   // a compile, then a NIR read per backend
  size_t done = 0;
  auto step_done = [&](const std::string& what) {
    if (o.on_step) o.on_step(++done, steps, what);
  };

  std::vector<PendingNir> programs;
  for (const auto& [c, variant_ptr, language] : selected) {
    const Variant& variant = *variant_ptr;
    auto source = load_case_program(language, variant.shaders.at(language), c->path);
    Result<CompiledProgram> program = source ? compile_program(*source) : std::unexpected(source.error());
    for (Stage stage : {Stage::vertex, Stage::fragment}) {
      StatsEntry e;
      if (program) {
        auto s = stage_stats(*program, stage);
        if (s) e = std::move(*s);
        else e.error = s.error().to_string();
      } else {
        e.error = program.error().to_string();
      }
      e.case_name = c->name;
      e.variant = variant.name;
      e.language = to_string(language);
      e.stage = to_string(stage);
      e.book = book_count(e.case_name, e.variant, e.stage);
      report.entries.push_back(std::move(e));
    }
    if (program && o.nir) programs.push_back({report.entries.size() - 2, std::move(*program)});
    if (!program && o.nir) done += 2;   // nothing for the driver to read: its two steps are done
    step_done(fmt::format("{}/{}/{}", c->name, variant.name, to_string(language)));
  }
  read_driver_counts(programs, o, report, step_done);
  if (auto ok = check_names(o.variants, variant_names, "variant"); !ok) return std::unexpected(ok.error());
  return report;
}

}  // namespace shaderbed::stats
