#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// The HTML report: DIR/index.html, one self-contained page (inline CSS and JS, images as
// data-URI PNGs, nothing fetched from the network), plus DIR/sources/ with copies of the
// cells' SPIR-V disassembly and SPIRV-Cross GLSL (as .txt so a browser shows them), linked
// relatively.
//
// The page: toolchain, totals and the image policy; failure cards (new failures open,
// errors, then known failures collapsed) with the reference, the render, the error heat
// map and every render of the same case/variant/shape side by side; a sortable, filterable
// table of all cells (click a header to sort; click a row for the same card with all
// metrics, value counts, tolerances and LUT derivation, timings, SPIR-V hashes and links).
//
// Images: each PNG is stored once (the reference is shared) and only set on an <img> when
// its card is shown. What is embedded is bounded by HtmlOptions (image_budget, and what
// max_page_bytes leaves after the markup), in this order: the images of failing and
// erroring cells, one passing example per case/variant, the other renders of failing
// cells' case/variant/shape, then the rest (references, renders, error maps) while the
// budget lasts. A full suite at the default 256 px (1120 cells, 2352 PNGs of ~5 KB) embeds
// everything: index.html is 14.4 MB all passing, 22 MB all failing. Images over the
// budget are referenced by their path relative to DIR (shown when the page is opened next
// to the run's images); a missing file is shown as "missing" with its path.
//
// URL fragment options (combine with &): #expand-all opens every row; #sort=KEY or
// #sort=KEY:desc sorts (KEY: index, case, variant, language, backend, path, shape, status,
// max_abs, threshold, min_passing, silhouette, rmse, psnr, attribution, ms);
// #status=failing|fail|known|error|pass and #filter=TEXT filter. When every shown image
// has settled, the page sets on <body> data-images-ready="all" (or "broken"),
// data-images-total and data-images-decoded (complete and naturalWidth > 0).
// A chart drawn elsewhere (plot/), shown inline in a "Speed against error" section before
// the failures. `svg` must be self-contained (no script, no external reference).
struct HtmlChart {
  std::string title;
  std::string svg;
  std::string caption;   // plain text
};

struct HtmlOptions {
  size_t image_budget = size_t(24) << 20;    // at most this many bytes of base64 image data
  size_t max_page_bytes = size_t(28) << 20;  // and index.html stays under this in total
  std::vector<HtmlChart> charts;
};

struct HtmlSummary {
  std::string index_path;
  size_t html_bytes = 0;
  size_t images_embedded = 0, image_bytes = 0;  // distinct PNGs in the page, their base64 size
  size_t images_linked = 0;                     // present but over the budget: relative file path
  size_t images_missing = 0;
  size_t sources_copied = 0;
};

Result<void> write_html(const RunReport& report, const std::string& dir);
Result<HtmlSummary> write_html(const RunReport& report, const std::string& dir, const HtmlOptions& options);

}  // namespace shaderbed
