#include "author/ShaderSurvey.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "author/ShaderText.h"
#include "compile/Compiler.h"
#include "compile/EffectFile.h"
#include "compile/IsolatedCompile.h"
#include "compile/ShaderLabFrontEnd.h"
#include "scene/CaseProgram.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

std::string extension_of(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

Error bad_input(std::string message, std::string file = "") {
  return Error{.message = std::move(message), .file = std::move(file), .stage = ErrorStage::init};
}

struct Loaded {
  std::string path;   // absolute
  std::string text;
};

// GLSL says #version or uses gl_ built-ins; HLSL and Cg put semantics after a colon.
bool looks_like_glsl(std::string_view text) {
  return text.find("#version") != std::string_view::npos || text.find("gl_") != std::string_view::npos;
}
bool looks_like_hlsl(std::string_view text) {
  for (const char* semantic : {": POSITION", ":POSITION", ": SV_", ":SV_", ": COLOR", ": TEXCOORD"})
    if (text.find(semantic) != std::string_view::npos) return true;
  return false;
}

// A GLSL file's stage: by extension, else by what it writes.
Stage glsl_stage(const Loaded& file) {
  const std::string ext = extension_of(file.path);
  if (ext == ".vert" || ext == ".vs" || ext == ".vsh") return Stage::vertex;
  if (ext == ".frag" || ext == ".fs" || ext == ".fsh") return Stage::fragment;
  return glsl_stage_of(file.text);
}

Result<SurveyedLanguage> find_glsl_files(const std::vector<Loaded>& files) {
  SurveyedLanguage out{.language = Language::glsl};
  for (const Loaded& f : files) {
    std::string& slot = glsl_stage(f) == Stage::vertex ? out.files.vertex : out.files.fragment;
    if (!slot.empty())
      return std::unexpected(bad_input("a second GLSL " + std::string(to_string(glsl_stage(f))) + " shader (the first is " +
                                           slot + "); give one vertex and one fragment file per language",
                                       f.path));
    slot = f.path;
  }
  if (out.files.vertex.empty() || out.files.fragment.empty())
    return std::unexpected(bad_input(std::string("GLSL needs a vertex and a fragment shader; no ") +
                                         (out.files.vertex.empty() ? "vertex shader (.vert, or a file writing gl_Position)"
                                                                   : "fragment shader (.frag)") +
                                         " among the files given",
                                     files.front().path));
  return out;
}

// HLSL/Cg: a DX9 effect's first technique and pass, else the functions whose outputs
// carry POSITION (vertex) and COLOR (fragment), first found first.
Result<SurveyedLanguage> find_entries(Language language, const std::vector<Loaded>& files) {
  SurveyedLanguage out{.language = language};
  // A Unity ShaderLab file: its program block's #pragma vertex / fragment (compile/ShaderLabFrontEnd.h).
  for (const Loaded& f : files) {
    if (!is_shaderlab_file(f.path, f.text)) continue;
    auto program = extract_shaderlab_program(f.text, f.path);
    if (!program) return std::unexpected(program.error());
    if (program->vertex_entry.empty() || program->fragment_entry.empty())
      return std::unexpected(bad_input("the ShaderLab program block has no #pragma vertex / #pragma fragment", f.path));
    out.files.vertex = out.files.fragment = f.path;
    out.files.vertex_entry = program->vertex_entry;
    out.files.fragment_entry = program->fragment_entry;
    out.notes.push_back(std::string("entries: the #pragma vertex and fragment of its first ") +
                        (program->hlsl_block ? "HLSLPROGRAM" : "CGPROGRAM") + " block");
    return out;
  }
  for (const Loaded& f : files) {
    if (!is_effect_file(f.path, f.text)) continue;
    auto effect = parse_effect(f.text, f.path);
    if (!effect) return std::unexpected(effect.error());
    if (effect->techniques.empty()) continue;
    const EffectTechnique& t = effect->techniques.front();
    out.files.vertex = out.files.fragment = f.path;
    out.files.technique = t.name;
    for (const EffectSampler& sampler : effect->samplers) out.declared_sampling.emplace_back(sampler.name, sampler.settings);
    out.files.pass = t.passes.empty() ? "" : t.passes.front().name;
    std::string others;
    for (size_t i = 1; i < effect->techniques.size(); ++i) others += (others.empty() ? "" : ", ") + effect->techniques[i].name;
    out.notes.push_back("the effect's first technique and pass" + (others.empty() ? std::string() : "; also in the file: " + others));
    return out;
  }
  std::vector<std::pair<const Loaded*, EntryCandidate>> vertex, fragment;
  for (const Loaded& f : files) {
    auto found = entry_candidates(f.text, f.path);
    if (!found) return std::unexpected(found.error());
    for (const EntryCandidate& c : *found) (c.stage == Stage::vertex ? vertex : fragment).push_back({&f, c});
  }
  const auto none = [&](const char* stage, const char* outputs) {
    std::string names;
    for (const Loaded& f : files) names += (names.empty() ? "" : ", ") + f.path;
    return bad_input(std::string("no ") + stage + " entry point found: no function returns or writes " + outputs +
                         " (name it in the case as " + (stage[0] == 'v' ? "vertex_entry" : "fragment_entry") + ")",
                     names);
  };
  if (vertex.empty()) return std::unexpected(none("vertex", "POSITION or SV_Position"));
  if (fragment.empty()) return std::unexpected(none("fragment", "COLOR or SV_Target"));
  out.files.vertex = vertex.front().first->path;
  out.files.vertex_entry = vertex.front().second.function;
  out.files.fragment = fragment.front().first->path;
  out.files.fragment_entry = fragment.front().second.function;
  const auto also = [](const auto& list) {
    std::string s;
    for (size_t i = 1; i < list.size(); ++i) s += (s.empty() ? "" : ", ") + list[i].second.function;
    return s;
  };
  std::string note = "entries: the functions writing POSITION (" + out.files.vertex_entry + ") and COLOR (" +
                     out.files.fragment_entry + ")";
  if (const std::string v = also(vertex); !v.empty()) note += "; other vertex candidates: " + v;
  if (const std::string p = also(fragment); !p.empty()) note += "; other fragment candidates: " + p;
  out.notes.push_back(note);
  return out;
}

// Each uniform once, with what its declaration says.
void collect_reflection(SurveyedLanguage& out, const CompiledProgram& program, const std::string& vertex_text,
                        const std::string& fragment_text) {
  std::set<std::string> seen, seen_samplers;
  for (const ShaderModule* module : {&program.vertex, &program.fragment}) {
    const std::string& text = module == &program.vertex ? vertex_text : fragment_text;
    for (const UniformBlock& block : module->reflection.uniform_blocks)
      for (const UniformMember& m : block.members) {
        if (!seen.insert(m.name).second) {   // declared in both stages: read if either reads it
          for (UniformFacts& known : out.uniforms) known.read |= known.name == m.name && m.read;
          continue;
        }
        UniformFacts u{.name = m.name, .is_float = m.is_float, .vecsize = m.vecsize, .columns = m.columns,
                       .array_size = m.array_size, .read = m.read};
        if (out.language != Language::glsl) {
          u.semantic = declared_semantic(text, m.name);
          u.hlsl_register = block.name.empty() ? -1 : declared_register(text, m.name);
          if (m.columns > 1) {
            u.mul_order = mul_order(vertex_text, m.name);
            if (!u.mul_order) u.mul_order = mul_order(fragment_text, m.name);
          }
        }
        u.declared_space = declared_space(text, m.name);
        u.component_meanings = component_meanings(text, m.name);
        if (u.component_meanings.empty())
          u.component_meanings = component_meanings(&text == &vertex_text ? fragment_text : vertex_text, m.name);
        out.uniforms.push_back(std::move(u));
      }
    for (const SamplerBinding& s : module->reflection.samplers)
      if (seen_samplers.insert(s.name).second) out.samplers.push_back(s);
      else
        for (SamplerBinding& known : out.samplers) known.read |= known.name == s.name && s.read;
  }
  out.inputs = program.vertex.reflection.inputs;
}

}  // namespace

