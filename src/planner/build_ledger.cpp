#include "brick_stack_sim/planner/build_ledger.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace brick_stack_sim {
namespace planner {
namespace {

double turnedAngle(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to) {
  return Eigen::AngleAxisd(from.linear().transpose() * to.linear()).angle();
}

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f mm", metres * 1e3);
  return text;
}

std::string degrees(double radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f deg", radians * 180.0 / M_PI);
  return text;
}

}  // namespace

void BuildLedger::recordPlaced(const std::string& id, const Eigen::Isometry3d& pose, double t,
                               bool thrown) {
  LedgerEntry entry;
  entry.id = id;
  entry.placement = ++placed_;
  entry.placed_at = t;
  entry.placed_pose = pose;
  entry.thrown = thrown;
  if (thrown) {
    entry.fate = BrickFate::kThrown;
    thrown_yet_ = true;
  }
  entries_.push_back(std::move(entry));
}

void BuildLedger::recordRefused(const std::string& id, const std::string& reason) {
  refusals_.push_back(id + ": " + reason);
}

std::string BuildLedger::judgeResting(LedgerEntry* entry, const ObservedBrick& brick) const {
  const Eigen::Isometry3d& pose = brick.pose;
  const bool slow = brick.linear_velocity.norm() < options_.settle_linear_speed &&
                    brick.angular_velocity.norm() < options_.settle_angular_speed;
  const bool still =
      entry->last_pose &&
      (pose.translation() - entry->last_pose->translation()).norm() < options_.settle_step;
  if (!brick.frozen && !brick.asleep && !(slow && still)) return "";
  // At rest, but where? Seen from above it must be where it was put.
  const Eigen::Vector3d drift = pose.translation() - entry->placed_pose.translation();
  const double aside = drift.head<2>().norm();
  const double turned = turnedAngle(entry->placed_pose, pose);
  if (aside > options_.fall_distance)
    return "came to rest " + millimetres(aside) + " aside of where it was placed";
  if (turned > options_.fall_angle)
    return "came to rest turned " + degrees(turned) + " from how it was placed";
  if (drift.z() > options_.fall_distance)
    return "came to rest " + millimetres(drift.z()) + " above where it was placed";
  entry->settled_pose = pose;
  entry->fate = BrickFate::kStanding;
  return "";
}

std::string BuildLedger::judgeSettled(LedgerEntry* entry, const Eigen::Isometry3d& pose,
                                      bool* shifted_now) const {
  const Eigen::Isometry3d& settled = *entry->settled_pose;
  const double moved = (pose.translation() - settled.translation()).norm();
  const double turned = turnedAngle(settled, pose);
  std::string how;
  if (moved > options_.fall_distance)
    how = "moved " + millimetres(moved) + " from where it had come to rest";
  else if (turned > options_.fall_angle)
    how = "turned " + degrees(turned) + " from how it had come to rest";
  if (how.empty() || !thrown_yet_) return how;
  // After a throw: knocked only when it left the structure (BrickFate).
  const double dropped = settled.translation().z() - pose.translation().z();
  if (dropped > options_.fall_distance) return how + " and dropped " + millimetres(dropped);
  if (!entry->shifted) {
    entry->shifted = true;
    entry->how = how + ", in place";
    *shifted_now = true;
  }
  return "";
}

std::vector<const LedgerEntry*> BuildLedger::observe(double t,
                                                     const std::vector<ObservedBrick>& bricks) {
  std::map<std::string, const ObservedBrick*> by_id;
  for (const ObservedBrick& brick : bricks) by_id.emplace(brick.id, &brick);

  std::vector<const LedgerEntry*> changed;
  for (LedgerEntry& entry : entries_) {
    if (entry.fate == BrickFate::kThrown || entry.fate == BrickFate::kFallen) continue;
    const auto found = by_id.find(entry.id);
    std::string how;
    bool shifted_now = false;
    if (found == by_id.end()) {
      how = "was removed from the simulation";
    } else {
      const ObservedBrick& brick = *found->second;
      entry.frozen = brick.frozen;
      entry.leaning = brick.frozen && brick.leaning;
      if (brick.fell_off)
        how = "fell off the table";
      else if (entry.settled_pose)
        how = judgeSettled(&entry, brick.pose, &shifted_now);
      else
        how = judgeResting(&entry, brick);
      entry.last_pose = brick.pose;
    }
    if (!how.empty()) {
      entry.fate = BrickFate::kFallen;
      entry.fell_at = t;
      entry.placed_when_fell = placed_;
      entry.fell_after_throw = thrown_yet_;
      entry.how = how;
    }
    if (!how.empty() || shifted_now) changed.push_back(&entry);
  }
  return changed;
}

