#pragma once
// Helpers for the report tests: a tiny PNG writer (stored deflate, no zlib), a sample run
// with real image files, and the folders the tests write to.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed::test {

namespace fs = std::filesystem;

inline uint32_t crc32(const std::string& bytes, size_t from = 0) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xffffffffu;
  for (size_t i = from; i < bytes.size(); ++i) c = table[(c ^ uint8_t(bytes[i])) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

inline void put32(std::string& s, uint32_t v) {
  for (int shift : {24, 16, 8, 0}) s += char((v >> shift) & 0xff);
}

// An 8-bit RGB PNG, uncompressed (zlib stored blocks). rgb: width*height*3 bytes.
inline std::string png_bytes(int width, int height, const std::vector<uint8_t>& rgb) {
  std::string raw;
  for (int y = 0; y < height; ++y) {
    raw += char(0);   // filter: none
    raw.append(reinterpret_cast<const char*>(rgb.data()) + size_t(y) * width * 3, size_t(width) * 3);
  }
  std::string z = "\x78\x01";
  for (size_t at = 0; at < raw.size() || at == 0; at += 65535) {
    const size_t n = std::min<size_t>(65535, raw.size() - at);
    z += char(at + n >= raw.size() ? 1 : 0);
    z += char(n & 0xff);
    z += char(n >> 8);
    z += char(~n & 0xff);
    z += char((~n >> 8) & 0xff);
    z.append(raw, at, n);
    if (raw.empty()) break;
  }
  uint32_t a = 1, b = 0;
  for (unsigned char c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
  put32(z, b << 16 | a);

  std::string png = "\x89PNG\r\n\x1a\n";
  auto chunk = [&](const char* type, const std::string& data) {
    put32(png, uint32_t(data.size()));
    const size_t start = png.size();
    png += type;
    png += data;
    put32(png, crc32(png, start));
  };
  std::string ihdr;
  put32(ihdr, uint32_t(width));
  put32(ihdr, uint32_t(height));
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);   // 8 bit, RGB, deflate, no filter, no interlace
  chunk("IHDR", ihdr);
  chunk("IDAT", z);
  chunk("IEND", "");
  return png;
}

// A shaded disc on a dark background; `shift` moves its highlight, `error` draws a heat map.
inline void write_test_png(const fs::path& path, int size, double shift, bool error = false) {
  std::vector<uint8_t> rgb(size_t(size) * size * 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size * 2 - 1, v = (y + 0.5) / size * 2 - 1, r2 = u * u + v * v;
      uint8_t* p = &rgb[(size_t(y) * size + x) * 3];
      if (r2 > 0.8) {
        p[0] = p[1] = p[2] = 24;
        continue;
      }
      const double nz = std::sqrt(1 - r2 / 0.8);
      const double lit = std::clamp(0.3 * (u + shift) - 0.4 * v + 0.85 * nz, 0.0, 1.0);
      if (error) {
        const double e = std::clamp(std::abs(shift) * (1 + u) * 0.5, 0.0, 1.0);
        p[0] = uint8_t(255 * e), p[1] = uint8_t(64 * (1 - e)), p[2] = uint8_t(128 * (1 - e));
      } else {
        p[0] = uint8_t(255 * lit), p[1] = uint8_t(200 * lit), p[2] = uint8_t(120 * lit);
      }
    }
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << png_bytes(size, size, rgb);
}

inline void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A fresh folder under the system temp dir, removed by the caller.
inline fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_report_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// build/tests/report/ (next to build/bin/, where the test runs from): kept artefacts.
inline fs::path artefact_dir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  fs::path dir = ec ? fs::current_path() / "report" : exe.parent_path().parent_path() / "tests" / "report";
  if (const char* env = std::getenv("SHADERBED_TEST_ARTEFACTS")) dir = env;
  fs::create_directories(dir, ec);
  return dir;
}

