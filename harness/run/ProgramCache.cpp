#include "run/ProgramCache.h"

#include <chrono>
#include <filesystem>

#include "compile/RelaxedPrecision.h"
#include "run/ProgramArtefacts.h"
#include "scene/CaseProgram.h"
#include "stats/SpirvCounts.h"

namespace shaderbed {
namespace {

Result<ProgramSource> relaxed(ProgramSource source) {
  for (ShaderSource* stage : {&source.vertex, &source.fragment}) {
    auto relaxed = relax_precision(source.language, std::move(*stage));
    if (!relaxed) return std::unexpected(relaxed.error());
    *stage = std::move(*relaxed);
  }
  return source;
}

// What an entry holds, near enough to budget by: its SPIR-V, its GLSL texts, and a fixed
// allowance for reflection and the strings around them.
size_t program_bytes(const CachedProgram& entry) {
  size_t bytes = 4096;
  if (!entry.program) return bytes + entry.program.error().to_string().size();
  const CompiledProgram& p = *entry.program;
  for (const ShaderModule* m : {&p.vertex, &p.fragment, &p.vertex_gl, &p.fragment_gl})
    bytes += m->spirv.size() * sizeof(uint32_t) + m->source_file.size();
  for (const std::string* text : {&p.vertex_cross_glsl, &p.fragment_cross_glsl, &p.vertex_native_glsl,
                                  &p.fragment_native_glsl})
    bytes += text->size();
  return bytes;
}

}  // namespace

const CachedProgram& ProgramCache::get(const Case& c, const Variant& variant, Language language) {
  const std::string key = c.name + "/" + variant.name + "/" + to_string(language);
  if (const CachedProgram* cached = programs_.find(key)) return *cached;
  CachedProgram entry;
  const auto t0 = std::chrono::steady_clock::now();
  const ShaderFiles& files = variant.shaders.at(language);
  auto source = load_case_program(language, files, c.path);
  // A DX9 effect's technique and pass (compile_program routes effects to their front end).
  if (source) source->effect = {.technique = files.technique, .pass = files.pass, .named_in = c.path, .line = files.line};
  if (source && options_.relaxed_precision) source = relaxed(std::move(*source));
  entry.program = source ? compile_program(*source, options_.opengl) : std::unexpected(source.error());
  if (entry.program) {
    auto vertex = stats::count_spirv(entry.program->vertex.spirv);
    auto fragment = stats::count_spirv(entry.program->fragment.spirv);
    if (vertex && fragment) entry.instructions = {vertex->total, fragment->total};
  }
  entry.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (entry.program && !options_.out_dir.empty())
    (void)write_program_artefacts((std::filesystem::path(options_.out_dir) / c.name / variant.name).string(),
                                  *entry.program, entry.sources);
  const size_t bytes = program_bytes(entry);
  return programs_.put(key, std::move(entry), bytes);
}

}  // namespace shaderbed
