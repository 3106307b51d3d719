#include "viewer/InspectionPanel.h"

#include <algorithm>
#include <regex>
#include <sstream>

#include <fmt/format.h>

namespace shaderbed::viewer {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool departs(const std::string& line) { return line.ends_with("matches nothing"); }

// "tests/differential/glsl/a.frag:14" -> "a.frag:14": the window is narrow.
std::string without_folders(const std::string& line) {
  static const std::regex folders(R"(\S*/([^/\s]+:\d+))");
  return std::regex_replace(line, folders, "$1");
}

}  // namespace

std::vector<TextLine> inspection_lines(const std::string& head, const std::string& listing, int rows) {
  std::vector<TextLine> out;
  if (rows <= 0) return out;
  out.push_back({head, kPanelTextColour});
  const std::vector<std::string> lines = split_lines(listing);
  const int n = int(lines.size());
  // Warm: each value that matches nothing and the source line above it (not indented).
  std::vector<bool> warm(lines.size(), false);
  int focus = -1;   // the first warm source line
  for (int i = 0; i < n; ++i) {
    if (!departs(lines[size_t(i)])) continue;
    warm[size_t(i)] = true;
    int s = i;
    while (s > 0 && lines[size_t(s)].starts_with(" ")) --s;
    warm[size_t(s)] = true;
    if (focus < 0) focus = s;
  }
  const int room = rows - 1;
  int start = 0, end = std::min(n, room);
  if (n > room && focus > 0) {
    start = std::min(focus - 1, n - room);
    end = start + room;
  }
  const bool marks = n > room && room >= 3;   // "..." rows for what is left out
  for (int i = start; i < end; ++i) {
    if (marks && i == start && start > 0)
      out.push_back({fmt::format("... {} lines above", start + 1), kPanelTextColour});
    else if (marks && i == end - 1 && end < n)
      out.push_back({fmt::format("... {} more lines", n - end + 1), kPanelTextColour});
    else
      out.push_back({without_folders(lines[size_t(i)]), warm[size_t(i)] ? kPanelDepartsColour : kPanelTextColour});
  }
  return out;
}

PanelRect inspection_panel_rect(const DisplayImage& image, int pixel_y, int line_count) {
  const int wanted = line_count * text_line_height() + 2 * kTextPadding;
  const int height = std::min(wanted, image.height / 2);
  const int y = pixel_y < image.height / 2 ? image.height - height : 0;
  return {0, y, image.width, height};
}

void draw_inspection_panel(DisplayImage& image, int pixel_y, const std::string& head, const std::string& listing) {
  const int all = 1 + int(split_lines(listing).size());
  const PanelRect rect = inspection_panel_rect(image, pixel_y, all);
  draw_text_panel(image, rect, inspection_lines(head, listing, rows_in(rect.height)));
}

}  // namespace shaderbed::viewer
