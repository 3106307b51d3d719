#include "run/StagedStoredImages.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/AtomicFile.h"
#include "core/SignalsHeld.h"
#include "run/StoredImages.h"
#include "run/StoredManifest.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

constexpr const char* kStagingPrefix = ".staging-";

Error staging_error(const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .stage = ErrorStage::stored_images};
}

// An exclusive flock on `path` (created if `create`), waited for if `wait`; the
// descriptor, or -1.
int lock_file(const fs::path& path, bool wait, bool create) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW | (create ? O_CREAT : 0), 0644);
  if (fd < 0) return -1;
  int locked;
  do locked = ::flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB));
  while (locked != 0 && errno == EINTR);
  if (locked != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// The staging folders of runs that are gone (killed before they could remove their own):
// those whose owner lock can be taken. Called with DIR locked.
void remove_abandoned_staging(const fs::path& dir, const fs::path& own) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.path().filename().string().starts_with(kStagingPrefix) || entry.path() == own) continue;
    const int fd = lock_file(entry.path() / ".owner", false, false);
    if (fd < 0) continue;   // its run is alive (or still making it)
    fs::remove_all(entry.path(), ec);
    ::close(fd);
  }
}

// One image moved into the set, and where the one it replaced was put.
struct Move {
  fs::path into, previous;   // previous empty: there was none
};

// Puts back what `moves` replaced, last first.
void undo(const std::vector<Move>& moves) {
  std::error_code ec;
  for (auto it = moves.rbegin(); it != moves.rend(); ++it) {
    if (it->previous.empty()) fs::remove(it->into, ec);
    else fs::rename(it->previous, it->into, ec);
  }
}

}  // namespace

Result<StagedStoredImages> StagedStoredImages::begin(const std::string& dir, int size) {
  const fs::path manifest = fs::path(dir) / "manifest.json";
  std::error_code ec;
  if (fs::exists(fs::symlink_status(manifest, ec))) {
    auto existing = read_stored_manifest(manifest.string());
    if (!existing) return std::unexpected(existing.error());
    if (existing->size != size)
      return std::unexpected(staging_error(manifest.string(), fmt::format("the folder holds {0}x{0} images; this run "
                                                                         "draws {1}x{1} (save into another folder, or "
                                                                         "run with --size {0})",
                                                                         existing->size, size)));
  }
  fs::create_directories(dir, ec);
  std::string pattern = (fs::path(dir) / (std::string(kStagingPrefix) + "XXXXXX")).string();
  if (!::mkdtemp(pattern.data()))
    return std::unexpected(staging_error(dir, std::string("cannot make a staging folder: ") + std::strerror(errno)));
  const int owner = lock_file(fs::path(pattern) / ".owner", false, true);
  if (owner < 0) {
    const std::string why = std::strerror(errno);
    fs::remove_all(pattern, ec);
    return std::unexpected(staging_error(dir, "cannot lock the staging folder: " + why));
  }
  return StagedStoredImages(dir, pattern, size, owner);
}

StagedStoredImages::StagedStoredImages(StagedStoredImages&& other) noexcept
    : dir_(std::move(other.dir_)), staging_(std::exchange(other.staging_, {})), size_(other.size_),
      owner_fd_(std::exchange(other.owner_fd_, -1)) {}

StagedStoredImages::~StagedStoredImages() {
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);
  if (owner_fd_ >= 0) ::close(owner_fd_);
}

Result<void> StagedStoredImages::commit(RunReport& report) {
  const SignalsHeld held;   // a stop half-way would leave new images beside the old manifest
  const fs::path dir(dir_);
  const int lock = lock_file(dir / ".lock", true, true);
  if (lock < 0) return std::unexpected(staging_error(dir_, std::string("cannot lock the folder: ") + std::strerror(errno)));
  struct Unlock {
    int fd;
    ~Unlock() { ::close(fd); }
  } unlock{lock};

  // Read again under the lock: a concurrent run may have added its entries since begin().
  const fs::path manifest_file = dir / "manifest.json";
  StoredManifest manifest{.size = size_};
  std::error_code ec;
  if (fs::exists(fs::symlink_status(manifest_file, ec))) {
    auto existing = read_stored_manifest(manifest_file.string());
    if (!existing) return std::unexpected(existing.error());
    if (existing->size != size_)
      return std::unexpected(staging_error(manifest_file.string(),
                                          fmt::format("the folder holds {0}x{0} images now (another run saved "
                                                      "them); this run drew {1}x{1}: nothing was saved",
                                                      existing->size, size_)));
    manifest = std::move(*existing);
  }
  manifest.tools = report.tools;

  std::vector<Move> moves;
  const fs::path previous = fs::path(staging_) / ".previous";
  const auto failed = [&](const fs::path& file, const std::string& why) {
    undo(moves);
    return std::unexpected(staging_error(file.string(), "cannot move the stored image into place: " + why +
                                                           " (the folder is as it was)"));
  };
  for (const CellResult& r : report.results) {
    if (r.artefacts.stored_exr.empty()) continue;
    const std::string file = stored_image_file(r);
    const fs::path staged = fs::path(staging_) / file, into = dir / file;
    Move move{.into = into};
    fs::create_directories(into.parent_path(), ec);
    if (fs::exists(fs::symlink_status(into, ec))) {
      move.previous = previous / file;
      fs::create_directories(move.previous.parent_path(), ec);
      fs::rename(into, move.previous, ec);
      if (ec) return failed(into, ec.message());
    }
    fs::rename(staged, into, ec);
    if (ec) {
      const std::string why = ec.message();
      if (!move.previous.empty()) fs::rename(move.previous, into, ec);
      return failed(into, why);
    }
    moves.push_back(std::move(move));
    manifest.images[r.id()] = {.file = file, .scene = r.scene_hash, .vertex_spirv_hash = r.vertex_spirv_hash,
                               .fragment_spirv_hash = r.fragment_spirv_hash};
  }
  if (auto ok = write_file_atomically(manifest_file.string(), stored_manifest_text(manifest),
                                      "the stored-images manifest");
      !ok) {
    undo(moves);
    return ok;
  }
  for (CellResult& r : report.results)
    if (!r.artefacts.stored_exr.empty()) r.artefacts.stored_exr = (dir / stored_image_file(r)).string();
  remove_abandoned_staging(dir, staging_);
  return {};
}

}  // namespace shaderbed
