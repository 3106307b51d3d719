#include "compare/Attribution.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "compare/ValueClass.h"

namespace shaderbed {
namespace {

std::string where(const RenderOutcome& r) { return r.backend + "/" + r.path; }

// "a", "a and b", "a, b and c".
std::string join_and(const std::vector<std::string>& items) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i)
    s += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return s;
}

std::string join_comma(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

void add_unique(std::vector<std::string>& v, const std::string& s) {
  if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
}

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.3g}", v) : "inf"; }

template <typename Pred>
std::vector<const RenderOutcome*> select(std::span<const RenderOutcome> renders, Pred pred) {
  std::vector<const RenderOutcome*> out;
  for (const RenderOutcome& r : renders)
    if (pred(r)) out.push_back(&r);
  return out;
}

bool all_pass(const std::vector<const RenderOutcome*>& rs) {
  return std::all_of(rs.begin(), rs.end(), [](const RenderOutcome* r) { return r->pass; });
}
bool none_pass(const std::vector<const RenderOutcome*>& rs) {
  return std::none_of(rs.begin(), rs.end(), [](const RenderOutcome* r) { return r->pass; });
}

// Max pairwise difference of the renders' images; -1 when an image is missing.
double difference_of(const std::vector<const RenderOutcome*>& rs, const std::vector<PixelClass>& classes) {
  std::vector<const Image*> images;
  for (const RenderOutcome* r : rs) {
    if (!r->image) return -1;
    images.push_back(r->image);
  }
  return renders_max_difference(images, classes);
}

std::vector<std::string> places(const std::vector<const RenderOutcome*>& rs, bool with_language) {
  std::vector<std::string> out;
  for (const RenderOutcome* r : rs) out.push_back(with_language ? r->language + " " + where(*r) : where(*r));
  return out;
}

}  // namespace

const char* to_string(Attribution a) {
  switch (a) {
    case Attribution::none: return "";
    case Attribution::front_end: return "front end";
    case Attribution::cross_compiler: return "cross-compiler";
    case Attribution::driver: return "driver";
    case Attribution::model_reference: return "model/reference";
    case Attribution::matrix_convention: return "matrix convention";
    case Attribution::reduced_precision: return "reduced precision";
    case Attribution::unclear: return "unclear";
  }
  return "unclear";
}

namespace {

// Intersection over union of the render's coverage and the reference's, with the
// reference's pixel (x, y) read at map(x, y).
template <typename Map>
double coverage_overlap(const Image& render, const ReferenceImage& reference, Map map) {
  size_t both = 0, either = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      const auto [rx, ry] = map(x, y);
      const bool drawn = render.coverage[size_t(y) * reference.width + x] != 0;
      const bool covered = reference.coverage[size_t(ry) * reference.width + rx] != 0;
      both += drawn && covered;
      either += drawn || covered;
    }
  return either ? double(both) / double(either) : 1.0;
}

constexpr const char* kMatrixCause =
    "the likely cause is the matrix convention: a row-vector shader (mul(v, M)) given a column-vector matrix "
    "(bind it as { value = \"...\", layout = \"row_vector\" }) or the reverse, a transposed matrix, or a missing "
    "(unbound or zero) one";

}  // namespace

std::string coverage_geometry_evidence(const Image& render, const ReferenceImage& reference) {
  const size_t pixels = size_t(reference.width) * reference.height;
  if (render.coverage.size() != pixels || reference.coverage.size() != pixels || pixels == 0) return "";
  size_t drawn = 0, covered = 0;
  for (size_t i = 0; i < pixels; ++i) {
    drawn += render.coverage[i] != 0;
    covered += reference.coverage[i] != 0;
  }
  if (covered == 0) return "";
  if (drawn == 0) return fmt::format("blank: the render draws nothing where the reference covers {} px; {}", covered, kMatrixCause);
  const int w = reference.width, h = reference.height;
  const double direct = coverage_overlap(render, reference, [](int x, int y) { return std::pair{x, y}; });
  if (direct >= 0.5) return "";
  struct Candidate {
    const char* how;
    double overlap;
  };
  std::vector<Candidate> candidates{
      {"mirrored left-right", coverage_overlap(render, reference, [&](int x, int y) { return std::pair{w - 1 - x, y}; })},
      {"mirrored top-bottom", coverage_overlap(render, reference, [&](int x, int y) { return std::pair{x, h - 1 - y}; })},
      {"rotated by 180 degrees", coverage_overlap(render, reference, [&](int x, int y) {
         return std::pair{w - 1 - x, h - 1 - y};
       })}};
  if (w == h)
    candidates.push_back({"transposed", coverage_overlap(render, reference, [](int x, int y) { return std::pair{y, x}; })});
  const auto best = std::max_element(candidates.begin(), candidates.end(),
                                     [](const Candidate& a, const Candidate& b) { return a.overlap < b.overlap; });
  if (best->overlap < 0.8)
    return fmt::format("the render covers {} px where the reference covers {} px, overlapping only {:.0f}%: the "
                       "geometry is misplaced; {}",
                       drawn, covered, 100 * direct, kMatrixCause);
  return fmt::format("the render covers the reference's area {} (overlap {:.0f}% that way, {:.0f}% as drawn); {}",
                     best->how, 100 * best->overlap, 100 * direct, kMatrixCause);
}

