#include "author/CaseDraft.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "author/CaseToml.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

// One value or a list: what a binding or parameter of so many components is written as.
std::string float_list(const std::vector<double>& values) {
  if (values.size() == 1) return toml_float(values[0]);
  toml::array list;
  for (double v : values) list.push_back(v);
  return toml_value(list);
}

std::string binding_value(const UniformGuess& g) {
  std::string value;
  if (g.sources.size() == 1 && !g.sources[0].name.empty()) {
    value = toml_string(g.sources[0].name);
  } else if (g.sources.size() == 1) {
    value = float_list(g.sources[0].literal);
  } else {
    // Several sources are one flat list: ["diffuse", 1.0] is a colour with alpha 1.
    toml::array list;
    for (const BindingSource& source : g.sources) {
      if (!source.name.empty()) list.push_back(source.name);
      for (double v : source.literal) list.push_back(v);
    }
    value = toml_value(list);
  }
  if (g.layout == MatrixLayout::row_vector) value = toml_inline_table({{"value", value}, {"layout", toml_string("row_vector")}});
  return value;
}

std::string simplified(std::string s) {
  std::string out;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c))) out += char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Each language's matrices switch together; any other doubt is its uniform's own.
std::string doubt_id(Language language, const UniformFacts& u, const UniformGuess& g) {
  return std::string(to_string(language)) + " " + (g.doubt_group.empty() ? u.name : g.doubt_group);
}

struct LanguageGuesses {
  const SurveyedLanguage* survey;
  std::vector<std::pair<const UniformFacts*, UniformGuess>> uniforms;
};

std::string relative_to(const fs::path& root, const std::string& file) {
  return fs::path(file).lexically_relative(root).generic_string();
}

// The image a texture most likely reads: one whose name shares the texture's, else the
// only image there is; "" when neither.
std::pair<std::string, std::string> image_for(const std::string& texture, const std::vector<std::string>& images) {
  const std::string t = simplified(texture);
  for (const std::string& image : images) {
    const std::string stem = simplified(fs::path(image).stem().string());
    if (!stem.empty() && (t.find(stem) != std::string::npos || stem.find(t) != std::string::npos))
      return {image, "the image named like the texture"};
  }
  if (images.size() == 1) return {images.front(), "the only image next to the shader: check it is the one"};
  return {"", ""};
}

}  // namespace