// A run with every kind of cell and real artefact files under `out`:
//   0 pass, 1 fail (driver), 2 known failure, 3 error, 4 fail whose PNGs are missing,
//   5 pass in another group (markup characters in its message and attribution).
inline RunReport sample_report(const fs::path& out, int size = 48) {
  RunReport report;
  report.out_dir = out.string();
  report.tools = {"glslang 11:12.0.0", "SPIRV-Tools v2022.4", "spirv-cross 2022.12.01", "Mesa 22.3.6 (LLVM 15.0.6)",
                  "Mesa 22.3.6 llvmpipe", "15.0.6"};
  report.wall_ms = 1234.5;
  report.shard = "";
  const fs::path group = out / "lambert" / "pixel" / "sphere";
  write_test_png(group / "reference.png", size, 0);
  write_text(out / "lambert" / "pixel" / "glsl.frag.spvasm", "; SPIR-V\n; Version: 1.0\nOpCapability Shader\n");
  write_text(out / "lambert" / "pixel" / "glsl.vert.spvasm", "; SPIR-V\nOpCapability Shader\n");
  write_text(out / "lambert" / "pixel" / "hlsl.frag.cross.glsl", "#version 450\nvoid main() { /* <&> */ }\n");

  auto cell = [&](std::string lang, std::string backend, std::string path, std::string shape, std::string status) {
    CellResult r;
    r.case_name = "lambert";
    r.variant = "pixel";
    r.language = std::move(lang);
    r.backend = std::move(backend);
    r.path = std::move(path);
    r.shape = std::move(shape);
    r.status = *parse_cell_status(status);
    r.interior_threshold = 2e-3;
    r.silhouette_threshold = 2e-2;
    r.time_ms = {{"compile", 3.5}, {"reference", 12.25}, {"build", 1.5}, {"draw", 0.75}, {"readback", 0.25}, {"compare", 0.5}};
    r.gpu = {"timestamp queries", 1, 5, {0.625, 0.5, 0.875, 0.9375}, {0.75, 0.6875, 1.125, 0.9375}};
    r.vertex_instructions = 10;
    r.fragment_instructions = 34;
    r.metrics.interior_pixels = 1200;
    r.metrics.silhouette_pixels = 180;
    r.metrics.covered_pixels = r.metrics.reference_covered_pixels = 1380;
    r.metrics.expected_area = 1379.6;
    r.vertex_spirv_hash = "0123456789abcdef";
    r.fragment_spirv_hash = "fedcba9876543210";
    return r;
  };
  auto images = [&](CellResult& r, double shift) {
    const fs::path dir = out / r.case_name / r.variant / r.shape;
    const std::string stem = r.language + "-" + r.backend + "-" + r.path;
    r.artefacts.render_png = (dir / (stem + ".png")).string();
    r.artefacts.error_png = (dir / (stem + ".error.png")).string();
    r.artefacts.render_exr = (dir / (stem + ".exr")).string();
    r.artefacts.error_exr = (dir / (stem + ".error.exr")).string();
    r.artefacts.reference_png = (dir / "reference.png").string();
    if (!fs::exists(r.artefacts.reference_png)) write_test_png(r.artefacts.reference_png, size, 0);
    write_test_png(r.artefacts.render_png, size, shift);
    write_test_png(r.artefacts.error_png, size, shift, true);
  };

  CellResult pass = cell("glsl", "vulkan", "spirv", "sphere", "pass");
  pass.metrics.max_abs = 4.2e-4;
  pass.metrics.rmse = 1e-4;
  pass.metrics.psnr = 80;
  pass.metrics.min_passing_interior = 4.2e-4;
  pass.metrics.min_passing_silhouette = 3e-3;
  pass.artefacts.vertex_spirv = (out / "lambert" / "pixel" / "glsl.vert.spvasm").string();
  pass.artefacts.fragment_spirv = (out / "lambert" / "pixel" / "glsl.frag.spvasm").string();
  images(pass, 0.001);

  CellResult fail = cell("glsl", "gl", "native", "sphere", "fail");
  fail.message = "interior max error 1.30e-01 > 2.00e-03";
  fail.attribution = "driver";
  fail.attribution_reason = "only gl/native differs from the other renders and the reference";
  fail.metrics.max_abs = 0.13;
  fail.metrics.rmse = 0.02;
  fail.metrics.psnr = 33.9;
  fail.metrics.bad_pixels = 411;
  fail.metrics.min_passing_interior = 0.13;
  fail.metrics.min_passing_silhouette = 0.2;
  fail.metrics.silhouette_max_abs = 0.2;
  images(fail, 0.6);

  CellResult known = cell("hlsl", "gl", "cross", "sphere", "fail");
  known.message = "interior max error 9.00e-03 > 2.00e-03";
  known.known_failure = true;
  known.known_reason = "SPIRV-Cross 2022 drops precise on the GL path (issue #12)";
  known.attribution = "cross-compiler";
  known.attribution_reason = "only the SPIRV-Cross path differs";
  known.metrics.max_abs = 9e-3;
  known.metrics.rmse = 1e-3;
  known.metrics.psnr = std::numeric_limits<double>::infinity();
  known.metrics.min_passing_interior = 9e-3;
  known.artefacts.fragment_cross_glsl = (out / "lambert" / "pixel" / "hlsl.frag.cross.glsl").string();
  known.artefacts.vertex_cross_glsl = (out / "lambert" / "pixel" / "no-such.vert.glsl").string();
  images(known, 0.15);

  CellResult error = cell("cg", "vulkan", "spirv", "cube", "error");
  error.message = "shaders/lambert.cg:12:5: compile: 'float4' : undeclared identifier\nsecond line";
  error.time_ms = {{"compile", 2.0}};

  CellResult missing = cell("glsl", "vulkan", "spirv", "torus", "fail");
  missing.message = "render coverage 0 pixels, reference 1380 (blank render)";
  missing.attribution = "unclear";
  missing.metrics.max_abs = std::numeric_limits<double>::quiet_NaN();
  missing.metrics.nonfinite = 1380;
  missing.metrics.nonfinite_mismatch = 1380;
  missing.metrics.render_values.nan = 1380;
  missing.artefacts.render_png = (out / "lambert/pixel/torus/gone.png").string();
  missing.artefacts.error_png = (out / "lambert/pixel/torus/gone.error.png").string();
  missing.artefacts.reference_png = (out / "lambert/pixel/torus/reference.png").string();

  CellResult odd = cell("glsl", "gl", "spirv", "cone", "pass");
  odd.case_name = "phong<&>\"'";
  odd.message = "note: <script>alert(1)</script> & \"quotes\" \x01 control \xff byte";
  odd.metrics.max_abs = 1e-5;
  odd.metrics.min_passing_interior = 1e-5;
  images(odd, 0.0);

  report.results = {pass, fail, known, error, missing, odd};
  return report;
}

