#pragma once
// Which contacts carry a brick: the classification every freezing model
// shares (thesis 3.3.1).

#include <functional>
#include <vector>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "stability/stability_model.h"

namespace brick_stack_sim {

class SupportGraph;

/// A run of contact pointers: one body's contacts in a ContactIndex, or a
/// vector's. A view, valid while what it views lives.
class ContactSpan {
 public:
  ContactSpan() = default;
  ContactSpan(const PairContact* const* first, const PairContact* const* last)
      : first_(first), last_(last) {}
  explicit ContactSpan(const std::vector<const PairContact*>& contacts)
      : ContactSpan(contacts.data(), contacts.data() + contacts.size()) {}
  const PairContact* const* begin() const { return first_; }
  const PairContact* const* end() const { return last_; }
  bool empty() const { return first_ == last_; }
  std::size_t size() const { return static_cast<std::size_t>(last_ - first_); }
  const PairContact* operator[](std::size_t i) const { return first_[i]; }

 private:
  const PairContact* const* first_ = nullptr;
  const PairContact* const* last_ = nullptr;
};

/// A step's contacts by the bodies they touch; contacts without points are
/// left out.
class ContactIndex {
 public:
  explicit ContactIndex(const std::vector<PairContact>* contacts);
  /// The contacts of `handle`, in the step's order.
  ContactSpan of(BodyHandle handle) const;

 private:
  // Every body's contacts in one array, sorted by body: built every step
  // for every mover, a map of one vector per body cost an allocation each.
  std::vector<BodyHandle> bodies_;
  std::vector<const PairContact*> contacts_;
};

/// May a brick rest on (or lean on) this body and join the stack? Frozen
/// bricks and the ground, and for a group judged together its members.
using SupporterTest = std::function<bool(BodyHandle)>;

/// The support patches of `body` among its `contacts`: one per supporter,
/// from the contacts whose normal is within `support_normal_tolerance` of
/// vertical with `body` on top, whose supporter passes `can_support` (a
/// stack cannot start on a moving brick) and that do not close faster than
/// `impact_speed` (an impact is not support). In supporter order. When
/// `side_contacts` is given, the other contacts with such supporters go
/// there, one patch per supporter too.
std::vector<SupportPatch> supportPatches(const BodyMotion& body, ContactSpan contacts,
                                         const SupporterTest& can_support,
                                         const StabilityOptions& options,
                                         std::vector<SupportPatch>* side_contacts = nullptr);

/// Frozen bricks and the ground of `graph`.
SupporterTest frozenOrGround(const SupportGraph& graph);

/// Where two faces rest flush (parallel within `flush_angle`), the patch is
/// their exact overlap rather than the points Bullet kept: its box-box
/// clipper keeps only penetrating points, so a brick tilted by a
/// micro-radian reports half its patch. Applied to the contacts whose normal
/// is within `support_normal_tolerance` of vertical and, when `wanted` is
/// given, that it accepts (a patch no one will judge is not worth the
/// clipping); `solid_of` gives a body's solid.
void refineFlushPatches(const std::function<PlacedSolid(BodyHandle)>& solid_of,
                        const StabilityOptions& options, std::vector<PairContact>* contacts,
                        const std::function<bool(const PairContact&)>& wanted = {});

}  // namespace brick_stack_sim
