// `shaderbed init SHADER...`: a first case file for your own shaders (author/CaseDraft.h),
// then one run of it, and what still needs you.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "author/CaseDraft.h"
#include "author/ShaderSurvey.h"
#include "cli/commands/InitGuessCheck.h"
#include "cli/commands/Command.h"
#include "compile/IsolatedCompile.h"
#include "core/AtomicFile.h"
#include "core/WritablePath.h"
#include "report/ConsoleReport.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

struct InitArguments {
  std::vector<std::string> shaders;
  std::string out;
  std::string language;
  std::vector<std::string> defines;        // NAME or NAME=VALUE
  std::vector<std::string> include_dirs;
  bool force = false;
  bool no_run = false;
  int size = 64;
};

int bad_input(const std::string& message) {
  fmt::print(stderr, "shaderbed: init: {}\n", message);
  return kExitBadInput;
}

// The run's errors, each distinct message once (a missing binding errors every cell alike;
// a blank original errors them with each shape's pixel counts after the first ';').
std::vector<std::string> distinct_errors(const RunReport& report) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const CellResult& cell : report.results)
    if (cell.status == CellStatus::error && seen.insert(cell.language + cell.message.substr(0, cell.message.find(';'))).second)
      out.push_back(cell.language + ": " + cell.message);
  return out;
}

// Failures, per language and attribution: "glsl: 16 cells failed (port: ...)". While a
// guess is unconfirmed the run's attribution is no verdict: the cells say so instead.
std::vector<std::string> failures(const RunReport& report, bool unconfirmed) {
  std::map<std::string, std::pair<int, std::string>> failed;
  for (const CellResult& cell : report.results)
    if (cell.status == CellStatus::fail && !cell.known_failure) {
      auto& [count, why] = failed[cell.language];
      ++count;
      if (why.empty() && !cell.attribution.empty()) why = cell.attribution + ": " + cell.attribution_reason;
    }
  std::vector<std::string> out;
  for (const auto& [language, entry] : failed)
    out.push_back(language + ": " + std::to_string(entry.first) + " cell" + (entry.first == 1 ? "" : "s") + " failed" +
                  (unconfirmed || entry.second.empty() ? "" : " (" + entry.second + ")") +
                  (unconfirmed ? "; no verdict on the port until the bindings above are checked"
                               : "; check its bindings and attributes"));
  return out;
}

int run_init(const InitArguments& args) {
  isolate_compiles();   // the survey compiles the user's shaders: a glslang crash is bad input, not ours
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
  // Not even --force writes over a shader given to read (`init x.toml` names its case x.toml).
  if (auto ok = check_not_an_input(out, "--out", args.shaders); !ok) return bad_input(ok.error().to_string());
  std::error_code ec;
  if (fs::exists(out, ec) && !args.force)
    return bad_input(out + " exists; init does not overwrite a case file (--force rewrites it)");
  if (auto ok = check_writable_file(out, "--out"); !ok) return bad_input(ok.error().to_string());

  SurveyPreprocessor preprocessor;
  for (const std::string& d : args.defines) {
    const size_t eq = d.find('=');
    preprocessor.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  for (const std::string& dir : args.include_dirs) {
    if (!fs::is_directory(dir, ec)) return bad_input("--include-dir: no such folder: " + dir);
    preprocessor.include_dirs.push_back(fs::absolute(dir).lexically_normal().string());
  }
  auto languages = survey_shaders(args.shaders, forced, preprocessor);
  if (!languages) return bad_input(languages.error().to_string());
  const std::vector<std::string> images = images_in(fs::absolute(first).parent_path().string());
  if (args.no_run) {
    const CaseDraft draft = draft_case(*languages, out, images);
    if (auto ok = write_file_atomically(out, draft.text, "case file"); !ok) return bad_input(ok.error().to_string());
    fmt::print("wrote {}\n", out);
    if (draft.todos.empty()) {
      fmt::print("\nnothing left to guess (not run: --no-run)\n");
      return 0;
    }
    fmt::print("\nstill needs you ({}):\n", out);
    for (const std::string& todo : draft.todos) fmt::print("  TODO {}\n", todo);
    return kExitFail;
  }

  fmt::print("wrote {}\nchecking it: shaderbed run --case {} --size {}\n", out, out, args.size);
  std::fflush(stdout);
  auto check = check_guesses({.languages = *languages, .case_path = out, .images = images, .size = args.size});
  if (!check) return bad_input(check.error().to_string());
  const bool unconfirmed = !check->check_first.empty();
  std::vector<std::string> problems;
  if (check->report) {
    RunReport shown = *check->report;
    // No verdict against the port while init's own guesses may be what differs.
    if (unconfirmed)
      for (CellResult& cell : shown.results)
        if (cell.status == CellStatus::fail && !cell.attribution.empty()) {
          cell.attribution = "unconfirmed bindings";
          cell.attribution_reason = "init's guesses are not confirmed: check these bindings first (listed below)";
        }
    print_console_report(shown, stdout);
    problems = distinct_errors(*check->report);
    for (std::string& f : failures(*check->report, unconfirmed)) problems.push_back(std::move(f));
  } else {
    problems.push_back("the case does not load yet: " + check->load_error);
  }
  if (!check->changed.empty()) {
    fmt::print("\ninit's check changed {} of its guesses ({}):\n", check->changed.size(), out);
    for (const std::string& c : check->changed) fmt::print("  {}\n", c);
  }
  for (const std::string& t : check->tried) fmt::print("  tried: {}\n", t);
  if (problems.empty() && check->draft.todos.empty()) {
    fmt::print("\nnothing left to guess: every cell ran and passed\n");
    return 0;
  }
  fmt::print("\nstill needs you ({}):\n", out);
  if (unconfirmed) {
    fmt::print("  check these bindings first:\n");
    for (const std::string& line : check->check_first) fmt::print("    {}\n", line);
  } else {
    for (const std::string& todo : check->draft.todos) fmt::print("  TODO {}\n", todo);
  }
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
  cmd->add_option("-D,--define", args->defines,
                  "A preprocessor define for every shader, NAME or NAME=VALUE (the case's `defines`)");
  cmd->add_option("-I,--include-dir", args->include_dirs,
                  "A folder #include searches after the including file's (the case's `include_dirs`)");
  cmd->add_option("--size", args->size, "Image size of the check run, in pixels")->capture_default_str()->check(CLI::Range(8, 4096));
  return {cmd, [args] { return run_init(*args); }};
}

}  // namespace shaderbed
