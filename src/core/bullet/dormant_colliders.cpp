#include "bullet/dormant_colliders.h"

#include <algorithm>
#include <unordered_map>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>

#include "bullet/bullet_conversions.h"
#include "bullet/bullet_scene.h"

namespace brick_stack_sim {

namespace {

/// Steps a frozen brick stays in Bullet's world after a mover last came near.
constexpr std::uint64_t kKeepSteps = 50;

}  // namespace

struct DormantColliders::Impl {
  struct Leaf {
    btDbvtNode* node = nullptr;
    std::uint64_t needed_at_step = 0;
  };
  BulletScene* scene = nullptr;
  btDbvt tree;
  std::unordered_map<BodyHandle, Leaf> leaves;
};

DormantColliders::DormantColliders(BulletScene* scene) : impl_(std::make_unique<Impl>()) {
  impl_->scene = scene;
}

DormantColliders::~DormantColliders() = default;

void DormantColliders::add(BodyHandle frozen) {
  Eigen::Vector3d low, high;
  impl_->scene->bounds(frozen, &low, &high);
  Impl::Leaf& leaf = impl_->leaves[frozen];
  // The tree's data pointer carries the handle itself, not an address.
  leaf.node =
      impl_->tree.insert(btDbvtVolume::FromMM(convertEigenToBt(low), convertEigenToBt(high)),
                         reinterpret_cast<void*>(static_cast<std::uintptr_t>(frozen)));
}

void DormantColliders::copyFrom(const DormantColliders& source) {
  std::vector<BodyHandle> frozen;
  for (const auto& entry : source.impl_->leaves) frozen.push_back(entry.first);
  // The tree's shape follows insertion order; near() sorts what it finds.
  std::sort(frozen.begin(), frozen.end());
  for (BodyHandle handle : frozen) {
    add(handle);
    impl_->leaves.at(handle).needed_at_step = source.impl_->leaves.at(handle).needed_at_step;
  }
  in_world_ = source.in_world_;
}

void DormantColliders::remove(BodyHandle frozen) {
  auto found = impl_->leaves.find(frozen);
  if (found == impl_->leaves.end()) return;
  auto position = std::find(in_world_.begin(), in_world_.end(), frozen);
  if (position != in_world_.end()) {
    impl_->scene->removeFromWorld(frozen);
    in_world_.erase(position);
  }
  impl_->tree.remove(found->second.node);
  impl_->leaves.erase(found);
}

void DormantColliders::refresh(BodyHandle frozen) {
  auto found = impl_->leaves.find(frozen);
  if (found == impl_->leaves.end()) return;
  Eigen::Vector3d low, high;
  impl_->scene->bounds(frozen, &low, &high);
  btDbvtVolume volume = btDbvtVolume::FromMM(convertEigenToBt(low), convertEigenToBt(high));
  impl_->tree.update(found->second.node, volume);
}

bool DormantColliders::contains(BodyHandle handle) const { return impl_->leaves.count(handle) > 0; }

std::size_t DormantColliders::size() const { return impl_->leaves.size(); }

std::vector<BodyHandle> DormantColliders::near(const Eigen::Vector3d& low,
                                               const Eigen::Vector3d& high) const {
  struct Collector : btDbvt::ICollide {
    std::vector<BodyHandle> found;
    void Process(const btDbvtNode* leaf) override {
      found.push_back(static_cast<BodyHandle>(reinterpret_cast<std::uintptr_t>(leaf->data)));
    }
  } collector;
  impl_->tree.collideTV(impl_->tree.m_root,
                        btDbvtVolume::FromMM(convertEigenToBt(low), convertEigenToBt(high)),
                        collector);
  std::sort(collector.found.begin(), collector.found.end());
  return collector.found;
}

std::vector<ColliderApproach> DormantColliders::bringWithinReach(
    const std::vector<MoverReach>& movers, std::uint64_t step) {
  std::vector<ColliderApproach> approaches;
  for (const MoverReach& mover : movers) {
    Eigen::Vector3d low, high;
    impl_->scene->bounds(mover.mover, &low, &high);
    const Eigen::Vector3d reach = Eigen::Vector3d::Constant(mover.travel);
    for (BodyHandle frozen : near(low - reach, high + reach)) {
      impl_->leaves.at(frozen).needed_at_step = step;
      if (!impl_->scene->inWorld(frozen)) {
        impl_->scene->addToWorld(frozen);
        in_world_.push_back(frozen);
      }
      approaches.push_back({mover.mover, frozen});
    }
  }
  return approaches;
}

void DormantColliders::sendBackIdle(std::uint64_t step) {
  for (std::size_t i = in_world_.size(); i-- > 0;) {
    const BodyHandle frozen = in_world_[i];
    if (impl_->leaves.at(frozen).needed_at_step + kKeepSteps < step) {
      impl_->scene->removeFromWorld(frozen);
      in_world_.erase(in_world_.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
}

}  // namespace brick_stack_sim