Result<Language> language_of_file(const std::string& path, std::string_view text) {
  const std::string ext = extension_of(path);
  if (ext == ".hlsl" || ext == ".fx" || ext == ".fxh" || ext == ".hlsli" || ext == ".ps") return Language::hlsl;
  if (ext == ".cg" || ext == ".cgh" || ext == ".cgfx") return Language::cg;
  if (ext == ".vert" || ext == ".frag" || ext == ".glsl" || ext == ".fs" || ext == ".vsh" || ext == ".fsh")
    return Language::glsl;
  if (is_shaderlab_file(path, text)) return text.find("HLSLPROGRAM") != std::string_view::npos ? Language::hlsl : Language::cg;
  // .vs is a GLSL vertex shader in GL samples and an HLSL one in D3D tutorials: the text says which.
  if (looks_like_glsl(text)) return Language::glsl;
  if (ext == ".vs" || looks_like_hlsl(text)) return Language::hlsl;
  return std::unexpected(bad_input("unknown shader extension '" + ext +
                                       "' (.hlsl/.fx/.fxh/.ps: hlsl; .cg: cg; .vert/.frag/.glsl/.vsh/.fsh/.fs: glsl; "
                                       ".shader: Unity ShaderLab; .vs and others by their text; or say --lang)",
                                   path));
}