// A run without files, for the summary matrix and the console views:
//   0 phong/pixel glsl vulkan/spirv sphere pass (4e-4)   1 ... cube fail (0.2, driver)
//   2 phong/pixel glsl gl/glsl sphere pass (3e-4)        3 phong/pixel hlsl gl/cross sphere known (0.01)
//   4 phong/vertex hlsl vulkan/spirv sphere error        5 lambert/pixel glsl vulkan/spirv sphere pass (NaN)
//   6 lambert/pixel glsl vulkan/spirv cube pass (0.5; a known failure that passed)
inline RunReport matrix_report() {
  auto cell = [](std::string case_name, std::string variant, std::string lang, std::string backend, std::string path,
                 std::string shape, std::string status, double max_abs) {
    CellResult r;
    r.case_name = std::move(case_name);
    r.variant = std::move(variant);
    r.language = std::move(lang);
    r.backend = std::move(backend);
    r.path = std::move(path);
    r.shape = std::move(shape);
    r.status = *parse_cell_status(status);
    r.metrics.max_abs = r.metrics.min_passing_interior = max_abs;
    r.interior_threshold = 2e-3;
    return r;
  };
  RunReport report;
  report.wall_ms = 2500;
  report.results = {cell("phong", "pixel", "glsl", "vulkan", "spirv", "sphere", "pass", 4e-4),
                    cell("phong", "pixel", "glsl", "vulkan", "spirv", "cube", "fail", 0.2),
                    cell("phong", "pixel", "glsl", "gl", "glsl", "sphere", "pass", 3e-4),
                    cell("phong", "pixel", "hlsl", "gl", "cross", "sphere", "fail", 0.01),
                    cell("phong", "vertex", "hlsl", "vulkan", "spirv", "sphere", "error", 0),
                    cell("lambert", "pixel", "glsl", "vulkan", "spirv", "sphere", "pass",
                         std::numeric_limits<double>::quiet_NaN()),
                    cell("lambert", "pixel", "glsl", "vulkan", "spirv", "cube", "pass", 0.5)};
  report.results[1].message = "interior max error 2.00e-01 > 2.00e-03";
  report.results[1].attribution = "driver";
  report.results[1].attribution_reason = "only vulkan differs";
  report.results[3].message = "interior max error 1.00e-02 > 2.00e-03";
  report.results[3].known_failure = true;
  report.results[3].known_reason = "SPIRV-Cross drops precise";
  report.results[4].message = "shaders/hlsl/phong_vs.hlsl:3: compile: syntax error";
  report.results[6].known_failure = true;
  report.results[6].known_reason = "flaky once";
  return report;
}

