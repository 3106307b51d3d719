#pragma once
// The shader's twin as a backend: a draw job's program, bindings, textures and vertex
// inputs handed to twin/ (the SPIR-V interpreter on the reference rasteriser), so a twin
// draws exactly what draw_cell binds for the GPUs. Its image keeps the twin's own
// precision (Image::exact_rgba); its float values are those rounded for storage. The last
// draw's inputs are kept, so its pixels can be traced back to the shader's lines.
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "backends/Backend.h"
#include "twin/Precision.h"
#include "twin/SignificanceLoss.h"
#include "twin/TwinDraw.h"
#include "twin/ValueOrigin.h"

namespace shaderbed {

class TwinRenderer final : public Backend {
 public:
  // threads 0: every core.
  explicit TwinRenderer(twin::Precision precision, unsigned threads = 0);
  ~TwinRenderer() override;
  std::string_view name() const override { return name_; }
  std::string driver_version() const override;
  std::string device_name() const override;
  std::vector<ShaderPath> paths(Language) const override { return {ShaderPath::spirv}; }
  Result<RenderOutput> render(const DrawJob& job) override;
  twin::Precision precision() const { return precision_; }

  // Of the last image render() drew: the instruction that first computed a NaN or Inf at
  // pixel (x, y); nothing when every value there is finite.
  Result<std::optional<twin::ValueOrigin>> nonfinite_origin(int x, int y) const;
  // Of the last image: the first instruction at pixel (x, y) whose fp32 result departs from
  // the double one by far more than its operands do (twin::significance_loss); nothing when
  // none does.
  Result<std::optional<twin::SignificanceLoss>> significance_loss(int x, int y) const;
  // Of the last image: pixel (x, y) with both stages in quad precision (twin::wide_pixel).
  Result<std::array<double, 4>> wide_pixel(int x, int y) const;
  // The last draw's program (null before a draw).
  const twin::Program* last_program() const;
  // The last draw's inputs in double, valid until the next draw (nothing before a draw):
  // what twin/ traces a pixel of it with.
  std::optional<twin::DrawInput> last_input() const;

 private:
  struct Programs;
  struct LastDraw;
  twin::Precision precision_;
  unsigned threads_;
  std::string name_;
  std::unique_ptr<Programs> programs_;
  std::unique_ptr<LastDraw> last_;
};

}  // namespace shaderbed
