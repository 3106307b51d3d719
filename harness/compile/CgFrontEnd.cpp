#include "compile/CgFrontEnd.h"

#include <optional>

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "compile/GlslangFrontEnd.h"
#include "compile/HlslIncluder.h"
#include "compile/SourceDefines.h"

namespace shaderbed {
namespace {

// Macros a Cg program may test; defined while preprocessing.
constexpr const char* kCgMacros =
    "#define SHADERBED 1\n"
    "#define SHADERBED_CG 1\n";

// `#include "file"` relative to the including file (HlslIncluder). Each included file goes
// through pass 1 (CgDialect.h) here; the first error is kept so it can be reported with
// the included file's name and line rather than as a failed #include.
class CgIncluder final : public HlslIncluder {
 public:
  CgIncluder(std::vector<CgNote>& notes, std::vector<SourceFile>& read, std::vector<std::string> include_dirs)
      : HlslIncluder(read, std::move(include_dirs)), notes_(notes) {}

  // `#include <file>` reads the case's include_dirs (a user's copies of an engine's headers).
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    if (has_include_dirs()) return includeLocal(header, includer, depth);
    return failure(std::string("Cg has no system headers; write #include \"") + header +
                   "\" (resolved relative to the including file), or name the headers' folder in the case's "
                   "include_dirs");
  }

  std::optional<Error> error;

 private:
  Result<Prepared> prepare(const std::string& text, const std::string& name, const char* includer) override {
    auto prepared = prepare_cg_file(text, name);
    if (!prepared) {
      if (!error) error = prepared.error();
      return std::unexpected(prepared.error());
    }
    notes_.insert(notes_.end(), prepared->notes.begin(), prepared->notes.end());
    notes_.push_back({includer ? includer : "", 0, "#include resolved to " + name});
    return Prepared{std::move(prepared->text), prepared->pragma_once};
  }

  std::vector<CgNote>& notes_;
};

// Finds lookups whose coordinate glslang truncated implicitly: in Cg the extra
// component is a depth to compare against (shadow lookup), which glslang drops.
class DepthCompareFinder : public glslang::TIntermTraverser {
 public:
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (found) return false;
    switch (node->getOp()) {
      case glslang::EOpTexture:
      case glslang::EOpTextureGrad:
      case glslang::EOpTextureLod:
      case glslang::EOpTextureBias:
        break;
      default:
        return true;
    }
    const glslang::TIntermSequence& args = node->getSequence();
    if (args.size() < 2) return true;
    const glslang::TIntermTyped* sampler = args[0]->getAsTyped();
    glslang::TIntermAggregate* coord = args[1]->getAsAggregate();
    if (!sampler || !coord || coord->getType().getQualifier().storage != glslang::EvqIn ||
        coord->getSequence().size() != 1)
      return true;
    const glslang::TIntermTyped* from = coord->getSequence()[0]->getAsTyped();
    if (!from || !coord->isConstructor()) return true;
    const int to_size = coord->getType().getVectorSize();
    const int from_size = from->getType().getVectorSize();
    if (from_size <= to_size) return true;
    const glslang::TSampler& s = sampler->getType().getSampler();
    const char* dim = s.dim == glslang::Esd1D     ? "1D"
                      : s.dim == glslang::Esd3D   ? "3D"
                      : s.dim == glslang::EsdCube ? "CUBE"
                                                  : "2D";
    found = node->getLoc();
    construct = std::string("tex") + dim + "(sampler" + dim + ", float" + std::to_string(from_size) + ")";
    return false;
  }

  std::optional<glslang::TSourceLoc> found;
  std::string construct;
};

}  // namespace

Result<CgPrepared> prepare_cg(const ShaderSource& source, Target target) {
  CgPrepared out;
  auto prepared = prepare_cg_file(source.text, source.path);
  if (!prepared) return std::unexpected(prepared.error());
  out.notes = std::move(prepared->notes);

  const EShLanguage stage = source.stage == Stage::vertex ? EShLangVertex : EShLangFragment;
  glslang::TShader shader(stage);
  const char* text = prepared->text.c_str();
  const int length = static_cast<int>(prepared->text.size());
  const char* name = source.path.c_str();
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  shader.setEntryPoint(source.entry_point.c_str());
  shader.setSourceEntryPoint(source.entry_point.c_str());
  const glslang::EShClient client = target == Target::vulkan ? glslang::EShClientVulkan : glslang::EShClientOpenGL;
  shader.setEnvInput(glslang::EShSourceHlsl, stage, client, 100);
  const std::string preamble = std::string(kCgMacros) + define_lines(source.defines);
  shader.setPreamble(preamble.c_str());
  const auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgHlslDX9Compatible);

  CgIncluder includer(out.notes, out.includes, source.include_dirs);
  std::string preprocessed;
  const bool ok =
      shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, messages, &preprocessed, includer);
  if (includer.error) return std::unexpected(*includer.error);
  if (!ok) return std::unexpected(glslang_log_error(shader.getInfoLog(), source.path, "preprocess"));

  auto translation = translate_cg(preprocessed, source.path, source.stage, source.entry_point);
  if (!translation) return std::unexpected(translation.error());
  out.notes.insert(out.notes.end(), translation->notes.begin(), translation->notes.end());
  out.text = translation->text;
  out.preamble = preamble + translation->helpers;
  out.translation = std::move(*translation);
  return out;
}

Result<void> check_cg_ast(glslang::TShader& shader, const std::string& path) {
  glslang::TIntermediate* intermediate = shader.getIntermediate();
  if (!intermediate || !intermediate->getTreeRoot()) return {};
  DepthCompareFinder finder;
  intermediate->getTreeRoot()->traverse(&finder);
  if (!finder.found) return {};
  const glslang::TSourceLoc& loc = *finder.found;
  return std::unexpected(Error{
      .message =
          "Cg feature '" + finder.construct +
          "' is not supported by shaderbed's Cg layer (no Cg compiler; Cg reads the extra coordinate as a depth to "
          "compare against, a shadow lookup that needs a depth texture and comparison sampler shaderbed does not "
          "bind, and glslang would silently drop it; pass exactly the lookup's coordinates)",
      .file = loc.name && !loc.name->empty() ? std::string(loc.name->c_str()) : path,
      .line = loc.line,
      .stage = ErrorStage::compile});
}

}  // namespace shaderbed