// `cases` x 3 variants x the 10 language/backend/path columns x 4 shapes, a PNG render and
// error map per cell and a reference per case/variant/shape under `out`, the first cell
// failing: a default-suite-sized report for the HTML image policy.
inline RunReport many_cell_report(const fs::path& out, int cases, int size = 32) {
  static const char* const columns[][3] = {{"hlsl", "vulkan", "spirv"}, {"hlsl", "gl", "spirv"}, {"hlsl", "gl", "cross"},
                                           {"cg", "vulkan", "spirv"},   {"cg", "gl", "spirv"},   {"cg", "gl", "cross"},
                                           {"glsl", "vulkan", "spirv"}, {"glsl", "gl", "glsl"},  {"glsl", "gl", "spirv"},
                                           {"glsl", "gl", "cross"}};
  RunReport report;
  report.out_dir = out.string();
  for (int c = 0; c < cases; ++c)
    for (const char* variant : {"pixel", "pixel_lut", "vertex"})
      for (const char* shape : {"cone", "cube", "sphere", "torus"}) {
        const std::string case_name = "case" + std::to_string(c);
        const fs::path dir = out / case_name / variant / shape;
        write_test_png(dir / "reference.png", size, 0);
        for (const auto& col : columns) {
          CellResult r;
          r.case_name = case_name;
          r.variant = variant;
          r.language = col[0];
          r.backend = col[1];
          r.path = col[2];
          r.shape = shape;
          r.status = report.results.empty() ? CellStatus::fail : CellStatus::pass;
          r.metrics.max_abs = report.results.empty() ? 0.25 : 1e-4;
          r.interior_threshold = 2e-3;
          const std::string stem = r.language + "-" + r.backend + "-" + r.path;
          r.artefacts.reference_png = (dir / "reference.png").string();
          r.artefacts.render_png = (dir / (stem + ".png")).string();
          r.artefacts.error_png = (dir / (stem + ".error.png")).string();
          write_test_png(r.artefacts.render_png, size, 0.001);
          write_test_png(r.artefacts.error_png, size, 0.001, true);
          report.results.push_back(std::move(r));
        }
      }
  return report;
}

}  // namespace shaderbed::test
