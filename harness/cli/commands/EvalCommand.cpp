// `shaderbed eval MODEL --L x,y,z --V x,y,z [--N x,y,z] [--T x,y,z] [--param k=v]`:
// what the reference model says one pixel should be, in double precision.
#include <memory>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "run/ParameterOverrides.h"
#include "reference/Reference.h"

namespace shaderbed {
namespace {

struct EvalArguments {
  std::string model;
  std::vector<double> light, view, normal{0, 1, 0}, tangent{1, 0, 0};
  std::vector<std::string> params;
  double distance = 50;
};

std::string join(const std::vector<double>& v) {
  std::string out;
  for (double x : v) out += (out.empty() ? "" : ", ") + fmt::format("{:g}", x);
  return out;
}

}  // namespace

Command add_eval_command(CLI::App& app) {
  auto args = std::make_shared<EvalArguments>();
  CLI::App* cmd = app.add_subcommand(
      "eval",
      "Print the reference model's RGB (double precision) for one configuration. Directions are normalised; "
      "L points to the light, V to the eye; without --N the normal is +Y. Point-light models put the light at "
      "--distance along L, and spot/Warn lights shine along -N.");
  cmd->add_option("model", args->model, "Model name (see shaders/cases, docs/models.md)")->required();
  cmd->add_option("--L", args->light, "Direction to the light, x,y,z")->delimiter(',')->expected(3)->required();
  cmd->add_option("--V", args->view, "Direction to the eye, x,y,z")->delimiter(',')->expected(3)->required();
  cmd->add_option("--N", args->normal, "Surface normal, x,y,z (default 0,1,0)")->delimiter(',')->expected(3);
  cmd->add_option("--T", args->tangent, "Tangent for anisotropic models, x,y,z (default 1,0,0)")
      ->delimiter(',')
      ->expected(3);
  cmd->add_option("--param", args->params, "Parameter override name=value[,value...] (repeatable)");
  cmd->add_option("--distance", args->distance, "Distance to a point light")->capture_default_str();

  return {cmd, [args] {
            reference::Params params;
            for (const std::string& text : args->params) {
              auto p = parse_parameter(text);
              if (!p) {
                fmt::print(stderr, "shaderbed: {}\n", p.error().to_string());
                return kExitBadInput;
              }
              params[p->first] = p->second;
            }
            auto v3 = [](const std::vector<double>& v) { return glm::dvec3(v[0], v[1], v[2]); };
            auto rgb = reference::evaluate(args->model, params, v3(args->light), v3(args->view), v3(args->normal),
                                           v3(args->tangent), args->distance);
            if (!rgb) {
              fmt::print(stderr, "shaderbed: eval: {}\n", rgb.error());
              return kExitBadInput;
            }
            auto defaults = reference::default_params(args->model);
            fmt::print("{} L=({}) V=({}) N=({})\n", args->model, join(args->light), join(args->view),
                       join(args->normal));
            if (defaults)
              for (const auto& [name, value] : *defaults) {
                auto given = params.find(name);
                fmt::print("  {} = {}{}\n", name, join(given == params.end() ? value : given->second),
                           given == params.end() ? "" : "  (given)");
              }
            fmt::print("rgb = {:.17g} {:.17g} {:.17g}\n", rgb->r, rgb->g, rgb->b);
            return 0;
          }};
}

}  // namespace shaderbed
