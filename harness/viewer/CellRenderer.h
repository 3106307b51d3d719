#pragma once
// Draws what the viewer shows, with the engine `run` uses: the cell's program compiled by
// the run's program cache, bound by the case's uniforms and textures, drawn by the same
// Vulkan or GL backend into a float target, and judged against the same reference (the
// model in double, or a differential case's original drawn alike) with the same
// comparison and thresholds. With the run's scene (nothing scaled, spun, zoomed or moved)
// the image is the one `run` draws for the cell, pixel for pixel.
//
// Not thread-safe: one renderer lives on the viewer's render thread, which owns its
// backends (an OSMesa context is current on one thread; the window's GL context lives on
// the main thread).
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "backends/Backend.h"
#include "compare/ImageComparison.h"
#include "run/CellDivergence.h"
#include "run/CellPlan.h"
#include "run/ProgramCache.h"
#include "run/ReferenceKinds.h"
#include "scene/CaseFile.h"
#include "viewer/CompileProbe.h"
#include "viewer/ViewerState.h"

namespace shaderbed::viewer {

struct FrameRequest {
  std::shared_ptr<const Case> c;
  ViewerState state;
  int size = 256;
  uint64_t generation = 0;
  bool sources_changed = false;   // the case or a shader changed on disk: compile again
};

struct Frame {
  uint64_t generation = 0;
  ViewerState state;
  std::optional<Image> render;              // the shader's image (or the Gouraud light's); none: see `problem`
  std::optional<ReferenceImage> reference;  // none: see reference_problem
  std::optional<Image> error;               // |render - reference| per channel, coverage = pixel class
  double interior_threshold = 0;            // absolute part, with a LUT variant's bound
  std::string verdict;                      // "pass", "fail", "not judged", "error"
  std::string detail;                       // why it failed or is not judged
  double max_error = 0;                     // interior max |render - reference|
  double tolerance_share = 0;               // of the interior tolerance (over 1 fails)
  std::optional<Error> problem;             // compile, bind or draw error: the last good image stays up
  std::string reference_problem;
  double draw_ms = 0;                       // the backend's draw and read-back
  double frame_ms = 0;                      // all of it: compile when needed, draw, reference, compare
};

// The inspector's question (`i` or a right click): pixel (x, y) of the image `frame` draws,
// in image space (the run's: row 0 at the top).
struct InspectRequest {
  FrameRequest frame;
  int x = 0, y = 0;
};

// Its answer: the cell's shader at that pixel, line by line, by its double twin
// (run/CellDivergence.h), matched to the original's values for a differential case.
struct Inspection {
  ViewerState state;                            // the cell asked about
  int x = 0, y = 0;
  std::optional<PixelExplanation> explanation;  // none: see `note`
  std::string note;                             // why not: outside the shape, a draw error
  double ms = 0;                                // all of it: the frame again, both twins, the traces
};

class CellRenderer {
 public:
  // `probe_binary`: the shaderbed executable, which compiles each program in a child
  // first (viewer/CompileProbe.h); "" compiles in this process only.
  explicit CellRenderer(std::string probe_binary);
  ~CellRenderer();
  CellRenderer(const CellRenderer&) = delete;
  CellRenderer& operator=(const CellRenderer&) = delete;

  Frame draw(const FrameRequest& request);
  // Draws the request's frame again and then its pixel by the twins; asked only by the
  // inspector, so a frame costs nothing more for it.
  Inspection inspect(const InspectRequest& request);

 private:
  struct Drawn {
    Image image;
    double draw_ms = 0;
  };
  class Drawer;
  // draw(), and with `inspection`, its pixel explained into it once the frame's cell and
  // reference are known.
  Frame draw_frame(const FrameRequest& request, Inspection* inspection);
  void explain_pixel(GroupDrawer& drawer, const CellGroup& group, const CellReference& reference, const Frame& frame,
                     Inspection& out);
  // `additions`: what the case's reference adds to its draws (run/CellDraw.h); may be null.
  Result<Drawn> draw_program(const Case& c, const Variant& variant, Language language, BackendSlot& slot,
                             ShaderPath path, const Mesh& mesh, const SceneSetup& scene, bool wireframe,
                             const DrawAdditions* additions, const Variation& variation = {});
  BackendSlot& backend(const std::string& name);   // started on first use
  Result<const Texture*> lut_of(const Case& c, const Variant& variant);

  CompileProbe probe_;
  std::unique_ptr<ProgramCache> programs_;
  std::set<std::string> probed_;                           // case/variant/language since the last change
  std::map<std::string, BackendSlot> backends_;            // by name
  std::map<std::string, Mesh> meshes_;                     // shape/tessellation
  std::map<std::string, Result<Texture>> luts_;            // variant and parameters
  StoredReferences no_stored_;                             // the viewer loads no stored run
  std::unique_ptr<ReferenceKinds> references_;             // made anew when the sources change
  std::unique_ptr<CellDivergence> twins_;                  // the inspector's, made on its first use
};

}  // namespace shaderbed::viewer
