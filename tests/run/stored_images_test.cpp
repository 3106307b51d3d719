// A folder of stored images (run --save-images / --against) is a user's known-good data:
// the run judged by it may not write into it, a run that saves into it replaces its
// images only as a whole, once it has finished, concurrent runs keep each other's
// entries, and a manifest is read strictly (no file outside the folder, no device, no
// field of the wrong type).
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::read_text;
using shaderbed::test::shaderbed_cli;
using shaderbed::test::TempDir;
namespace fs = std::filesystem;
using nlohmann::json;

const std::string kLibraryCases = (fs::path(SHADERBED_SOURCE_DIR) / "shaders" / "cases").string();
// One cell, tiny: what these tests judge is the folder, not the pixels.
const std::string kOneTinyCell = " --variant pixel --lang glsl --backend vulkan --shape sphere --size 16 --repeat 0 -q";

// Every file of a folder (hidden ones too) and its bytes.
std::map<std::string, std::string> folder_files(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = read_text(e.path());
  return files;
}

bool no_staging_folder_left(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().starts_with(".staging")) return false;
  return true;
}

int line_count(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

// `shaderbed ARGS`, started without waiting: its pid (output to `log`).
pid_t start_shaderbed(const std::string& args, const std::string& log) {
  const std::string command = std::string("exec ") + SHADERBED_BINARY + " " + args + " >" + log + " 2>&1";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

int exit_status_of(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// A known-good set of lambert's one cell, saved under dir/good.
std::string save_known_good_lambert(const TempDir& dir) {
  const std::string good = dir / "good";
  const auto [status, out] = shaderbed_cli("run --case lambert --cases-dir " + kLibraryCases + kOneTinyCell + " --save-images " + good);
  EXPECT_EQ(status, 0) << out;
  EXPECT_TRUE(fs::exists(fs::path(good) / "manifest.json")) << out;
  return good;
}

TEST(StoredImages, ARunMayNotWriteIntoTheFolderThatJudgesIt) {
  TempDir dir("stored_refuse");
  const std::string good = save_known_good_lambert(dir);
  const auto before = folder_files(good);
  fs::create_directory_symlink(good, dir / "alias");
  const std::string run = "run --case lambert --cases-dir " + kLibraryCases + kOneTinyCell;
  for (const std::string& options :
       {" --against " + good + " --save-images " + good,                        // judged by what it replaces
        " --against " + dir / "alias" + " --save-images " + good + "/",         // the same folder, by another name
        " --against " + good + " --save-images " + good + "/new",               // one inside the other
        " --against " + good + " --out " + good,                                // renders over the stored EXRs
        " --against " + good + "/../good --out " + dir.path().string(),         // the set inside --out
        " --save-images " + dir / "fresh" + " --out " + dir / "fresh"}) {       // a set that holds renders
    const auto [status, out] = shaderbed_cli(run + options);
    EXPECT_EQ(status, 2) << options << "\n" << out;
    EXPECT_EQ(line_count(out), 1) << options << "\n" << out;
    EXPECT_TRUE(out.starts_with("shaderbed: ")) << options << "\n" << out;
    EXPECT_TRUE(folder_files(good) == before) << options;
  }
  EXPECT_FALSE(fs::exists(dir / "fresh/manifest.json"));
  EXPECT_FALSE(fs::exists(dir / "lambert")) << "refused before anything was drawn";
}

TEST(StoredImages, AFolderOfAnotherSizeIsRefusedBeforeItsImagesAreTouched) {
  TempDir dir("stored_size");
  const std::string good = save_known_good_lambert(dir);
  const auto before = folder_files(good);
  const auto [status, out] =
      shaderbed_cli("run --case lambert --cases-dir " + kLibraryCases + std::regex_replace(kOneTinyCell, std::regex("--size 16"), "--size 24") +
                    " --save-images " + good);
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("16x16"), std::string::npos) << out;
  EXPECT_TRUE(folder_files(good) == before);
  EXPECT_TRUE(no_staging_folder_left(good));
}

TEST(StoredImages, AnInterruptedSaveLeavesTheOldSetWhole) {
  TempDir dir("stored_interrupt");
  const std::string good = save_known_good_lambert(dir);
  const auto before = folder_files(good);
  std::map<std::string, fs::file_time_type> written;
  for (const auto& e : fs::recursive_directory_iterator(good)) written[e.path().string()] = e.last_write_time();
  // Many cells, one worker: the first image is written long before the last.
  const pid_t pid = start_shaderbed("run --case lambert --cases-dir " + kLibraryCases +
                                  " --lang glsl,hlsl --size 16 --repeat 0 -q --jobs 1 --save-images " + good,
                              dir / "log");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool drawn = false;
  while (!drawn && std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(good, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      if (it->path().extension() == ".exr" &&
          (!written.contains(it->path().string()) || written.at(it->path().string()) != it->last_write_time(ec)))
        drawn = true;   // a new image: staged, or (as runs did) written over the known-good one
    if (!drawn) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_TRUE(drawn) << read_text(dir / "log");
  kill(pid, SIGINT);
  EXPECT_EQ(exit_status_of(pid), 128 + SIGINT) << read_text(dir / "log");
  EXPECT_TRUE(folder_files(good) == before) << read_text(dir / "log");
  EXPECT_TRUE(no_staging_folder_left(good));
}

TEST(StoredImages, ConcurrentSavesIntoOneFolderKeepEveryEntry) {
  TempDir dir("stored_concurrent");
  const std::string shared = dir / "shared";
  const std::vector<std::string> cases = {"lambert", "phong", "blinn_phong", "minnaert", "oren_nayar"};
  std::vector<pid_t> runs;
  for (const std::string& c : cases)
    runs.push_back(start_shaderbed("run --case " + c + " --cases-dir " + kLibraryCases + kOneTinyCell + " --jobs 1 --save-images " + shared,
                             dir / (c + ".log")));
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(exit_status_of(runs[i]), 0) << read_text(dir / (cases[i] + ".log"));
  const json manifest = json::parse(read_text(fs::path(shared) / "manifest.json"));
  for (const std::string& c : cases) {
    const std::string id = c + "/pixel/glsl/vulkan/spirv/sphere";
    ASSERT_TRUE(manifest["images"].contains(id)) << id << "\n" << manifest.dump(1);
    EXPECT_TRUE(fs::exists(fs::path(shared) / manifest["images"][id]["file"].get<std::string>()));
  }
  EXPECT_TRUE(no_staging_folder_left(shared));
}

// The lock concurrent saves take: a run that has drawn waits for it before it touches the
// manifest (the concurrent test above shows the effect, this the protocol, deterministically).
TEST(StoredImages, ASaveWaitsForTheFolderLockBeforeItWritesTheManifest) {
  TempDir dir("stored_lock");
  const fs::path shared = dir.path() / "shared";
  fs::create_directories(shared);
  const int lock = open((shared / ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(lock, 0);
  ASSERT_EQ(flock(lock, LOCK_EX), 0);
  const pid_t pid = start_shaderbed("run --case lambert --cases-dir " + kLibraryCases + kOneTinyCell +
                                        " --save-images " + shared.string(),
                                    dir / "log");
  // Drawn: its image is staged (or, unlocked, the manifest is written).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool drawn = false;
  while (!drawn && std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(shared, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      drawn = drawn || it->path().filename() == "glsl-vulkan-spirv.exr" || it->path().filename() == "manifest.json";
    if (!drawn) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(drawn) << read_text(dir / "log");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  int status = 0;
  EXPECT_EQ(waitpid(pid, &status, WNOHANG), 0) << "the run finished while the folder was locked";
  EXPECT_FALSE(fs::exists(shared / "manifest.json"));
  EXPECT_FALSE(fs::exists(shared / "lambert")) << "an image moved in while the folder was locked";
  close(lock);
  EXPECT_EQ(exit_status_of(pid), 0) << read_text(dir / "log");
  EXPECT_TRUE(fs::exists(shared / "lambert/pixel/sphere/glsl-vulkan-spirv.exr"));
  EXPECT_TRUE(json::parse(read_text(shared / "manifest.json"))["images"].contains("lambert/pixel/glsl/vulkan/spirv/sphere"));
}

// A manifest entry naming a file outside its folder, and an EXR that is no regular file.
TEST(StoredImages, AManifestMayNameOnlyRegularFilesInsideItsFolder) {
  TempDir dir("stored_outside");
  const std::string good = save_known_good_lambert(dir);
  const fs::path manifest = fs::path(good) / "manifest.json";
  const std::string original = read_text(manifest);
  const std::string file = "lambert/pixel/sphere/glsl-vulkan-spirv.exr";
  fs::copy_file(fs::path(good) / file, dir / "elsewhere.exr");
  const std::string run = "run --case lambert --cases-dir " + kLibraryCases + kOneTinyCell + " --against " + good;
  for (const std::string& outside : {std::string("../elsewhere.exr"), dir / "elsewhere.exr"}) {
    std::string text = original;
    text.replace(text.find(file), file.size(), outside);
    std::ofstream(manifest) << text;
    const auto [status, out] = shaderbed_cli(run);
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find(manifest.string()), std::string::npos) << out;
    EXPECT_NE(out.find("lambert/pixel/glsl/vulkan/spirv/sphere"), std::string::npos) << out;
    EXPECT_NE(out.find("folder"), std::string::npos) << out;
  }
  std::ofstream(manifest) << original;
  // The stored EXR replaced by a FIFO or /dev/zero: the cell is an error, at once.
  const fs::path exr = fs::path(good) / file;
  for (const bool fifo : {true, false}) {
    fs::remove(exr);
    if (fifo) ASSERT_EQ(mkfifo(exr.c_str(), 0600), 0);
    else fs::create_symlink("/dev/zero", exr);
    const auto [status, out] = shaderbed::test::run_shell("timeout 20 " + std::string(SHADERBED_BINARY) + " " + run +
                                                          " --json " + dir / "r.json" + " >/dev/null; echo exit $?");
    (void)status;
    EXPECT_NE(out.find("exit 1"), std::string::npos) << out;
    const json r = json::parse(read_text(dir / "r.json"))["results"][0];
    EXPECT_EQ(r["status"], "error") << r.dump(1);
    EXPECT_NE(r["message"].get<std::string>().find("not a regular file"), std::string::npos) << r.dump(1);
  }
}

TEST(StoredImages, AManifestThatIsADeviceOrHasAFieldOfTheWrongTypeIsAClearError) {
  TempDir dir("stored_manifest");
  const std::string good = save_known_good_lambert(dir);
  const fs::path manifest = fs::path(good) / "manifest.json";
  const std::string original = read_text(manifest);
  const std::string run = std::string("timeout 20 ") + SHADERBED_BINARY + " run --case lambert --cases-dir " + kLibraryCases +
                          kOneTinyCell + " --against " + good + " 2>&1; echo exit $? #";
  const auto refused = [&](const std::string& what, const std::string& expected) {
    const auto [status, out] = shaderbed::test::run_shell("ulimit -v 4000000; " + run);
    EXPECT_NE(out.find("exit 2"), std::string::npos) << what << "\n" << out;
    EXPECT_NE(out.find("shaderbed: " + manifest.string()), std::string::npos) << what << "\n" << out;
    EXPECT_NE(out.find(expected), std::string::npos) << what << "\n" << out;
  };
  for (const auto& [from, to, expected] :
       {std::tuple<std::string, std::string, std::string>{"\"size\": 16", "\"size\": \"16\"", "'size' is a string"},
        {"\"scene\": \"", "\"scene\": 7, \"x\": \"", "'scene' is a number"},
        {"\"images\": {", "\"images\": [], \"old\": {", "'images' is an array"},
        {"\"glslang\": \"", "\"glslang\": [], \"x\": \"", "'tools.glslang' is an array"}}) {
    std::string text = original;
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
    std::ofstream(manifest) << text;
    refused(to, expected);
  }
  fs::remove(manifest);
  fs::create_symlink("/dev/zero", manifest);
  refused("/dev/zero", "not a regular file");
  fs::remove(manifest);
  ASSERT_EQ(mkfifo(manifest.c_str(), 0600), 0);
  refused("a FIFO", "not a regular file");
}

}  // namespace
