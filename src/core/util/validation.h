#pragma once
// The shape of every validation message of the core: the field's key, its
// value and what it must be ("time_step = -0.001: must be in [1e-5, 0.1] s").

#include <cmath>
#include <sstream>
#include <string>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

template <typename Value>
Status bad(const std::string& name, const Value& value, const std::string& requirement) {
  std::ostringstream text;
  text << name << " = " << value << ": " << requirement;
  return Status::error(text.str());
}

inline bool positive(double value) { return std::isfinite(value) && value > 0.0; }
inline bool nonNegative(double value) { return std::isfinite(value) && value >= 0.0; }

}  // namespace brick_stack_sim
