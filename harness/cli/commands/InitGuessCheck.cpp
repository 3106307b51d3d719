#include "cli/commands/InitGuessCheck.h"

#include <unistd.h>

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "core/AtomicFile.h"
#include "core/ThisExecutable.h"
#include "report/ConsoleProgress.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

bool no_reference(const CellResult& cell) {
  return cell.status == CellStatus::error && cell.message.find("is no reference") != std::string::npos;
}

GuessRunScore score_of(const RunReport& report) {
  GuessRunScore s{.loads = true, .cells = report.results.size()};
  for (const CellResult& cell : report.results) {
    s.rmse += cell.metrics.rmse;
    s.no_reference += no_reference(cell);
    const bool passed = cell.status == CellStatus::pass || cell.status == CellStatus::skipped ||
                        (cell.status == CellStatus::fail && cell.known_failure);
    if (passed) continue;
    ++s.not_passed;
    if (auto l = parse_language(cell.language); l && std::find(s.failing.begin(), s.failing.end(), *l) == s.failing.end())
      s.failing.push_back(*l);
  }
  return s;
}

// A valid original first, then fewer cells that disagree, then (all else equal) a clearly
// smaller error: a switch must earn its place.
bool better(const GuessRunScore& a, const GuessRunScore& b) {
  if (a.loads != b.loads) return a.loads;
  if (a.no_reference != b.no_reference) return a.no_reference < b.no_reference;
  if (a.not_passed != b.not_passed) return a.not_passed < b.not_passed;
  return a.not_passed > 0 && a.rmse < 0.5 * b.rmse;
}

std::string lines_text(const std::vector<int>& lines) {
  std::string s = lines.size() == 1 ? "line " : "lines ";
  for (size_t i = 0; i < lines.size(); ++i) s += (i ? ", " : "") + std::to_string(lines[i]);
  return s;
}

struct Trial {
  CaseDraft draft;
  std::optional<RunReport> report;
  std::string load_error;
  GuessRunScore score;
};

class Checker {
 public:
  explicit Checker(const GuessCheckInput& input) : input_(input) {}

  Result<Trial> run(const std::map<std::string, std::string>& switched, bool progress) {
    Trial t{.draft = draft_case(input_.languages, input_.case_path, input_.images, switched), .report = {}, .load_error = "",
            .score = {}};
    if (auto ok = write_file_atomically(input_.case_path, t.draft.text, "case file"); !ok) return std::unexpected(ok.error());
    RunOptions options;
    options.select.cases = {input_.case_path};
    options.cell.size = input_.size;
    options.cell.timing = {.warmup = 0, .runs = 0};
    options.workers.worker_binary = this_executable().string();   // the user's shaders: a crash costs cells, not the command
    ConsoleProgress console(stderr, isatty(STDERR_FILENO), false);
    if (progress) options.on_cell = [&](size_t done, size_t total, const CellResult& cell) { console.update(done, total, cell); };
    auto report = run_suite(options);
    if (!report) {
      t.load_error = report.error().to_string();
      return t;
    }
    t.score = score_of(*report);
    t.report = std::move(*report);
    return t;
  }

 private:
  const GuessCheckInput& input_;
};

// Whether a doubt could explain what the run shows: the original's guesses decide every
// comparison; a port's only its own cells.
bool may_explain(const GuessDoubt& d, const GuessRunScore& s, Language original) {
  if (s.all_pass()) return false;
  if (d.language == original) return true;
  return s.no_reference == 0 && std::find(s.failing.begin(), s.failing.end(), d.language) != s.failing.end();
}

}  // namespace

std::string GuessRunScore::text() const {
  if (!loads) return "the case does not load";
  if (no_reference) return fmt::format("the original drew no valid reference ({} of {} cells judged nothing)", no_reference, cells);
  if (!not_passed) return fmt::format("all {} cells pass", cells);
  return fmt::format("{} of {} cells do not pass", not_passed, cells);
}

Result<GuessCheck> check_guesses(const GuessCheckInput& input) {
  Checker checker(input);
  std::map<std::string, std::string> switched;
  auto first = checker.run(switched, true);
  if (!first) return std::unexpected(first.error());
  Trial best = std::move(*first);
  GuessCheck out;
  const Language original = input.languages.front().language;
  std::set<std::string> confirmed;
  // Each doubt once, in the order the case lists them (the original's first); a switch kept
  // changes what the later ones are judged against.
  for (size_t k = 0; k < best.draft.doubts.size(); ++k) {
    const GuessDoubt doubt = best.draft.doubts[k];
    if (!best.score.loads || !may_explain(doubt, best.score, original)) continue;
    fmt::print("checking a guess ({}): {} instead of {}\n", lines_text(doubt.lines), doubt.instead, doubt.guessed);
    std::fflush(stdout);
    std::map<std::string, std::string> trial_switch = switched;
    const std::string why = "with " + doubt.guessed + ", " + best.score.text();
    trial_switch[doubt.id] = why;
    auto trial = checker.run(trial_switch, false);
    if (!trial) return std::unexpected(trial.error());
    const std::string outcome = "before, " + best.score.text() + "; after, " + trial->score.text();
    if (better(trial->score, best.score)) {
      // A valid original or fewer disagreeing cells confirm the switch; a smaller error alone does not.
      if (trial->score.no_reference < best.score.no_reference || trial->score.not_passed < best.score.not_passed)
        confirmed.insert(doubt.id);
      out.changed.push_back(fmt::format("{}: {} now bound as `{}` instead of {}: {}", lines_text(doubt.lines), doubt.uniforms,
                                        doubt.instead, doubt.guessed, outcome));
      switched = std::move(trial_switch);
      best = std::move(*trial);
    } else {
      out.tried.push_back(fmt::format("{}: {} as `{}` did not help ({}), so kept as guessed ({})", lines_text(doubt.lines),
                                      doubt.uniforms, doubt.instead, trial->score.text(), doubt.guessed));
    }
  }
  // The last run may have been a trial not kept: write the kept case back.
  if (auto ok = write_file_atomically(input.case_path, best.draft.text, "case file"); !ok) return std::unexpected(ok.error());

  if (!best.score.all_pass()) {
    for (const GuessDoubt& d : best.draft.doubts)
      if (!confirmed.contains(d.id) && may_explain(d, best.score, original))
        out.check_first.push_back(
            d.switched ? fmt::format("{}: {}: switched by init's check (it lowered the error), still not confirmed",
                                     lines_text(d.lines), d.uniforms)
                       : fmt::format("{}: {}: {}, a guess no run confirmed (switching to `{}` did not help)",
                                     lines_text(d.lines), d.uniforms, d.guessed, d.instead));
    for (const std::string& todo : best.draft.todos) out.check_first.push_back("TODO " + todo);
  }
  out.draft = std::move(best.draft);
  out.report = std::move(best.report);
  out.load_error = std::move(best.load_error);
  out.score = best.score;
  return out;
}

}  // namespace shaderbed
