#pragma once
// `run --save-images DIR` replaces a stored set as a whole. The run's workers write its
// images into a staging folder of its own inside DIR (hidden, .staging-XXXXXX); only when
// the run has finished are they moved over the old ones and the manifest rewritten, under
// a lock on DIR (so concurrent runs into one folder keep each other's entries), and a
// move or write that fails puts back what it replaced. A run that is refused, fails or
// is interrupted leaves the old set as it was; entries of other cells are kept.
#include <string>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

class StagedStoredImages {
 public:
  // Checks DIR's manifest (a folder of another image size than `size`, or a manifest
  // that cannot be read, is refused now rather than after the run) and makes the staging
  // folder.
  static Result<StagedStoredImages> begin(const std::string& dir, int size);

  StagedStoredImages(StagedStoredImages&& other) noexcept;
  StagedStoredImages& operator=(StagedStoredImages&&) = delete;
  StagedStoredImages(const StagedStoredImages&) = delete;
  ~StagedStoredImages();   // removes the staging folder, with whatever was not moved in

  // Where the run's images are written (save_stored_image), by the workers too.
  const std::string& staging_dir() const { return staging_; }

  // Moves the report's saved cells (artefacts.stored_exr, in the staging folder) into DIR
  // and adds them to its manifest, all or none; their stored_exr then names them in DIR.
  Result<void> commit(RunReport& report);

 private:
  StagedStoredImages(std::string dir, std::string staging, int size, int owner_fd)
      : dir_(std::move(dir)), staging_(std::move(staging)), size_(size), owner_fd_(owner_fd) {}

  std::string dir_;
  std::string staging_;
  int size_ = 0;
  // A lock held on staging/.owner while this run lives: a later run removes a staging
  // folder whose owner lock it can take (its run was killed before it could clean up).
  int owner_fd_ = -1;
};

}  // namespace shaderbed
