// geomcheck — helpers shared by the check functions (internal to properties/).
#pragma once

#include <string>

#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

/// snprintf into a string, up to three double arguments.
std::string fmt(const char* f, double a, double b = 0, double c = 0);
/// "(x, y, z)" with round-trip precision.
std::string vec(Vec3 v);

}  // namespace geomcheck
