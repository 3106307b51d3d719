#pragma once
// The parsers of a case file's sections, one file each (scene/CaseSection*.cpp), and the
// value readers they share (scene/CaseValues.cpp). load_case (scene/CaseFile.cpp) runs
// them in turn; nothing outside scene/ needs these.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "core/Error.h"
#include "scene/CaseFile.h"

namespace shaderbed::case_sections {

// The parsed case file, and the folder its shader, texture and probe paths are relative to.
struct CaseDocument {
  const std::string& path;
  const toml::table& root;
  std::filesystem::path shader_root;   // shader_root_of(path)
};

// Reads its part of the document into the case, or says where the file is wrong. Each
// checks only its own keys, after the sections before it have been read.
using SectionParser = Result<void> (*)(const CaseDocument& doc, Case& c);

Result<void> read_judged_against(const CaseDocument& doc, Case& c);   // model or reference (CaseSectionReference)
Result<void> read_tessellation(const CaseDocument& doc, Case& c);     // CaseSectionScene
Result<void> read_params(const CaseDocument& doc, Case& c);           // [params]
Result<void> read_variants(const CaseDocument& doc, Case& c);         // [variants.NAME]
// `defines` and `include_dirs`, merged into every variant's ShaderFiles (CaseSectionPreprocessor)
Result<void> read_preprocessor(const CaseDocument& doc, Case& c);
Result<void> read_bindings(const CaseDocument& doc, Case& c);         // [bindings.<language>]
Result<void> read_attributes(const CaseDocument& doc, Case& c);       // [attributes.<language>]
Result<void> read_light(const CaseDocument& doc, Case& c);            // CaseSectionScene
Result<void> read_ambient(const CaseDocument& doc, Case& c);          // CaseSectionScene
Result<void> read_sh(const CaseDocument& doc, Case& c);               // [sh]
Result<void> read_textures(const CaseDocument& doc, Case& c);         // [textures]
Result<void> read_tolerance(const CaseDocument& doc, Case& c);        // [tolerance]
// Once the variants are known: the reference render's variant and language exist, and a
// LUT variant has a model (CaseSectionReference).
Result<void> check_reference(const CaseDocument& doc, Case& c);

// An error in the case file at `node` (its line and column), or in the file as a whole.
Error at(const std::string& path, const toml::node& node, std::string message);
Error at(const std::string& path, std::string message);

// Case and variant names become folder names under --out: letters, digits, '_', '-' and
// '.', not starting with '.', so no name can leave the output folder.
Result<void> plain_name(const std::string& path, const toml::node& node, const std::string& name, const char* what);

// A number or an array of numbers, all finite; `key` names the value in errors.
Result<std::vector<double>> numbers(const std::string& path, const toml::node& node, const std::string& key);

// A table of preprocessor defines, NAME = "text" | number | boolean (1 or 0), in the
// order written; skip_languages passes over the per-language tables ([defines.glsl]).
Result<std::vector<std::pair<std::string, std::string>>> define_table(const std::string& path, const toml::table& table,
                                                                      bool skip_languages);

// Literal numbers: a number, a boolean (1 or 0) or an array of them, nested arrays
// flattened (a matrix written row by row stays in the order written). False when the
// node holds anything else.
bool literal_numbers(const toml::node& node, std::vector<double>& out);

}  // namespace shaderbed::case_sections
