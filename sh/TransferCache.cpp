#include "sh/TransferCache.h"

#include <array>
#include <algorithm>
#include <atomic>
#include <bit>
#include <cstring>
#include <fstream>
#include <functional>
#include <string_view>
#include <system_error>
#include <thread>

#include <fmt/format.h>
#include <unistd.h>

#include "sh/Basis.h"

namespace sh {

namespace {

// A 128-bit content digest from two independently mixed 64-bit lanes over 8-byte words.
// Not cryptographic: it guards against accidents (an edited mesh, a flipped byte), and
// the header compares the key's fields themselves, so a name collision is never served.
class Digest {
 public:
  void bytes(const void* data, size_t size) {
    length_ += size;
    const auto* p = static_cast<const unsigned char*>(data);
    for (; size >= 8; p += 8, size -= 8) {
      uint64_t w;
      std::memcpy(&w, p, 8);
      word(w);
    }
    if (size > 0) {
      uint64_t w = 0;
      std::memcpy(&w, p, size);
      word(w ^ (uint64_t{0xA5} << 56));  // a short tail differs from the same bytes zero-padded
    }
  }
  template <typename T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  std::array<uint64_t, 2> finish() const {
    const uint64_t a = mix(a_ ^ length_);
    return {a, mix(b_ ^ std::rotl(a, 17) ^ words_)};
  }

 private:
  // splitmix64's finaliser: a bijection with full avalanche.
  static uint64_t mix(uint64_t x) {
    x ^= x >> 30;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBull;
    return x ^ (x >> 31);
  }
  void word(uint64_t w) {
    a_ = mix(a_ ^ w);
    b_ = std::rotl(b_ ^ (w * 0x87C37B91114253D5ull), 31) * 0x4CF5AD432745937Full + 0x52DCE729ull;
    ++words_;
  }
  uint64_t a_ = 0x9E3779B97F4A7C15ull;
  uint64_t b_ = 0xC2B2AE3D27D4EB4Full;
  uint64_t words_ = 0;
  uint64_t length_ = 0;
};

// Little helpers that append fixed-size fields to a byte string (host byte order: a file
// from a machine of the other endianness fails the key comparison and is recomputed).
template <typename T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

constexpr char magic[8] = {'S', 'H', 'B', 'T', 'R', 'A', 'N', 'S'};

// The full key, as bytes, in the order the header stores it.
std::string make_key(const TransferScene& scene, const TransferOptions& options, const std::vector<Sample>& samples) {
  std::string key(magic, sizeof magic);
  put(key, transfer_cache_version);
  put(key, static_cast<uint32_t>(options.kind));
  put(key, static_cast<int32_t>(options.bands));
  put(key, static_cast<int32_t>(options.grid));
  put(key, options.seed);
  put(key, static_cast<int32_t>(options.kind == TransferKind::interreflected ? options.bounces : 0));

  Digest sample_digest;
  for (const Sample& s : samples) {
    sample_digest.value(s.direction);
    sample_digest.value(s.weight);
  }
  put(key, static_cast<uint64_t>(samples.size()));
  for (uint64_t part : sample_digest.finish()) put(key, part);

  Digest scene_digest;
  put(key, static_cast<uint64_t>(scene.meshes().size()));
  for (const TransferMesh& mesh : scene.meshes()) {
    put(key, static_cast<uint64_t>(mesh.positions.size()));
    put(key, static_cast<uint64_t>(mesh.indices.size()));
    scene_digest.bytes(mesh.positions.data(), mesh.positions.size() * sizeof(glm::dvec3));
    scene_digest.bytes(mesh.normals.data(), mesh.normals.size() * sizeof(glm::dvec3));
    scene_digest.bytes(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    scene_digest.value(mesh.albedo);
  }
  for (uint64_t part : scene_digest.finish()) put(key, part);
  return key;
}

std::string hex(const std::array<uint64_t, 2>& digest) { return fmt::format("{:016x}{:016x}", digest[0], digest[1]); }

std::array<uint64_t, 2> checksum(std::string_view payload) {
  Digest digest;
  digest.bytes(payload.data(), payload.size());
  return digest.finish();
}

size_t payload_size(const TransferScene& scene, int bands) {
  size_t doubles = 0;
  for (const TransferMesh& mesh : scene.meshes()) doubles += 3 * mesh.positions.size() * static_cast<size_t>(coefficient_count(bands));
  return doubles * sizeof(double);
}

// File layout: key | u64 payload size | 2 × u64 payload checksum | payload (every
// mesh's coefficients in order, x y z doubles).
constexpr size_t trailer_of_header = sizeof(uint64_t) * 3;

std::expected<std::vector<VertexTransfer>, std::string> read_cache(const std::filesystem::path& file, const std::string& key,
                                                                   const TransferScene& scene, int bands) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return std::unexpected(std::string("no cache file"));
  std::string content(static_cast<size_t>(std::max<std::streamoff>(in.tellg(), 0)), '\0');
  in.seekg(0);
  if (!in.read(content.data(), static_cast<std::streamsize>(content.size())))
    return std::unexpected(std::string("cache file unreadable"));
  const size_t header = key.size() + trailer_of_header;
  if (content.size() < header) return std::unexpected(fmt::format("cache file truncated ({} bytes)", content.size()));
  if (content.compare(0, key.size(), key) != 0) return std::unexpected(std::string("cache file holds another key"));
  uint64_t stored_size = 0;
  std::array<uint64_t, 2> stored_sum{};
  std::memcpy(&stored_size, content.data() + key.size(), sizeof stored_size);
  std::memcpy(stored_sum.data(), content.data() + key.size() + sizeof stored_size, sizeof stored_sum);
  const size_t expected = payload_size(scene, bands);
  if (stored_size != expected || content.size() - header != expected)
    return std::unexpected(fmt::format("cache payload is {} bytes (header says {}), expected {}", content.size() - header,
                                       stored_size, expected));
  const std::string_view payload = std::string_view(content).substr(header);
  if (checksum(payload) != stored_sum) return std::unexpected(std::string("cache checksum mismatch"));

  std::vector<VertexTransfer> result;
  size_t offset = 0;
  for (const TransferMesh& mesh : scene.meshes()) {
    VertexTransfer t{bands, std::vector<glm::dvec3>(mesh.positions.size() * static_cast<size_t>(coefficient_count(bands)))};
    const size_t bytes = t.coefficients.size() * 3 * sizeof(double);
    for (size_t i = 0; i < t.coefficients.size(); ++i)
      std::memcpy(&t.coefficients[i], payload.data() + offset + i * 3 * sizeof(double), 3 * sizeof(double));
    offset += bytes;
    result.push_back(std::move(t));
  }
  return result;
}

std::expected<void, std::string> write_cache(const std::filesystem::path& file, const std::string& key,
                                             const std::vector<VertexTransfer>& transfer) {
  std::string payload;
  for (const VertexTransfer& t : transfer)
    for (const glm::dvec3& c : t.coefficients) {
      put(payload, c.x);
      put(payload, c.y);
      put(payload, c.z);
    }
  std::string content = key;
  put(content, static_cast<uint64_t>(payload.size()));
  for (uint64_t part : checksum(payload)) put(content, part);
  content += payload;

  // A name no other writer uses (process, thread, counter), renamed over the final file
  // only once complete: readers see the old file or the new one, never a partial one.
  static std::atomic<uint64_t> counter{0};
  const std::filesystem::path temporary =
      file.string() + fmt::format(".tmp.{}.{}.{}", static_cast<long>(::getpid()),
                                  std::hash<std::thread::id>{}(std::this_thread::get_id()), counter++);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return std::unexpected(fmt::format("cannot create {}", temporary.string()));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      return std::unexpected(fmt::format("cannot write {}", temporary.string()));
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return std::unexpected(fmt::format("cannot rename {} to {}: {}", temporary.string(), file.string(), error.message()));
  }
  return {};
}

}  // namespace

