#pragma once
// Where a shader loses significance at one pixel: the fragment stage traced twice, once
// with every float result rounded to binary32 (what an ideal fp32 device computes) and once
// in double, and the first instruction whose fp32 result departs from the double one by
// far more than its operands do. A cancellation (1 - cos(x) for tiny x, (a + b) - a with
// huge a) or an amplification (pow(x, 1e4)) shows there; the rounding of each operation
// (6e-8 relative) does not.
#include <optional>
#include <string>
#include <vector>

#include "twin/TwinDraw.h"
#include "twin/ValueOrigin.h"

namespace twin {

struct SignificanceLoss {
  // The instruction, with its fp32 trace's values (result and operands) and source line.
  ValueOrigin origin;
  std::vector<double> exact_values;                  // the result in double
  std::vector<std::vector<double>> exact_operands;   // the operands in double, as origin.operands
  double relative_error = 0;           // of the result, fp32 against double (infinite: NaN/Inf on one side)
  double operand_relative_error = 0;   // the largest of its operands'
  // "lit.frag:12 `float s = 1.0 - c;`: OpFSub(%float_1 = 1, c = 0.99999994 [double 0.999999955]) =
  //  5.96046448e-08 [double 4.5e-08]: relative error 0.32, operands 5.2e-08"
  std::string describe() const;
};

struct SignificanceOptions {
  double factor = 64;       // the result's relative error must exceed factor x its operands' ...
  double floor = 1e-5;      // ... and this (some 170 fp32 ulps)
  double tiny = 1e-30;      // relative error = |f - d| / max(|d|, tiny)
};

// |f - d| / max(|d|, tiny); infinite when one side is NaN or infinite and the other is not
// the same (both NaN, or the same infinity, are no error).
double relative_error(double f, double d, double tiny);

// At pixel (x, y): the fragment stage traced in float (Precision::single; uniform blocks read
// as the buffer's floats, as a device reads them) and in double (Precision::exact, whatever
// input.precision says; the blocks' unrounded values when the binder gave them), float results aligned by
// (instruction index, occurrence); the first instruction with at least one value operand
// whose result's relative error exceeds options.factor x the largest relative error of its
// operands, and options.floor. Nothing when no instruction loses significance. An error
// when the pixel is not covered or the shader cannot run.
TwinResult<std::optional<SignificanceLoss>> significance_loss(const DrawInput& input, int x, int y,
                                                              const SignificanceOptions& options = {});

}  // namespace twin
