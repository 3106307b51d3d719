#pragma once
// `shaderbed view`: the book's interactive test bed (its §7; docs/viewer.md)
// on shaderbed's engine. A window shows one cell of a case, drawn offscreen by the
// backend `run` uses and judged against the same reference; keys (viewer/KeyMap.h) change
// the cell, the view and the case's parameters, the mouse moves the light, and a change
// to the case file or a shader on disk is compiled and drawn again within a second. A
// frame is drawn only when something changed, so an idle viewer costs nothing.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "viewer/ViewerState.h"

namespace shaderbed::viewer {

struct ViewerOptions {
  std::string case_name;          // a name in cases_dir or a case file; "" = phong, else the first case
  std::string cases_dir;
  CellChoice choice;
  std::vector<std::string> params;   // --param overrides, "name=value[,value...]"
  int size = 256;
  std::string out_dir = "view";      // the screenshot key's folder
  std::string screenshot;            // --screenshot FILE: draw `frames` frames, write FILE, exit
  int frames = 1;
  bool split = false;                // start in the split view
  std::vector<std::pair<int, int>> inspect;   // --inspect X,Y: pixels inspected (as `i` does) after the first frame
  std::string probe_binary;          // the shaderbed executable (compile probe); "" = compile in-process only
};

// Exit status: 0 (quit, or the screenshot written), 1 nothing could be drawn for
// --screenshot, 2 bad input or no display (stderr says which, and that xvfb-run gives one).
int run_viewer(const ViewerOptions& options);

}  // namespace shaderbed::viewer
