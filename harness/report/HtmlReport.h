#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// The HTML report: DIR/index.html, one page (inline CSS and JS, nothing fetched from the
// network; images embedded as data-URI PNGs within a budget, the rest linked to the run's
// files), plus DIR/sources/ with copies of the cells' SPIR-V disassembly and SPIRV-Cross
// GLSL (as .txt so a browser shows them), linked relatively.
//
// The page: toolchain, totals and the image policy; the summary matrix (report/SummaryMatrix:
// case/variant x language/backend/path, as the console prints it), each count a link that
// filters the table to its cells; failure cards (new failures open, errors, then known
// failures collapsed), one per way of failing (cells of a case/variant/language with the
// same failure, report/CellGroups.h failure_key, share a card that lists them), each
// showing first the reference | render | error map (false colour with its scale bar,
// report/HtmlScaleBar.h; a flicker toggle; zoom synchronised across the three), then the
// numbers, then why (collapsed: the message, the attribution, the convention fits), and
// every render of the same case/variant/shape (docs/html-report.md); a sortable, filterable table of all cells
// (click a header to sort; click a row for the same card with all metrics, value counts,
// tolerances and LUT derivation, timings, SPIR-V hashes and links).
//
// Load time: a browser spends it on bytes and on laying out table rows. So the cards are
// stored as HTML strings in a JSON array and put into the page when opened (only the open
// failure cards are in the markup), and a table of more than 250 cells starts with no row
// shown until a matrix link, a filter or "show all" asks for some.
//
// Images: each PNG is stored once (the reference is shared) and only set on an <img> when
// its card is shown. What is embedded is bounded by HtmlOptions (image_budget, and what
// max_page_bytes leaves after the markup), in this order: the images of failing and
// erroring cells, one passing example per case/variant, the other renders of failing
// cells' case/variant/shape, then the rest (references, renders, error maps) while the
// budget lasts. Images over the budget are referenced by their path relative to DIR (shown
// when the page is opened next to the run's images, as scripts/demo writes it); a missing
// file is shown as "missing" with its path. Measured on the default suite at 256 px, all
// passing (1400 cells, 2940 PNGs of ~3.5 KB): index.html is 6.0 MB (240 PNGs embedded,
// 1.0 MB; the card store 3.8 MB; the table and the rest 1.2 MB) and headless Chromium's
// load event comes 0.6-0.7 s after navigation on a busy 2-core machine (most of it reading
// the file); embedding every PNG, with every card in the markup, it was 19.2 MB and 3.1-3.3 s.
//
// URL fragment options (combine with &): #expand-all opens every row; #sort=KEY or
// #sort=KEY:desc sorts (KEY: index, case, variant, language, backend, path, shape, status,
// max_abs, threshold, min_passing, silhouette, rmse, psnr, attribution, ms);
// #status=failing|fail|known|error|pass and #filter=TEXT filter (TEXT is looked for in the
// row's text and in its "/case/variant/lang/backend/path/shape/", so the matrix links use
// "/phong/pixel/glsl/vulkan/spirv/"). They are read on load and whenever the fragment
// changes. When every shown image has settled, the page sets on <body>
// data-images-ready="all" (or "broken"), data-images-total and data-images-decoded
// (complete and naturalWidth > 0).

// A chart drawn elsewhere (plot/), shown inline in a "Speed against error" section before
// the failures. `svg` must be self-contained (no script, no external reference).
struct HtmlChart {
  std::string title;
  std::string svg;
  std::string caption;   // plain text
};

struct HtmlOptions {
  size_t image_budget = size_t(1) << 20;     // at most this many bytes of base64 image data
  size_t max_page_bytes = size_t(8) << 20;   // and index.html stays under this in total
  std::vector<HtmlChart> charts;
  // Plain-text notes shown under the image policy, e.g. what `merge` left out of the page.
  std::vector<std::string> notes;
};

struct HtmlSummary {
  std::string index_path;
  size_t html_bytes = 0;
  size_t images_embedded = 0, image_bytes = 0;  // distinct PNGs in the page, their base64 size
  size_t images_linked = 0;                     // present but over the budget: relative file path
  size_t images_missing = 0;
  size_t sources_copied = 0;
  size_t sources_not_copied = 0;                // a copy failed (a full disk): shown without a link
};

Result<void> write_html(const RunReport& report, const std::string& dir);
Result<HtmlSummary> write_html(const RunReport& report, const std::string& dir, const HtmlOptions& options);

}  // namespace shaderbed
