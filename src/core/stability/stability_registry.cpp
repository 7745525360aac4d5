#include "stability/stability_registry.h"

#include "stability/com_criterion.h"
#include "stability/equilibrium_criterion.h"
#include "stability/stack_stability_model.h"
#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

using ModelFactory = std::unique_ptr<StabilityModel> (*)(const StabilityOptions&, BodyNamer);

struct ModeEntry {
  const char* name;
  const char* summary;
  ModelFactory create;  ///< Null: no model (plain Bullet).
};

std::unique_ptr<StabilityModel> createComModel(const StabilityOptions& options, BodyNamer name_of) {
  auto criterion = std::make_unique<ComCriterion>(options, name_of);
  return std::make_unique<StackStabilityModel>(options, std::move(name_of), std::move(criterion));
}

std::unique_ptr<StabilityModel> createEquilibriumModel(const StabilityOptions& options,
                                                       BodyNamer name_of) {
  auto criterion = std::make_unique<EquilibriumCriterion>(options, name_of);
  return std::make_unique<StackStabilityModel>(options, std::move(name_of), std::move(criterion));
}

/// Every mode of this build: a new model is a new criterion and a line here.
const ModeEntry kModes[] = {
    {"none", "plain Bullet, the baseline every benchmark compares against", nullptr},
    {"com",
     "the thesis's stack stability layer: bricks resting stably are frozen, woken when their "
     "COM-above leaves their support",
     &createComModel},
    {"equilibrium",
     "exact rigid-block statics: a linear program over contact forces with Coulomb friction "
     "(COIN-OR Clp) judges every freeze and wake, leaning bricks and card houses included",
     &createEquilibriumModel},
};

const ModeEntry* findMode(const std::string& mode) {
  for (const ModeEntry& entry : kModes)
    if (mode == entry.name) return &entry;
  return nullptr;
}

}  // namespace

const std::vector<std::string>& availableStabilityModes() {
  static const std::vector<std::string> modes = [] {
    std::vector<std::string> names;
    for (const ModeEntry& entry : kModes) names.emplace_back(entry.name);
    return names;
  }();
  return modes;
}

std::string describeStabilityMode(const std::string& mode) {
  const ModeEntry* entry = findMode(mode);
  return entry ? entry->summary : "";
}

Status checkStabilityMode(const std::string& mode) {
  if (findMode(mode)) return Status::success();
  // A mode name from a typo can be long; the message stays readable.
  const std::string shown = mode.size() > 40 ? mode.substr(0, 40) + "..." : mode;
  return Status::error(
      "stability mode '" + shown +
      "' is not available in this build (available: " + joinNames(availableStabilityModes()) + ")");
}

std::unique_ptr<StabilityModel> createStabilityModel(const StabilityOptions& options,
                                                     BodyNamer name_of) {
  const ModeEntry* entry = findMode(options.mode);
  if (!entry || !entry->create) return nullptr;
  return entry->create(options, std::move(name_of));
}

}  // namespace brick_stack_sim
