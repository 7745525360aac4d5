#include "stability/statics_memo.h"

#include <cstring>
#include <utility>

namespace brick_stack_sim {

namespace {

template <typename T>
void appendBits(const T& value, std::string* bits) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  bits->append(bytes, sizeof(T));
}

void appendBits(const Eigen::Vector3d& vector, std::string* bits) {
  for (int i = 0; i < 3; ++i) appendBits(vector[i], bits);
}

/// Every field the LP reads, field by field (a struct's padding is not part
/// of the problem).
std::string problemBits(const StaticsAssembly& assembly) {
  std::string bits;
  appendBits(assembly.bodies().size(), &bits);
  for (const StaticsBody& body : assembly.bodies()) {
    appendBits(body.mass, &bits);
    appendBits(body.com, &bits);
    appendBits(body.fixed, &bits);
    appendBits(body.applied_force, &bits);
    appendBits(body.applied_torque, &bits);
  }
  for (const StaticsContact& contact : assembly.contacts()) {
    appendBits(contact.a, &bits);
    appendBits(contact.b, &bits);
    appendBits(contact.point, &bits);
    appendBits(contact.normal, &bits);
    appendBits(contact.friction, &bits);
  }
  return bits;
}

}  // namespace

StaticsSolution StaticsMemo::solve(const StaticsAssembly& assembly) {
  std::string bits = problemBits(assembly);
  if (auto known = answers_.find(bits); known != answers_.end()) {
    ++hits_;
    return known->second;
  }
  ++solves_;
  StaticsSolution solution = assembly.solve();
  // A failed solve is not kept: asked again, Clp gets another chance.
  if (!solution.solved || capacity_ == 0) return solution;
  if (answers_.size() >= capacity_) {
    answers_.erase(oldest_first_.front());
    oldest_first_.pop_front();
  }
  oldest_first_.push_back(bits);
  answers_.emplace(std::move(bits), solution);
  return solution;
}

}  // namespace brick_stack_sim
