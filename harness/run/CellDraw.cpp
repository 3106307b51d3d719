#include "run/CellDraw.h"

#include "run/CaseTextures.h"
#include "run/CaseUniforms.h"

namespace shaderbed {

Result<DrawnCell> draw_cell(Backend& backend, const CellDraw& d) {
  static const BindingTable no_bindings;
  const auto own = d.c.bindings.find(d.language);
  const BindingTable& table = d.bindings ? *d.bindings : own == d.c.bindings.end() ? no_bindings : own->second;
  NamedValues values = d.values ? *d.values : bindable_values(d.scene, d.c);
  if (d.additions) values.insert(d.additions->values.begin(), d.additions->values.end());
  CaseUniforms uniforms(table, std::move(values), d.c.path, &d.program.uniform_defaults);
  if (auto bound = uniforms.check_all_bound(d.program); !bound) return std::unexpected(bound.error());
  DrawnCell drawn;
  if (d.other_sources) drawn.warnings = uniforms.unused_bindings(d.program, *d.other_sources);
  for (std::string& w : uniforms.unread_unbound(d.program)) drawn.warnings.push_back(std::move(w));

  CaseTextures textures(table, d.c.textures.for_language(d.language), d.lut, d.c.path, &d.program.sampler_settings,
                        d.additions ? &d.additions->textures : nullptr);
  if (auto ok = textures.check(d.program); !ok) return std::unexpected(ok.error());
  for (const std::string& w : textures.unread_unbound()) drawn.warnings.push_back(w);
  if (d.flip_images && !textures.flip_images_vertically()) return fail(ErrorStage::counterfactual, "no image to flip");
  if (d.texel_step && !textures.step_texels(d.texel_step->texture, d.texel_step->channel))
    return fail(ErrorStage::counterfactual, "'" + d.texel_step->texture + "' is no 8-bit image file");
  drawn.texture_note = textures.reference_note();

  const Mesh& mesh = d.additions && d.additions->mesh ? *d.additions->mesh : d.mesh;
  DrawJob job{d.program, d.path, mesh, uniforms, d.scene.width, d.scene.height, &textures, d.timing};
  job.render_state = d.program.render_state;   // a DX9 effect pass's states
  if (d.fill) job.render_state.fill = *d.fill;
  const auto attributes = d.c.attributes.find(d.language);
  if (attributes != d.c.attributes.end()) job.attributes = &attributes->second;
  auto rendered = backend.render(job);
  if (!rendered)
    return std::unexpected(Error(rendered.error()).in_backend(std::string(backend.name()) + "/" + to_string(d.path)));
  drawn.image = std::move(rendered->image);
  drawn.timings = std::move(rendered->timings);
  return drawn;
}

}  // namespace shaderbed