const LedgerEntry* BuildLedger::find(const std::string& id) const {
  for (const LedgerEntry& entry : entries_)
    if (entry.id == id) return &entry;
  return nullptr;
}

const LedgerEntry* BuildLedger::firstFallen() const {
  const LedgerEntry* first = nullptr;
  for (const LedgerEntry& entry : entries_) {
    if (entry.fate != BrickFate::kFallen) continue;
    if (!first || entry.fell_at < first->fell_at) first = &entry;
  }
  return first;
}

BuildSummary BuildLedger::summary() const {
  BuildSummary summary;
  summary.refused = static_cast<int>(refusals_.size());
  for (const LedgerEntry& entry : entries_) {
    ++summary.placed;
    switch (entry.fate) {
      case BrickFate::kThrown:
        ++summary.thrown;
        break;
      case BrickFate::kUnsettled:
        ++summary.unsettled;
        break;
      case BrickFate::kStanding:
        ++summary.standing;
        if (entry.shifted) ++summary.shifted;
        if (entry.frozen) ++summary.frozen;
        if (entry.frozen && entry.leaning) ++summary.leaning;
        break;
      case BrickFate::kFallen:
        ++(entry.fell_after_throw ? summary.knocked : summary.fallen);
        break;
    }
  }
  return summary;
}

bool BuildLedger::met(ExpectedOutcome expect, std::string* verdict) const {
  const LedgerEntry* fallen = nullptr;  // the first to fall during the build
  for (const LedgerEntry& entry : entries_)
    if (entry.fate == BrickFate::kFallen && !entry.fell_after_throw &&
        (!fallen || entry.fell_at < fallen->fell_at))
      fallen = &entry;
  auto describe = [](const LedgerEntry& entry) {
    char when[96];
    std::snprintf(when, sizeof when, " (seen at t=%.1f s, after %d placements)", entry.fell_at,
                  entry.placed_when_fell);
    return "brick " + entry.id + " (placement " + std::to_string(entry.placement) + ") " +
           entry.how + when;
  };
  if (expect == ExpectedOutcome::kCollapses) {
    if (fallen) {
      *verdict = "collapsed as the scene expects: the first to fall was " + describe(*fallen);
      return true;
    }
    *verdict = "the scene expects a collapse, but every brick of it stands";
    return false;
  }
  if (fallen) {
    *verdict = "the build failed: " + describe(*fallen);
    return false;
  }
  if (!refusals_.empty()) {
    *verdict = "the build failed: the simulator refused brick " + refusals_.front();
    return false;
  }
  for (const LedgerEntry& entry : entries_) {
    if (entry.fate == BrickFate::kUnsettled) {
      *verdict = "the build failed: brick " + entry.id + " never came to rest";
      return false;
    }
  }
  *verdict = "it stands as the scene expects";
  return true;
}

std::string formatSummary(const std::string& scene, const BuildSummary& summary, double t) {
  char shifted[48] = "";
  if (summary.shifted > 0) std::snprintf(shifted, sizeof shifted, " (%d shifted)", summary.shifted);
  char text[512];
  std::snprintf(text, sizeof text,
                "demo summary: scene %s, placed %d, standing %d%s, fallen %d, knocked %d, "
                "unsettled %d, refused %d, thrown %d, frozen %d (stable %d, leaning %d), t=%.1f s",
                scene.c_str(), summary.placed, summary.standing, shifted, summary.fallen,
                summary.knocked, summary.unsettled, summary.refused, summary.thrown, summary.frozen,
                summary.frozen - summary.leaning, summary.leaning, t);
  return text;
}

}  // namespace planner
}  // namespace brick_stack_sim