std::expected<CachedTransfer, std::string> cached_transfer_report(const TransferScene& scene, const TransferOptions& options,
                                                                  const std::filesystem::path& cache_dir,
                                                                  const TransferProgress& progress) {
  if (auto valid = check_transfer_options(options); !valid) return std::unexpected(valid.error());
  // The samples are generated here, once, so the key hashes exactly what is integrated.
  const std::vector<Sample> samples = jittered_samples(options.grid, options.seed);
  const std::string key = make_key(scene, options, samples);
  Digest name;
  name.bytes(key.data(), key.size());

  CachedTransfer result;
  result.file = cache_dir / fmt::format("transfer-{}.shtr", hex(name.finish()));
  if (auto stored = read_cache(result.file, key, scene, options.bands)) {
    result.transfer = std::move(*stored);
    return result;
  } else {
    result.reason = stored.error();
  }

  auto computed = compute_transfer(scene, options, samples, progress);
  if (!computed) return std::unexpected(computed.error());
  result.transfer = std::move(*computed);
  result.computed = true;
  std::error_code error;
  std::filesystem::create_directories(cache_dir, error);
  if (error) {
    result.write_error = fmt::format("cannot create {}: {}", cache_dir.string(), error.message());
  } else if (auto written = write_cache(result.file, key, result.transfer); !written) {
    result.write_error = written.error();
  }
  return result;
}

std::expected<std::vector<VertexTransfer>, std::string> cached_transfer(const TransferScene& scene, const TransferOptions& options,
                                                                        const std::filesystem::path& cache_dir,
                                                                        const TransferProgress& progress) {
  auto report = cached_transfer_report(scene, options, cache_dir, progress);
  if (!report) return std::unexpected(report.error());
  return std::move(report->transfer);
}

}  // namespace sh