Result<std::vector<SurveyedLanguage>> survey_shaders(const std::vector<std::string>& paths,
                                                     std::optional<Language> forced,
                                                     const SurveyPreprocessor& preprocessor) {
  if (paths.empty()) return std::unexpected(bad_input("no shader files given"));
  std::vector<Language> order;
  std::map<Language, std::vector<Loaded>> groups;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) return std::unexpected(bad_input("no such shader file", p));
    auto source = load_shader_source(Stage::vertex, fs::absolute(p).lexically_normal().string());
    if (!source) return std::unexpected(bad_input(source.error().message, p));
    auto language = forced ? Result<Language>(*forced) : language_of_file(p, source->text);
    if (!language) return std::unexpected(language.error());
    if (!groups.contains(*language)) order.push_back(*language);
    groups[*language].push_back({source->path, source->text});
  }
  std::vector<SurveyedLanguage> out;
  for (Language language : order) {
    const std::vector<Loaded>& files = groups[language];
    auto surveyed = language == Language::glsl ? find_glsl_files(files) : find_entries(language, files);
    if (!surveyed) return std::unexpected(surveyed.error());
    SurveyedLanguage& s = *surveyed;
    s.files.defines = preprocessor.defines;
    s.files.include_dirs = preprocessor.include_dirs;
    // Compiled as the runner compiles a case's files (scene/CaseProgram.h, compile_program).
    auto program_source = load_case_program(language, s.files, "");
    if (program_source) program_source->effect = {.technique = s.files.technique, .pass = s.files.pass, .named_in = "", .line = 0};
    Result<CompiledProgram> program = program_source ? compile_program(*program_source, false)
                                                     : Result<CompiledProgram>(std::unexpected(program_source.error()));
    // A compiler that crashed or hung on the shader (compile/IsolatedCompile.h) is no guess
    // to write down: the user's shader must change first.
    if (!program && compiler_did_not_finish(program.error())) return std::unexpected(program.error());
    if (program)
      collect_reflection(s, *program, program_source->vertex.text, program_source->fragment.text);
    else
      s.compile_error = program.error().to_string();
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace shaderbed
