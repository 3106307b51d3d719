#pragma once
// One factory and one set of defaults per model, each defined in its own file in this
// folder. A new model is a new file here, two declarations below and a line in
// ModelRegistry.cpp. The defaults are docs/models.md's (the book's values); the
// parameters of the LUT variants (lut_size, lut_rows) are not model parameters: the
// reference evaluates the analytic model.
#include "reference/LightingModel.h"
#include "reference/Reference.h"

namespace reference {

ModelOrError make_ambient(const Params& params);           // ambient
ModelOrError make_lambert(const Params& params);           // diffuse
ModelOrError make_phong(const Params& params);             // diffuse, specular, power
ModelOrError make_blinn_phong(const Params& params);       // diffuse, specular, power
ModelOrError make_schlick(const Params& params);           // diffuse, specular, power
ModelOrError make_minnaert(const Params& params);          // diffuse, minnaert_power
ModelOrError make_oren_nayar(const Params& params);        // diffuse, roughness_sq
ModelOrError make_ward_iso(const Params& params);          // diffuse, specular, roughness
ModelOrError make_ward_aniso(const Params& params);        // diffuse, specular, roughness_xy
ModelOrError make_cook_torrance(const Params& params);     // diffuse, gaussian_c, slope_m, fresnel_r0
ModelOrError make_point_attenuated(const Params& params);  // diffuse, light_color, attenuation
ModelOrError make_spot(const Params& params);  // diffuse, light_color, attenuation, cos_umbra, cos_penumbra, falloff
ModelOrError make_warn(const Params& params);  // diffuse, light_color, warn_exponent

Params ambient_defaults();
Params lambert_defaults();
Params phong_defaults();
Params blinn_phong_defaults();
Params schlick_defaults();
Params minnaert_defaults();
Params oren_nayar_defaults();
Params ward_iso_defaults();
Params ward_aniso_defaults();
Params cook_torrance_defaults();
Params point_attenuated_defaults();
Params spot_defaults();
Params warn_defaults();

}  // namespace reference
