#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <unordered_map>

#include "stability/statics_assembly.h"

namespace brick_stack_sim {

/// Answers of cold statics solves (no warm start), kept by the exact bits of
/// their problem. A pile's component is judged anew whenever a brick joins
/// it, and most of its leaning groups then pose the LP they posed before,
/// bit for bit: a cold solve is a pure function of its bodies and contacts,
/// so handing back the kept answer changes nothing but the cost. A problem
/// that differs in any bit is solved.
class StaticsMemo {
 public:
  /// Keeps the answers of the last `capacity` distinct problems.
  explicit StaticsMemo(std::size_t capacity = 256) : capacity_(capacity) {}

  /// assembly.solve(), or the answer it gave to the same bits before.
  StaticsSolution solve(const StaticsAssembly& assembly);

  std::size_t hits() const { return hits_; }      ///< Answers handed back.
  std::size_t solves() const { return solves_; }  ///< Problems solved.

 private:
  std::size_t capacity_;
  std::unordered_map<std::string, StaticsSolution> answers_;
  std::deque<std::string> oldest_first_;
  std::size_t hits_ = 0;
  std::size_t solves_ = 0;
};

}  // namespace brick_stack_sim
