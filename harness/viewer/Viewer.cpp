#include "viewer/Viewer.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <deque>
#include <filesystem>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/Elapsed.h"
#include "reference/ModelRegistry.h"
#include "run/ParameterOverrides.h"
#include "run/Runner.h"
#include "viewer/FileWatcher.h"
#include "twin/PixelListing.h"
#include "viewer/FrameWorker.h"
#include "viewer/InspectionPanel.h"
#include "viewer/Screenshot.h"
#include "viewer/SplitView.h"
#include "viewer/ViewerWindow.h"
#include "viewer/VulkanPresenter.h"

namespace shaderbed::viewer {
namespace fs = std::filesystem;
namespace {


constexpr double kPollSeconds = 0.2;   // how often the files are looked at (reload within a second)

// The case the options name, checked as `run` checks it (names, parameters, model, size).
Result<Case> load_view_case(const ViewerOptions& o) {
  std::string name = o.case_name;
  if (name.empty()) {
    auto files = list_case_files(o.cases_dir);
    if (!files) return std::unexpected(files.error());
    if (files->empty()) return fail(ErrorStage::options, "no case files in " + o.cases_dir);
    const bool phong = std::ranges::any_of(*files, [](const std::string& f) { return fs::path(f).stem() == "phong"; });
    name = phong ? "phong" : fs::path(files->front()).stem().string();
  }
  RunOptions run;
  run.select.cases_dir = o.cases_dir;
  run.select.cases = {name};
  run.select.params = o.params;
  run.cell.size = o.size;
  auto plan = plan_suite(run);
  if (!plan) return std::unexpected(plan.error());
  return std::move((*plan)->cases.front());
}

// The case file again, after it changed on disk, with the command line's --param.
Result<Case> reload_case(const std::string& path, const std::vector<std::string>& params) {
  auto loaded = load_case(path);
  if (!loaded) return std::unexpected(loaded.error());
  std::vector<Case> cases{std::move(*loaded)};
  if (auto ok = apply_parameter_overrides(params, {}, cases); !ok) return std::unexpected(ok.error());
  const Case& c = cases.front();
  if (!c.differential() && !reference::find_model(c.model))
    return std::unexpected(Error{.message = "unknown model '" + c.model + "'", .file = c.path, .line = c.model_line,
                                 .stage = ErrorStage::case_file});
  return std::move(cases.front());
}

std::string verdict_text(const Frame& f) {
  if (f.verdict == "pass" || f.verdict == "fail")
    return fmt::format("{}, max {:.3g} ({:.3g} of tol)", f.verdict, f.max_error, f.tolerance_share);
  if (f.verdict == "not judged" && f.reference)
    return fmt::format("not judged ({}), max {:.3g}", f.detail.substr(0, f.detail.find(':')), f.max_error);
  return f.verdict;
}

std::string title_of(const ViewerState& state, const Frame* good, const std::optional<Error>& problem,
                     const std::string& inspected = "") {
  std::string title = "shaderbed view: " + cell_text(state);
  if (problem) title += " | ERROR " + problem->to_string() + (good ? " (last good image shown)" : "");
  else if (good) title += " | " + verdict_text(*good);
  const std::string params = parameters_text(state);
  if (!params.empty()) title += " | " + params;
  if (good) title += fmt::format(" | draw {:.1f} ms, frame {:.0f} ms", good->draw_ms, good->frame_ms);
  if (!inspected.empty()) title += " | " + inspected;
  return title;
}

// What the window shows for the last good frame, in the current split setting.
DisplayImage compose(const Frame& frame, bool split) {
  const DisplayImage render = render_panel(*frame.render);
  if (!split) return render;
  return side_by_side({render,
                       frame.reference ? reference_panel(*frame.reference) : empty_panel(render.width, render.height),
                       frame.error ? error_panel(*frame.error, frame.interior_threshold)
                                   : empty_panel(render.width, render.height)});
}

int content_width(int size, bool split) { return split ? 3 * size + 2 * kSplitGap : size; }

std::string values_text(const std::vector<double>& values) {
  if (values.size() == 1) return fmt::format("{:.6g}", values.front());
  std::vector<std::string> each;
  for (double v : values) each.push_back(fmt::format("{:.6g}", v));
  return fmt::format("({})", fmt::join(each, ", "));
}

// The inspector on stdout: the cell and the pixel, then the listing (twin/PixelListing.h);
// a pixel with nothing to list is one line.
std::string inspection_text(const Inspection& in, int size) {
  std::string head = fmt::format("inspect {}, pixel ({}, {}) of {}x{} (row 0 at the top)", cell_text(in.state), in.x, in.y,
                                 size, size);
  if (!in.explanation) return head + ": " + in.note + "\n";
  const PixelExplanation& e = *in.explanation;
  head += e.against.empty() ? ", by its double twin (no original to match: a model reference)"
                            : ", by its double twin, values matched against " + e.against;
  return head + fmt::format(" ({:.0f} ms):\n", in.ms) + twin::listing_text(e.lines);
}

// The inspector in the title: the first value that matches nothing in the original, else
// the line that wrote last.
std::string inspection_summary(const Inspection& in) {
  const std::string at = fmt::format("pixel ({}, {})", in.x, in.y);
  if (!in.explanation) return in.note.starts_with(at) ? in.note : at + ": " + in.note;
  const auto& lines = in.explanation->lines;
  if (lines.empty()) return at + ": no line executed";
  const auto line_value = [&](const twin::ListedLine& l, const twin::ListedValue& v) {
    return fmt::format("{}:{} {}{}", std::filesystem::path(l.file).filename().string(), l.line,
                       v.name.empty() ? "" : v.name + " = ", values_text(v.values));
  };
  for (const twin::ListedLine& l : lines)
    for (const twin::ListedValue& v : l.values)
      if (v.departs) return at + ": " + line_value(l, v) + " matches nothing in " + in.explanation->against;
  const twin::ListedLine& last = lines.back();
  const std::string tail = last.values.empty() ? fmt::format("{}:{}", std::filesystem::path(last.file).filename().string(), last.line)
                                               : line_value(last, last.values.back());
  return at + fmt::format(": {} lines{}, last {}", lines.size(),
                          in.explanation->against.empty() ? "" : ", each value matches " + in.explanation->against, tail);
}

// The inspector in the window (viewer/InspectionPanel.h): a short head (the stdout one is
// too wide for it) and the same listing, or why there is none.
void draw_inspection(DisplayImage& image, const Inspection& in) {
  const std::string head = fmt::format("pixel ({}, {}) of {}", in.x, in.y, cell_text(in.state));
  draw_inspection_panel(image, in.y, head, in.explanation ? twin::listing_text(in.explanation->lines) : in.note);
}

}  // namespace

int run_viewer(const ViewerOptions& o) {
  // The compile probe's pipe: a child that crashed must be an error, not a SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  auto loaded = load_view_case(o);
  if (!loaded) {
    fmt::print(stderr, "shaderbed: {}\n", loaded.error().to_string());
    return 2;
  }
  auto initial = initial_state(*loaded, o.choice);
  if (!initial) {
    fmt::print(stderr, "shaderbed: {}\n", initial.error().to_string());
    return 2;
  }
  ViewerState state = std::move(*initial);
  state.split = o.split;
  auto current_case = std::make_shared<const Case>(std::move(*loaded));

  // Before any thread starts (it sets the environment): lavapipe presents, as it draws.
  pin_presentation_driver();
  // The frames are presented with the API of the backend that drew them: a Vulkan swapchain
  // for vulkan, the window's GL context for gl (viewer/Presenter.h).
  auto window = ViewerWindow::open(content_width(o.size, state.split), o.size, title_of(state, nullptr, std::nullopt),
                                   present_api_of(state.backend));
  if (!window) {
    if (window.error().stage == ErrorStage::display)
      fmt::print(stderr,
                 "shaderbed: view needs a display: {}. Without one, run it under a virtual X server: "
                 "xvfb-run -a shaderbed view ...\n",
                 window.error().message);
    else
      fmt::print(stderr, "shaderbed: {}\n", window.error().to_string());
    return 2;
  }
  ViewerWindow& win = **window;
  const auto tell = [&win] {
    for (const std::string& notice : win.take_notices()) fmt::print(stderr, "shaderbed view: {}\n", notice);
  };
  tell();

  FrameWorker worker(o.probe_binary, [&win] { win.wake(); });
  FileWatcher watcher;
  watcher.watch(case_files(*current_case));

  uint64_t generation = 0;
  ViewerState requested = state;
  bool sources_changed = false;
  const auto request = [&] {
    requested = state;
    worker.submit({current_case, state, o.size, ++generation, std::exchange(sources_changed, false)});
  };
  request();

  std::optional<Frame> good;            // the last frame that drew
  std::optional<Error> problem;         // the last frame's error (compile, bind, draw)
  std::optional<Error> case_problem;    // the case file's, until it reads again
  std::string reported_problem;         // printed on stderr once per distinct error
  bool reload_pending = false;                    // the files changed; the frame that shows it is not in yet
  auto reload_seen = Clock::now();
  std::vector<std::string> reloaded_files;
  std::deque<InputEvent> queue;
  bool screenshot_pending = false;                // c: waiting for generation screenshot_at's frame (and a resize) to write one
  uint64_t screenshot_at = 0;
  int frames = 0;
  std::vector<double> draw_times;
  auto last_poll = Clock::now();
  // The inspector (i, a right click, --inspect): asked one at a time of the render thread.
  std::deque<InspectRequest> inspections;
  bool inspecting = false;
  std::optional<Inspection> inspected;   // the last answer, in the title and the window while its image is up
  std::deque<std::pair<int, int>> inspect_at_start(o.inspect.begin(), o.inspect.end());
  bool quit = false;
  int status = 0;

  const auto current_problem = [&] { return case_problem ? case_problem : problem; };
  // The last inspection's summary stays in the title while its image is up.
  const auto title_now = [&] {
    return title_of(state, good ? &*good : nullptr, current_problem(),
                    inspected && inspected->state.same_image(state) ? inspection_summary(*inspected) : "");
  };
  // What the window shows: the frame, and the last inspection's panel while its image is up.
  const auto composed_now = [&] {
    DisplayImage image = compose(*good, state.split);
    if (inspected && inspected->state.same_image(state)) draw_inspection(image, *inspected);
    return image;
  };
  const auto show = [&] {
    // The backend that drew the image on screen decides how it is presented (before the
    // first frame, the cell's): B between vulkan and gl makes the window again.
    if (auto remade = win.present_with(present_api_of(good ? good->state.backend : state.backend)); !remade) {
      fmt::print(stderr, "shaderbed view: {}\n", remade.error().to_string());
      quit = true, status = 2;
      return;
    }
    win.set_title(title_now());
    if (good) win.show(composed_now(), current_problem().has_value());
    else win.show({}, current_problem().has_value());
    tell();
  };
  const auto report_problem = [&] {
    const std::optional<Error> now = current_problem();
    if (!now || now->to_string() == reported_problem) return;
    reported_problem = now->to_string();
    fmt::print(stderr, "shaderbed view: {}{}\n", reported_problem, good ? " (the last good image stays up)" : "");
  };
  const auto take_screenshot = [&](const std::string& stem) {
    if (!good) {
      fmt::print(stderr, "shaderbed view: no screenshot: nothing has been drawn{}\n",
                 problem ? " (" + problem->to_string() + ")" : "");
      return false;
    }
    // The window as it shows the frame, read back, so the file is what is on screen; when
    // the window is not at one image pixel per pixel (resized, or a resize still on its
    // way), the content at that scale instead.
    show();   // keys in the same batch (e, then c) may have changed it since the last show
    const DisplayImage composed = composed_now();
    DisplayImage shown = win.capture();
    if (shown.width != composed.width || shown.height != composed.height) {
      fmt::print(stderr, "shaderbed view: screenshot: {}: the PNG is the image as composed, not read back from the window\n",
                 shown.width == 0 ? std::string("the window's pixels cannot be read back")
                                  : fmt::format("the window shows the image at {}x{}, not {}x{}", shown.width,
                                                shown.height, composed.width, composed.height));
      shown = composed;
    }
    auto written = write_screenshot(stem, *good, shown, state.split);
    if (!written) {
      fmt::print(stderr, "shaderbed view: screenshot: {}\n", written.error().to_string());
      return false;
    }
    fmt::print("screenshot: {}\n", fmt::join(*written, " "));
    std::fflush(stdout);
    return true;
  };

  const auto inspect_pixel = [&](int x, int y) {
    inspections.push_back({{current_case, state, o.size, 0, false}, x, y});
  };
  // The pixel under window position (x, y): in the split view, each panel's pixels are the cell's.
  const auto inspect_under = [&](double x, double y) {
    const auto at = win.image_pixel(x, y, content_width(o.size, state.split), o.size);
    const auto pixel = at ? panel_pixel(at->first, at->second, o.size, o.size, state.split ? 3 : 1) : std::nullopt;
    if (!pixel) {
      fmt::print("inspect: the cursor ({:.0f}, {:.0f}) is not over the image\n", x, y);
      std::fflush(stdout);
      return;
    }
    inspect_pixel(pixel->first, pixel->second);
  };
  // Prints an answer that came in and asks the next question; true when an answer came in.
  const auto take_inspection = [&] {
    bool answered = false;
    if (inspecting) {
      std::optional<Inspection> answer = worker.take_inspection();
      if (!answer) return false;
      fmt::print("{}", inspection_text(*answer, o.size));
      std::fflush(stdout);
      inspected = std::move(answer);
      inspecting = false;
      answered = true;
    }
    if (!inspections.empty()) {
      worker.inspect(std::move(inspections.front()));
      inspections.pop_front();
      inspecting = true;
    }
    return answered;
  };

  uint64_t last_frame = 0;   // the generation of the last frame that arrived
  // A pending screenshot (c), once its frame has arrived and the window has its size.
  const auto take_screenshot_when_due = [&] {
    if (!screenshot_pending || last_frame < screenshot_at || win.resizing()) return;
    take_screenshot(next_screenshot_stem(o.out_dir, state));
    screenshot_pending = false;
  };
  while (!quit) {
    win.wait(kPollSeconds);
    tell();   // a frame the window's refresh could not present
    for (InputEvent& e : win.take_events()) queue.push_back(e);
    if (win.close_requested()) break;

    // Input, in order; a screenshot holds the rest back until the frame of the state the
    // keys before it made has arrived, and the window has the size they asked for, so
    // keys, then a screenshot, is deterministic.
    bool touched = false;
    while (!queue.empty() && !screenshot_pending && !quit) {
      const InputEvent e = queue.front();
      queue.pop_front();
      touched = true;
      const bool split_before = state.split;
      if (e.kind == InputEvent::Kind::drag) drag_light(state, e.dx, e.dy, win.height());
      else if (e.kind == InputEvent::Kind::scroll) scroll_zoom(state, e.steps);
      else if (e.kind == InputEvent::Kind::inspect) inspect_under(e.x, e.y);
      else switch (handle_key(state, e.key)) {
          case Effect::quit: quit = true; break;
          case Effect::inspect: inspect_under(e.x, e.y); break;
          case Effect::help: fmt::print("{}", key_table()), std::fflush(stdout); break;
          case Effect::screenshot:
            if (!state.same_image(requested)) request();
            screenshot_pending = true, screenshot_at = generation;
            take_screenshot_when_due();
            break;
          case Effect::redraw:
          case Effect::none: break;
        }
      if (state.split != split_before) win.resize(content_width(o.size, state.split), o.size);
    }
    if (quit) break;

    // The files: a changed case file is read again (an error in it keeps the last image).
    if (ms_since(last_poll) >= kPollSeconds * 1000) {
      last_poll = Clock::now();
      const std::vector<std::string> changed = watcher.changed();
      if (!changed.empty()) {
        reload_seen = Clock::now();
        reload_pending = true;
        reloaded_files = changed;
        auto reloaded = reload_case(current_case->path, o.params);
        if (!reloaded) {
          case_problem = reloaded.error();
          report_problem();
          fmt::print("reloaded {}: {}\n", fmt::join(changed, ", "), case_problem->to_string());
          std::fflush(stdout);
          reload_pending = false;
          touched = true;
        } else {
          case_problem.reset();
          state = with_case(state, *reloaded);
          current_case = std::make_shared<const Case>(std::move(*reloaded));
          watcher.watch(case_files(*current_case));
          sources_changed = true;
          request();
        }
      }
    }
    if (!state.same_image(requested)) request();

    const bool answered = take_inspection();   // its summary goes into the title
    std::optional<Frame> frame = worker.take();
    if (!frame && !answered) {
      if (touched) show();   // the split view, the selected parameter, the title
      take_screenshot_when_due();   // e.g. once a resize has landed
      continue;
    }
    if (frame) {
      ++frames;
      last_frame = frame->generation;
      if (frame->problem) {
        problem = frame->problem;
      } else {
        problem.reset();
        if (!case_problem) reported_problem.clear();
        draw_times.push_back(frame->draw_ms);
        good = std::move(*frame);
      }
      report_problem();
      if (reload_pending) {
        fmt::print("reloaded {} in {:.0f} ms{}\n", fmt::join(reloaded_files, ", "), ms_since(reload_seen),
                   problem ? ": " + problem->to_string() : "");
        std::fflush(stdout);
        reload_pending = false;
      }
    }
    // --inspect X,Y: once the first frame is in.
    if (good)
      while (!inspect_at_start.empty()) {
        inspect_pixel(inspect_at_start.front().first, inspect_at_start.front().second);
        inspect_at_start.pop_front();
      }
    take_inspection();
    show();
    if (quit) break;
    take_screenshot_when_due();
    // --screenshot FILE --frames N: N frames (and the --inspect answers), then the file, then exit.
    if (!o.screenshot.empty() && !screenshot_pending && queue.empty() && last_frame == generation) {
      if (inspecting || !inspections.empty()) continue;
      if (frames < o.frames) {
        request();   // the same image again: one more frame
        continue;
      }
      status = take_screenshot(screenshot_stem(o.screenshot)) ? 0 : 1;
      if (!draw_times.empty()) {
        std::vector<double> sorted = draw_times;
        std::ranges::sort(sorted);
        fmt::print("{} frames: draw median {:.2f} ms\n", frames, sorted[sorted.size() / 2]);
      }
      fmt::print("{}\n", title_now());
      quit = true;
    }
  }
  return status;
}

}  // namespace shaderbed::viewer