double renders_max_difference(std::span<const Image* const> images, const std::vector<PixelClass>& classes) {
  if (images.size() < 2) return 0;
  for (const Image* im : images)
    if (im->rgba.size() != classes.size() * 4 || im->coverage.size() != classes.size()) return kInf;
  double worst = 0;
  for (size_t i = 0; i < classes.size(); ++i) {
    if (classes[i] != PixelClass::interior) continue;
    const bool drawn = images[0]->coverage[i] != 0;
    for (const Image* im : images)
      if ((im->coverage[i] != 0) != drawn) return kInf;
    if (!drawn) continue;
    for (int c = 0; c < 3; ++c) {
      const float first = images[0]->rgba[i * 4 + c];
      const int cls = value_class(first);
      float lo = first, hi = first;
      for (const Image* im : images) {
        const float v = im->rgba[i * 4 + c];
        if (value_class(v) != cls) return kInf;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      if (cls == 0) worst = std::max(worst, double(hi) - double(lo));
    }
  }
  return worst;
}

namespace {

std::vector<Verdict> stage_verdicts(std::span<const RenderOutcome> renders, const ReferenceImage& reference,
                                    const ComparisonThresholds& t, double expected_area);

}  // namespace

std::vector<Verdict> attribute_failures(std::span<const RenderOutcome> renders, const ReferenceImage& reference,
                                        const ComparisonThresholds& t, double expected_area) {
  std::vector<Verdict> verdicts = stage_verdicts(renders, reference, t, expected_area);
  for (size_t i = 0; i < renders.size() && i < verdicts.size(); ++i) {
    if (renders[i].pass || !renders[i].image) continue;
    const std::string evidence = coverage_geometry_evidence(*renders[i].image, reference);
    if (evidence.empty()) continue;
    Verdict& v = verdicts[i];
    if (v.attribution == Attribution::unclear || v.attribution == Attribution::model_reference) {
      v = {Attribution::matrix_convention, evidence + (v.reason.empty() ? "" : " (" + v.reason + ")")};
    } else {
      v.reason += "; " + evidence;
    }
  }
  return verdicts;
}

namespace {

std::vector<Verdict> stage_verdicts(std::span<const RenderOutcome> renders, const ReferenceImage& reference,
                                    const ComparisonThresholds& t, double expected_area) {
  std::vector<Verdict> verdicts(renders.size());
  if (std::all_of(renders.begin(), renders.end(), [](const RenderOutcome& r) { return r.pass; })) return verdicts;
  const std::vector<PixelClass> classes = classify_pixels(reference);
  std::vector<std::string> languages;
  for (const RenderOutcome& r : renders) add_unique(languages, r.language);
  const auto everything = select(renders, [](const RenderOutcome&) { return true; });

  // Every render fails: only the reference (or nothing) can be singled out.
  if (none_pass(everything)) {
    Verdict v{Attribution::unclear, ""};
    std::vector<std::string> backends;
    for (const RenderOutcome& r : renders) add_unique(backends, r.backend);
    const double diff = renders.size() >= 2 ? difference_of(everything, classes) : -1;
    const std::string who = fmt::format("all {} renders ({} on {})", renders.size(), join_comma(languages),
                                        join_comma(backends));
    if (renders.size() < 2) {
      v.reason = "the only render fails; nothing to compare it with";
    } else if (diff < 0) {
      v.reason = fmt::format("{} fail; their images are not available to compare", who);
    } else if (diff > t.interior_max_abs) {
      v.reason = fmt::format("{} fail and disagree with each other (max difference {})", who, number(diff));
    } else if (languages.size() < 2) {
      v.reason = fmt::format("{} fail and agree with each other (max difference {}), but with one language the "
                             "front end cannot be told from the model",
                             who, number(diff));
    } else {
      v = {Attribution::model_reference,
           fmt::format("{} agree with each other (max difference {} <= {}) but not with the reference", who,
                       number(diff), number(t.interior_max_abs))};
      if (expected_area > 0) {
        // A reference whose coverage matches the mesh's projected area while the
        // renders' does not is not the odd one out.
        size_t band = 0, ref_covered = 0, render_covered = 0;
        for (PixelClass c : classes) band += c == PixelClass::silhouette;
        for (uint8_t c : reference.coverage) ref_covered += c != 0;
        for (uint8_t c : renders[0].image->coverage) render_covered += c != 0;
        const double allow = double(coverage_allowance(band));
        if (std::abs(double(ref_covered) - expected_area) <= allow &&
            std::abs(double(render_covered) - expected_area) > allow)
          v = {Attribution::unclear,
               fmt::format("{} agree with each other, but their coverage ({} px) is off the expected area (≈{:.0f} "
                           "px) which the reference ({} px) matches: a fault every language shares, not the model",
                           who, render_covered, expected_area, ref_covered)};
      }
    }
    for (Verdict& out : verdicts) out = v;
    return verdicts;
  }

  for (size_t i = 0; i < renders.size(); ++i) {
    const RenderOutcome& f = renders[i];
    if (f.pass) continue;
    Verdict& v = verdicts[i];
    const auto same_language = select(renders, [&](const RenderOutcome& r) { return r.language == f.language; });
    const auto other_languages = select(renders, [&](const RenderOutcome& r) { return r.language != f.language; });

    // Reduced precision: only the renders computed in the precision the shader asked for differ.
    const auto failing_full = select(renders, [](const RenderOutcome& r) { return !r.pass && !r.reduced_precision; });
    const auto passing_full = select(renders, [](const RenderOutcome& r) { return r.pass && !r.reduced_precision; });
    if (f.reduced_precision && failing_full.empty() && !passing_full.empty()) {
      v = {Attribution::reduced_precision,
           fmt::format("{} on {} computes in reduced precision what the shader declares so (mediump, lowp); every "
                       "render at full precision passes ({})",
                       f.language, where(f), join_comma(places(passing_full, true)))};
      continue;
    }

    // Front end: this language fails everywhere, every other language passes everywhere.
    if (none_pass(same_language) && !other_languages.empty() && all_pass(other_languages)) {
      std::vector<std::string> others;
      for (const RenderOutcome* r : other_languages) add_unique(others, r->language);
      const double diff = difference_of(same_language, classes);
      std::string agreement;
      if (same_language.size() >= 2 && diff >= 0)
        agreement = diff <= t.interior_max_abs
                        ? fmt::format(" and agree with each other (max difference {})", number(diff))
                        : fmt::format(" (and differ from each other: max difference {})", number(diff));
      const std::string on = same_language.size() == 1
                                 ? fmt::format("{} render on its only path ({}) differs", f.language, where(f))
                                 : fmt::format("{} renders on all {} paths ({}) differ", f.language,
                                               same_language.size(), join_comma(places(same_language, false)));
      v = {Attribution::front_end, fmt::format("{} from the reference{}; {} pass{}", on, agreement, join_and(others),
                                               others.size() == 1 ? "es" : "")};
      continue;
    }

    // Cross-compiler: only the SPIRV-Cross output of this language fails.
    const auto non_cross = select(renders, [&](const RenderOutcome& r) { return r.language == f.language && r.path != "cross"; });
    if (f.path == "cross" && !non_cross.empty() && all_pass(non_cross)) {
      std::vector<std::string> also;
      for (const RenderOutcome& r : renders)
        if (r.path == "cross" && !r.pass && r.language != f.language) add_unique(also, r.language);
      v = {Attribution::cross_compiler,
           fmt::format("{} on {} differs from the reference; {} on {} pass{}{}", f.language, where(f), f.language,
                       join_comma(places(non_cross, false)), non_cross.size() == 1 ? "es" : "",
                       also.empty() ? "" : fmt::format("; the cross path also fails for {}", join_and(also)))};
      continue;
    }

    // Driver: the same shaders pass on another backend.
    std::vector<std::string> other_backends;
    for (const RenderOutcome* r : same_language)
      if (r->backend != f.backend) add_unique(other_backends, r->backend);
    std::string good_backend;
    std::vector<const RenderOutcome*> good;
    for (const std::string& b : other_backends) {
      auto on_b = select(renders, [&](const RenderOutcome& r) { return r.language == f.language && r.backend == b; });
      if (all_pass(on_b)) {
        good_backend = b;
        good = std::move(on_b);
        break;
      }
    }
    if (!good_backend.empty()) {
      const auto also_failing = select(renders, [&](const RenderOutcome& r) {
        return r.backend == f.backend && !r.pass && &r != &f;
      });
      v = {Attribution::driver,
           fmt::format("{} on {} differs from the reference; the same {} shaders pass on {} ({}){}", f.language,
                       where(f), f.language, good_backend, join_comma(places(good, false)),
                       also_failing.empty()
                           ? fmt::format("; every other {} render passes", f.backend)
                           : fmt::format("; also failing on {}: {}", f.backend, join_comma(places(also_failing, true))))};
      continue;
    }

    const auto failing = select(renders, [](const RenderOutcome& r) { return !r.pass; });
    const auto passing = select(renders, [](const RenderOutcome& r) { return r.pass; });
    v = {Attribution::unclear, fmt::format("no single stage explains it: failing {}; passing {}",
                                           join_comma(places(failing, true)), join_comma(places(passing, true)))};
  }
  return verdicts;
}

}  // namespace
}  // namespace shaderbed
