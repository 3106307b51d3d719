#include "run/ReferenceKinds.h"

namespace shaderbed {
namespace {

// The images a known-good run stored (run --save-images): each cell is judged against its
// own image, drawn with the same scene (run/StoredImages.h).
class StoredReference final : public CellReference {
 public:
  StoredReference(const Case& c, const StoredRun* run, std::string dir, std::string toolchain_note)
      : c_(c), run_(run), dir_(std::move(dir)), toolchain_note_(std::move(toolchain_note)) {}

  ReferenceSource source() const override { return {"images", "images in " + (run_ ? run_->dir : dir_), false, toolchain_note_}; }
  const Result<ReferenceImage>* group_image() const override { return nullptr; }
  Result<ReferenceImage> cell_image(const CellResult& r) const override {
    if (!run_) return fail(ErrorStage::reference, "the stored images in " + dir_ + " are not loaded here");
    return load_stored_image(*run_, r.id(), r.scene_hash);
  }
  bool notes_textures() const override { return !c_.differential(); }

 private:
  const Case& c_;
  const StoredRun* run_;   // null: the folder was not loaded (the viewer loads none)
  std::string dir_;
  std::string toolchain_note_;
};

// --against DIR, or the case's `reference = { images = "DIR" }`.
class StoredKind final : public ReferenceKind {
 public:
  explicit StoredKind(const StoredReferences& stored) : stored_(stored) {}
  bool judges(const Case& c, const CellSettings& s) const override {
    return !s.against_dir.empty() || !c.reference_images.empty();
  }
  std::unique_ptr<CellReference> prepare(const GroupScene& g, GroupDrawer&) override {
    const std::string& dir = g.settings.against_dir.empty() ? g.group.c->reference_images : g.settings.against_dir;
    const auto run = stored_.runs.find(dir);
    const auto note = stored_.toolchain_notes.find(dir);
    return std::make_unique<StoredReference>(*g.group.c, run == stored_.runs.end() ? nullptr : &run->second, dir,
                                             note == stored_.toolchain_notes.end() ? "" : note->second);
  }

 private:
  const StoredReferences& stored_;
};

}  // namespace

std::unique_ptr<ReferenceKind> stored_reference_kind(const StoredReferences& stored) {
  return std::make_unique<StoredKind>(stored);
}

}  // namespace shaderbed
