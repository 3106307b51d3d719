#pragma once
// RGB values as the `shaderbed sh` reports compare and print them.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace shaderbed {

// The largest |channel|: a difference of colours as one number.
inline double max_component(const glm::dvec3& v) { return std::max({std::abs(v.r), std::abs(v.g), std::abs(v.b)}); }

inline nlohmann::json rgb_json(const glm::dvec3& v) { return {v.r, v.g, v.b}; }

}  // namespace shaderbed
