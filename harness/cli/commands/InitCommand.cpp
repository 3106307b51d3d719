// `shaderbed init SHADER...`: a first case file for your own shaders (author/CaseDraft.h),
// then one run of it, and what still needs you.
#include <unistd.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "author/CaseDraft.h"
#include "author/ShaderSurvey.h"
#include "cli/commands/Command.h"
#include "core/AtomicFile.h"
#include "core/ThisExecutable.h"
#include "core/WritablePath.h"
#include "report/ConsoleProgress.h"
#include "report/ConsoleReport.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

struct InitArguments {
  std::vector<std::string> shaders;
  std::string out;
  std::string language;
  bool force = false;
  bool no_run = false;
  int size = 64;
};

int bad_input(const std::string& message) {
  fmt::print(stderr, "shaderbed init: {}\n", message);
  return kExitBadInput;
}

// The run's errors, each distinct message once (a missing binding errors every cell alike).
std::vector<std::string> distinct_errors(const RunReport& report) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const CellResult& cell : report.results)
    if (cell.status == CellStatus::error && seen.insert(cell.message).second)
      out.push_back(cell.language + ": " + cell.message);
  return out;
}

// Runs the new case once, small; prints its summary. The problems it found, for the list.
std::vector<std::string> check_run(const std::string& case_path, int size) {
  RunOptions options;
  options.select.cases = {case_path};
  options.cell.size = size;
  options.cell.timing = {.warmup = 0, .runs = 0};
  options.workers.worker_binary = this_executable().string();   // the user's shaders: a crash costs cells, not the command
  ConsoleProgress progress(stderr, isatty(STDERR_FILENO), false);
  options.on_cell = [&](size_t done, size_t total, const CellResult& cell) { progress.update(done, total, cell); };
  auto report = run_suite(options);
  if (!report) return {"the case does not load yet: " + report.error().to_string()};
  print_console_report(*report, stdout);
  std::vector<std::string> problems = distinct_errors(*report);
  // Failures, per language and attribution: "glsl: 16 cells differ (port: ...)".
  std::map<std::string, std::pair<int, std::string>> failed;
  for (const CellResult& cell : report->results)
    if (cell.status == CellStatus::fail) {
      auto& [count, why] = failed[cell.language];
      ++count;
      if (why.empty() && !cell.attribution.empty()) why = cell.attribution + ": " + cell.attribution_reason;
    }
  for (const auto& [language, entry] : failed)
    problems.push_back(language + ": " + std::to_string(entry.first) + " cell" + (entry.first == 1 ? "" : "s") +
                       " failed" + (entry.second.empty() ? "" : " (" + entry.second + ")") +
                       "; check its bindings and attributes");
  return problems;
}

int run_init(const InitArguments& args) {
  std::optional<Language> forced;
  if (!args.language.empty()) {
    auto l = parse_language(args.language);
    if (!l) return bad_input("--lang: " + l.error().message);
    forced = *l;
  }
  const fs::path first = args.shaders.front();
  const std::string out = fs::absolute(args.out.empty() ? first.parent_path() / (first.stem().string() + ".toml")
                                                        : fs::path(args.out))
                              .lexically_normal()
                              .string();
  std::error_code ec;
  if (fs::exists(out, ec) && !args.force)
    return bad_input(out + " exists; init does not overwrite a case file (--force rewrites it)");
  if (auto ok = check_writable_file(out, "--out"); !ok) return bad_input(ok.error().to_string());

  auto languages = survey_shaders(args.shaders, forced);
  if (!languages) return bad_input(languages.error().to_string());
  const CaseDraft draft = draft_case(*languages, out, images_in(fs::absolute(first).parent_path().string()));
  if (auto ok = write_file_atomically(out, draft.text, "case file"); !ok) return bad_input(ok.error().to_string());
  fmt::print("wrote {}\n", out);

  std::vector<std::string> problems;
  if (!args.no_run) {
    fmt::print("checking it: shaderbed run --case {} --size {}\n", out, args.size);
    std::fflush(stdout);
    problems = check_run(out, args.size);
  }
  if (draft.todos.empty() && problems.empty()) {
    fmt::print("\nnothing left to guess{}\n", args.no_run ? " (not run: --no-run)" : ": every cell ran");
    return 0;
  }
  fmt::print("\nstill needs you ({}):\n", out);
  for (const std::string& todo : draft.todos) fmt::print("  TODO {}\n", todo);
  for (const std::string& problem : problems) fmt::print("  run: {}\n", problem);
  return kExitFail;
}

}  // namespace

Command add_init_command(CLI::App& app) {
  auto args = std::make_shared<InitArguments>();
  CLI::App* cmd = app.add_subcommand(
      "init",
      "Write a case file for your own shaders and run it once. Reads each shader's reflection (and a DX9 effect's "
      "techniques), guesses every uniform's binding from its name, semantic, register and type with a comment saying "
      "why, maps GLSL vertex inputs by name, and marks what it cannot guess with TODO (commented out, so the case "
      "still loads). The case is differential: the first language given is the reference every backend, path and "
      "port is compared with. Exit 0: written, nothing left to guess and every cell ran; 1: written, but TODOs or "
      "run errors remain (listed under \"still needs you\"); 2: bad input (a missing shader, an unknown extension, "
      "no entry point, an existing case without --force)");
  cmd->add_option("shaders", args->shaders,
                  "Shader files: .hlsl/.fx/.fxh (hlsl), .cg (cg), .vert/.frag/.glsl/.vs/.fs (glsl; a vertex and a "
                  "fragment file). Several languages = the original first, then its ports")
      ->required();
  cmd->add_option("--out", args->out, "Case file to write (default: <first shader's stem>.toml next to it)");
  cmd->add_flag("--force", args->force, "Overwrite an existing case file");
  cmd->add_option("--lang", args->language, "Read every file as this language (hlsl, cg, glsl), whatever its extension");
  cmd->add_flag("--no-run", args->no_run, "Write the case only; do not run it");
  cmd->add_option("--size", args->size, "Image size of the check run, in pixels")->capture_default_str()->check(CLI::Range(8, 4096));
  return {cmd, [args] { return run_init(*args); }};
}

}  // namespace shaderbed