std::vector<std::string> images_in(const std::string& folder) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (entry.is_regular_file() &&
        (ext == ".png" || ext == ".exr" || ext == ".hdr" || ext == ".tga" || ext == ".dds" || ext == ".jpg" || ext == ".jpeg"))
      out.push_back(entry.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

CaseDraft draft_case(const std::vector<SurveyedLanguage>& languages, const std::string& case_path,
                     const std::vector<std::string>& images, const std::map<std::string, std::string>& switched) {
  const fs::path root = shader_root_of(fs::absolute(case_path).lexically_normal().string());
  CaseTomlWriter w;
  if (languages.empty()) return {};

  // Guess everything first: the parameters and the ambient colour go above the bindings.
  std::vector<LanguageGuesses> guesses;
  std::vector<GuessDoubt> doubts;
  std::map<std::string, std::pair<ParameterGuess, std::vector<std::string>>> parameters;
  bool uses_ambient = false;
  for (const SurveyedLanguage& s : languages) {
    LanguageGuesses lg{&s, {}};
    GuessContext context{.language = s.language};
    for (const UniformFacts& u : s.uniforms)
      if (u.columns > 1) {
        const auto g = guess_uniform(u, context);
        if (!g.sources.empty() && g.sources[0].name == "world") context.has_world_matrix = true;
      }
    for (const UniformFacts& u : s.uniforms) {
      UniformGuess g = guess_uniform(u, context);
      if (g.unsure()) {
        const std::string id = doubt_id(s.language, u, g);
        auto it = std::find_if(doubts.begin(), doubts.end(), [&](const GuessDoubt& d) { return d.id == id; });
        if (it == doubts.end()) {
          doubts.push_back({.id = id, .language = s.language, .uniforms = "", .guessed = g.doubt, .instead = "", .lines = {},
                            .switched = switched.contains(id)});
          it = doubts.end() - 1;
        }
        it->uniforms += (it->uniforms.empty() ? "'" : ", '") + u.name + "'";
        it->instead += (it->instead.empty() ? "" : "; ") + toml_entry(u.name, binding_value(g.alternatives.front()));
        if (it->switched) {
          UniformGuess alternative = g.alternatives.front();
          alternative.reason += "; init's check run switched to this: " + switched.at(id);
          alternative.doubt = g.doubt;
          alternative.doubt_group = g.doubt_group;
          alternative.alternatives = {std::move(g)};
          alternative.alternatives.front().alternatives.clear();
          g = std::move(alternative);
        }
      }
      for (const ParameterGuess& parameter : g.parameters) {
        auto& [p, users] = parameters.try_emplace(parameter.name, parameter, std::vector<std::string>{}).first->second;
        users.push_back(u.name);
      }
      for (const BindingSource& source : g.sources) uses_ambient |= source.name == "ambient_light";
      lg.uniforms.push_back({&u, std::move(g)});
    }
    guesses.push_back(std::move(lg));
  }

  std::string names;
  std::set<std::string> listed;
  for (const SurveyedLanguage& s : languages)
    for (const std::string& f : {s.files.vertex, s.files.fragment})
      if (listed.insert(f).second) names += (names.empty() ? "" : ", ") + fs::path(f).filename().string();
  const SurveyedLanguage& original = languages.front();
  w.line("# Case written by `shaderbed init` from " + names + ": check the TODOs.");
  w.line("# A differential case: no model; every cell is judged against the reference render of the");
  w.line("# first language given (the original). Run it: shaderbed run --case " + fs::path(case_path).filename().string());
  std::string description = fs::path(original.files.fragment).filename().string() + " (" + to_string(original.language) + ")";
  if (languages.size() == 1) {
    description += " drawn on every backend and path against its own Vulkan SPIR-V render";
  } else {
    description += " against its port" + std::string(languages.size() > 2 ? "s" : "") + " in";
    for (size_t i = 1; i < languages.size(); ++i) description += std::string(i > 1 ? "," : "") + " " + to_string(languages[i].language);
  }
  w.line(toml_entry("description", toml_string(description)));
  w.line(toml_entry("reference", toml_inline_table({{"language", toml_string(to_string(original.language))},
                                                    {"backend", toml_string("vulkan")},
                                                    {"path", toml_string("spirv")}})));
  // The preprocessor's inputs init was given (--define, --include-dir), as the case keys them.
  if (!original.files.defines.empty()) {
    TomlEntries defines;
    for (const auto& [name, value] : original.files.defines) defines.emplace_back(name, toml_string(value));
    w.line(toml_entry("defines", toml_inline_table(defines)));
  }
  if (!original.files.include_dirs.empty()) {
    std::string dirs;
    for (const std::string& d : original.files.include_dirs) dirs += (dirs.empty() ? "" : ", ") + toml_string(relative_to(root, d));
    w.line(toml_entry("include_dirs", "[" + dirs + "]"));
  }
  if (uses_ambient)
    w.commented(toml_entry("ambient", float_list({0.1, 0.1, 0.1})), "the scene's ambient light colour, what ambient_light binds");

  if (!parameters.empty()) {
    w.header("params");
    for (const auto& [name, entry] : parameters) {
      std::string users;
      for (const std::string& u : entry.second) users += (users.empty() ? "'" : ", '") + u + "'";
      w.commented(toml_entry(name, float_list(entry.first.value)), entry.first.reason + " (for " + users + ")");
    }
  }

  w.header("variants.pixel");
  for (const SurveyedLanguage& s : languages) {
    TomlEntries files = {{"vertex", toml_string(relative_to(root, s.files.vertex))},
                         {"fragment", toml_string(relative_to(root, s.files.fragment))}};
    if (!s.files.technique.empty()) {
      files.emplace_back("technique", toml_string(s.files.technique));
      if (!s.files.pass.empty()) files.emplace_back("pass", toml_string(s.files.pass));
    } else if (s.language != Language::glsl) {
      files.emplace_back("vertex_entry", toml_string(s.files.vertex_entry));
      files.emplace_back("fragment_entry", toml_string(s.files.fragment_entry));
    }
    std::string note;
    for (const std::string& n : s.notes) note += (note.empty() ? "" : "; ") + n;
    w.commented(toml_entry(to_string(s.language), toml_inline_table(files)), note);
  }

  for (const LanguageGuesses& lg : guesses) {
    const SurveyedLanguage& s = *lg.survey;
    const std::string table = std::string("bindings.") + to_string(s.language);
    if (!s.compile_error.empty()) {
      w.header(table);
      w.todo("", "make " + std::string(to_string(s.language)) + " compile, then bind its uniforms here (or run init again "
                 "with --force): " + s.compile_error);
      continue;
    }
    if (lg.uniforms.empty()) continue;
    w.header(table);
    for (const auto& [u, g] : lg.uniforms) {
      if (!u->read) w.commented("# " + toml_key(u->name), "declared but never read by the compiled shader: needs no binding");
      else if (g.bound_by_default) w.commented("# " + toml_key(u->name), g.reason);
      else if (g.todo()) w.todo("# " + toml_entry(u->name, float_list(g.placeholder)), g.reason + ", under [" + table + "]");
      else {
        if (g.unsure() || !g.alternatives.empty())
          for (GuessDoubt& d : doubts)
            if (d.id == doubt_id(s.language, *u, g)) d.lines.push_back(w.next_line());
        w.commented(toml_entry(u->name, binding_value(g)), g.reason);
      }
    }
  }

  for (const SurveyedLanguage& s : languages) {
    std::vector<std::pair<std::string, std::string>> mapped;   // line, comment
    std::vector<std::pair<std::string, std::string>> unmapped;
    for (const StageInput& input : s.inputs) {
      // HLSL/Cg inputs are placed by their semantics.
      if (s.language != Language::glsl && !input.semantic.empty()) continue;
      if (input.name.starts_with("gl_")) continue;
      if (auto a = guess_attribute(input.name))
        mapped.push_back({toml_entry(input.name, toml_string(a->attribute)), a->reason});
      else
        unmapped.push_back({"# " + toml_entry(input.name, toml_string("position")),
                            "map vertex input '" + input.name + "' (location " + std::to_string(input.location) +
                                ") to position, normal, tangent, texcoord or color"});
    }
    if (mapped.empty() && unmapped.empty()) continue;
    w.header(std::string("attributes.") + to_string(s.language));
    for (const auto& [code, why] : mapped) w.commented(code, why);
    for (const auto& [code, why] : unmapped) w.todo(code, why);
  }

  // Textures by the names each language's shaders declare; one [textures] table when
  // every language names them alike.
  std::vector<std::pair<Language, std::vector<SamplerBinding>>> textures;
  for (const SurveyedLanguage& s : languages)
    if (!s.samplers.empty()) textures.push_back({s.language, s.samplers});
  const auto names_of = [](const std::vector<SamplerBinding>& list) {
    std::set<std::string> out;
    for (const SamplerBinding& b : list) out.insert(b.name);
    return out;
  };
  const bool common = std::all_of(textures.begin(), textures.end(), [&](const auto& t) {
    return names_of(t.second) == names_of(textures.front().second);
  }) && (textures.size() == languages.size() || textures.size() <= 1);
  // Every language samples as the original does: its SamplerState (guessed: linear, wrap),
  // its effect's sampler_state, else the defaults (linear, clamp). A port sampling
  // otherwise would differ for a reason no shader has.
  const SurveyedLanguage& first_language = languages.front();
  std::string sampling_why;
  SamplerSettings sampling;
  for (const SamplerBinding& b : first_language.samplers)
    if (b.kind == SamplerKind::sampler && sampling_why.empty()) {
      sampling.address_u = sampling.address_v = sampling.address_w = AddressMode::wrap;
      sampling_why = "as the original's SamplerState '" + b.name + "' (a guess: a sampler state's usual settings)";
    }
  for (const auto& [name, settings] : first_language.declared_sampling)
    if (sampling_why.empty()) {
      sampling = settings;
      sampling_why = "as the original's sampler_state of '" + name + "'";
    }
  if (sampling_why.empty()) sampling_why = "as the original samples (the defaults)";
  const auto sampling_entries = [&] {
    return TomlEntries{{"filter", toml_string(to_string(sampling.mag_filter))}, {"address", toml_string(to_string(sampling.address_u))}};
  };
  for (size_t i = 0; i < textures.size(); ++i) {
    if (common && i > 0) break;
    const auto& [language, samplers] = textures[i];
    const bool port = language != first_language.language && !common;
    w.header(common ? "textures" : std::string("textures.") + to_string(language));
    for (const SamplerBinding& b : samplers) {
      if (b.kind == SamplerKind::sampler) {
        w.commented(toml_entry(b.name, toml_inline_table(sampling_entries())),
                    port ? sampling_why : "a guess: a sampler state's usual settings");
        continue;
      }
      if (!b.read) {
        w.commented("# " + toml_entry(b.name, toml_inline_table({{"file", toml_string("FILE.png")}})),
                    "declared but never sampled by the compiled shader: needs no texture");
        continue;
      }
      if (b.cube) {
        const toml::array faces{"+x.png", "-x.png", "+y.png", "-y.png", "+z.png", "-z.png"};
        w.todo("# " + toml_entry(b.name, toml_inline_table({{"file", toml_value(faces)}})),
               "bind cube map '" + b.name + "' to six image files (+X, -X, +Y, -Y, +Z, -Z)");
        continue;
      }
      const auto [image, why] = image_for(b.name, images);
      if (image.empty())
        w.todo("# " + toml_entry(b.name, toml_inline_table({{"file", toml_string("FILE.png")}})),
               "bind texture '" + b.name + "' to an image file");
      else if (port && b.kind == SamplerKind::combined) {
        TomlEntries entries{{"file", toml_string(relative_to(root, image))}};
        for (auto& entry : sampling_entries()) entries.push_back(std::move(entry));
        w.commented(toml_entry(b.name, toml_inline_table(entries)), why + "; sampled " + sampling_why);
      } else
        w.commented(toml_entry(b.name, toml_inline_table({{"file", toml_string(relative_to(root, image))}})), why);
    }
  }

  w.line();
  w.line("# no [tolerance]: differential cases default to a documented fp32 bound relative to the pixel's magnitude");
  std::string text = w.text();
  // The header asks for the TODOs only when there are some (same line count either way).
  if (w.todos().empty()) text.replace(text.find("check the TODOs."), 16, "check its guesses.");
  return {std::move(text), w.todos(), std::move(doubts)};
}

}  // namespace shaderbed
