#include "engine/impacts/local_impacts.hpp"

#include <algorithm>

#include "engine/collision/collision_detection.hpp"
#include "engine/collision/narrowphase.hpp"
#include "engine/collision/signed_distance.hpp"
#include "engine/geometry/shape_extent.hpp"
#include "engine/step/step_context.hpp"
#include "engine/threads.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace gp {

namespace {

// Pairs a thread takes at a time, and pairs whose times of impact are found side by side before
// they are gathered (a fixed room of slots rather than room per body).
constexpr std::size_t kSweptPairsPerTask = 128;
constexpr std::size_t kSweptPairsPerBlock = 8 * kSweptPairsPerTask;

}  // namespace

void LocalImpacts::classify(StepContext& ctx) {
  pending_.clear();
  if (!ctx.impacts_allowed()) return;
  const WorldShapes& start = ctx.world_start;
  const ImpactFilter f = impact_filter(ctx.settings);
  const auto touch_of = [&](const ShapePair& p) {
    return find_touch({ctx.shapes[p.first], start[p.first]},
                      {ctx.shapes[p.second], start[p.second]}, *ctx.motion, {0.0, ctx.h}, f);
  };
  // Pairs whose contact touches are the contact solver's: no distance to compute.
  const std::span<const ShapePair> pairs = ctx.pairs;
  const std::vector<std::uint8_t>& touching = ctx.touching_pairs;
  if (one_thread() || pairs.size() < CollisionDetection::kParallelPairs) {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      if (touching[i] != 0) continue;
      if (const auto touch = touch_of(pairs[i])) pending_.push_back({pairs[i], *touch});
    }
  } else {
    // On several threads, a block of the pairs apart at a time: each one's time into its own
    // slot, then gathered in the pairs' order, so that they do not depend on the number of
    // threads.
    apart_.reserve(kSweptPairsPerBlock);
    touches_.resize(kSweptPairsPerBlock);
    for (std::size_t next = 0; next < pairs.size();) {
      apart_.clear();
      for (; next < pairs.size() && apart_.size() < kSweptPairsPerBlock; ++next) {
        if (touching[next] == 0) apart_.push_back(static_cast<std::uint32_t>(next));
      }
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, apart_.size(), kSweptPairsPerTask),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t k = r.begin(); k < r.end(); ++k) {
                            touches_[k] = touch_of(pairs[apart_[k]]);
                          }
                        });
      for (std::size_t k = 0; k < apart_.size(); ++k) {
        if (touches_[k]) pending_.push_back({pairs[apart_[k]], *touches_[k]});
      }
    }
  }
  if (pending_.empty()) return;
  // An impact is resolved at its t_c; its speculative contact must not close the gap before.
  auto impact = pending_.begin();
  ctx.contacts.erase_if([&](const Contact& c) {
    while (impact != pending_.end() && contact_key(impact->pair) < c.key()) ++impact;
    return impact != pending_.end() && contact_key(impact->pair) == c.key();
  });
}

bool LocalImpacts::in_solver(const StepContext& ctx, std::uint32_t shape) const {
  return roles_[ctx.shapes[shape].body] == BodyRole::kInSolver;
}

bool LocalImpacts::engaged(const StepContext& ctx, const Contact& c) const {
  const MotionState& s = ctx.start;
  const double h = ctx.h;
  const double slop = ctx.settings.linear_slop;
  // Touching is told by the depth alone: a resting pile's points need no velocity.
  for (const ContactPointState& p : ctx.contacts.points(c)) {
    if (p.depth > -slop) return true;
  }
  for (const ContactPointState& p : ctx.contacts.points(c)) {
    const double closing = -contact_normal_velocity(s, c, p) * h;  // m
    if (p.depth + std::max(closing, 0.0) > -slop) return true;
  }
  return false;
}

void LocalImpacts::join(const StepContext& ctx, BodyId b) {
  if (ctx.dynamic[b]) roles_[b] = BodyRole::kInSolver;
}

template <typename Asked>
void LocalImpacts::join_engaged(const StepContext& ctx, const Asked& asked) {
  for (const Contact& c : ctx.contacts) {
    if (!asked(c) || !engaged(ctx, c)) continue;
    join(ctx, c.body_a);
    join(ctx, c.body_b);
  }
}

void LocalImpacts::hand_over(StepContext& ctx) {
  const WorldShapes& start = ctx.world_start;
  ContactSet& speculative = ctx.speculative_contacts;
  speculative.clear();
  // Without impacts there is nothing to hand over, and no role is read before the next step's.
  if (pending_.empty()) return;
  roles_.assign(ctx.dynamic.size(), BodyRole::kFree);
  // Here only the bodies of the impacts need to know whether they are the solver's: only their
  // contacts are asked whether they are engaged (most of a pile's are not theirs).
  for (const Pending& e : pending_) {
    for (const std::uint32_t shape : {e.pair.first, e.pair.second}) {
      const BodyId b = ctx.shapes[shape].body;
      if (ctx.dynamic[b] && roles_[b] == BodyRole::kFree) roles_[b] = BodyRole::kInImpact;
    }
  }
  join_engaged(ctx, [this](const Contact& c) {
    return roles_[c.body_a] == BodyRole::kInImpact || roles_[c.body_b] == BodyRole::kInImpact;
  });
  for (bool grew = true; grew;) {
    grew = false;
    std::erase_if(pending_, [&](const Pending& e) {
      if (!in_solver(ctx, e.pair.first) && !in_solver(ctx, e.pair.second)) return false;
      const WorldShapeView& a = start[e.pair.first];
      const WorldShapeView& b = start[e.pair.second];
      // A margin that reaches the other shape, so that the solver holds the gap closed.
      const ContactManifold m = collide(a, b, e.touch.distance_t0 + ctx.settings.contact_margin);
      if (m.count > 0) append_contact(e.pair, ctx.shapes, m, ctx.start, speculative);
      join(ctx, ctx.shapes[e.pair.first].body);
      join(ctx, ctx.shapes[e.pair.second].body);
      grew = true;
      return true;
    });
  }
  // The bodies left with impacts are the exact path's alone: a contact of theirs that is not
  // engaged (apart, not closing within the step) is searched for impacts after theirs instead.
  for (const Pending& e : pending_) {
    roles_[ctx.shapes[e.pair.first].body] = BodyRole::kWithImpact;
    roles_[ctx.shapes[e.pair.second].body] = BodyRole::kWithImpact;
  }
  if (!pending_.empty()) drop_contacts_with_impacts(ctx);
}

void LocalImpacts::drop_contacts_with_impacts(StepContext& ctx) const {
  ctx.contacts.erase_if([this, &ctx](const Contact& c) {
    return (ctx.dynamic[c.body_a] && roles_[c.body_a] == BodyRole::kWithImpact) ||
           (ctx.dynamic[c.body_b] && roles_[c.body_b] == BodyRole::kWithImpact);
  });
}

void LocalImpacts::follow_path(BodyId b, double tau, StepContext& ctx) const {
  const Ballistic& path = *ctx.motion;
  ctx.start.set(b, {path.position(b, tau), path.angle(b, tau), path.velocity(b, tau),
                    path.angular_velocity(b, tau)});
}

bool LocalImpacts::resolve(StepContext& ctx) {
  if (pending_.empty()) return true;
  // The search after an impact asks of any body near it whether it is the solver's: the contacts
  // hand_over() did not ask are asked now. Those of the bodies with impacts are gone.
  const auto joined = [this, &ctx](BodyId b) {
    return !ctx.dynamic[b] || roles_[b] == BodyRole::kInSolver;
  };
  join_engaged(ctx, [&](const Contact& c) { return !joined(c.body_a) || !joined(c.body_b); });
  const double h = ctx.h;
  // The times classify() only bracketed, from the motion it followed: nothing has moved since.
  for (Pending& e : pending_) {
    e.touch.time = touch_time(e.touch, ctx.shapes[e.pair.first], ctx.shapes[e.pair.second],
                              *ctx.motion, {0.0, h});
  }
  MotionState& start = ctx.start;
  const double same_time = simultaneity(h);
  while (!pending_.empty() && ctx.impacts_allowed()) {
    const double tau =
        std::min_element(pending_.begin(), pending_.end(), [](const Pending& x, const Pending& y) {
          return x.touch.time < y.touch.time;
        })->touch.time;
    group_.clear();
    changed_.clear();
    held_.clear();
    // The group's bodies are moved to the impact in `start` itself, which is the step's scratch:
    // only the static and kinematic ones, whose paths the impact does not change, are held aside
    // to be put back after it.
    for (const Pending& e : pending_) {
      if (e.touch.time > tau + same_time) continue;
      group_.push_back(e.pair);
      for (std::uint32_t shape : {e.pair.first, e.pair.second}) {
        const BodyId b = ctx.shapes[shape].body;
        if (ctx.dynamic[b]) {
          if (roles_[b] == BodyRole::kResolving) continue;
          roles_[b] = BodyRole::kResolving;
          changed_.push_back(b);
        } else {
          if (std::any_of(held_.begin(), held_.end(), [b](const Held& x) { return x.body == b; }))
            continue;
          held_.push_back({b, start.of(b)});
        }
        follow_path(b, tau, ctx);
      }
    }
    std::sort(group_.begin(), group_.end());
    resolve_impacts(group_, ctx, ctx.time + tau, start, impact_contacts_);
    ++ctx.impacts_this_step;
    // Under constant accelerations the path through the state just after the impact, followed
    // back by τ, starts where the body must start to pass through that state.
    for (BodyId b : changed_) follow_path(b, -tau, ctx);
    for (const Held& x : held_) start.set(x.body, x.state);
    std::erase_if(pending_, [this, &ctx](const Pending& e) {
      return changed(ctx.shapes[e.pair.first]) || changed(ctx.shapes[e.pair.second]);
    });
    if (!search_after(ctx, tau)) return false;
    for (BodyId b : changed_) roles_[b] = BodyRole::kWithImpact;
  }
  if (!pending_.empty()) return false;
  drop_contacts_with_impacts(ctx);
  return true;
}

bool LocalImpacts::search_after(StepContext& ctx, double tau) {
  const std::span<const BodyId> changed = changed_;
  const double h = ctx.h;
  const Ballistic& motion = *ctx.motion;
  WorldShapes& rest_start = ctx.world_start;
  WorldBounds& end = ctx.end_bounds;
  // First every changed shape placed where the rest of its path starts (and its box where it
  // ends), so that two changed shapes see each other's.
  for (BodyId b : changed) {
    for (auto [i, last] = ctx.shapes.of_body(b); i < last; ++i) {
      const ShapeRecord& shape = ctx.shapes[i];
      end.place(i, shape.local, motion.frame(shape, h));
      rest_start.place(i, shape.local, motion.frame(shape, tau));
    }
  }
  const double half_margin = 0.5 * ctx.settings.contact_margin;
  // The box of a shape over the rest of its path, + margin / 2.
  const auto swept = [&](std::uint32_t i) {
    return rest_start.bounds(i).united(end.bounds(i)).fattened(half_margin);
  };
  const ImpactFilter f = impact_filter(ctx.settings);
  for (BodyId b : changed) {
    for (auto [i, last] = ctx.shapes.of_body(b); i < last; ++i) {
      const Aabb box = swept(i);
      const WorldShapeView here = rest_start[i];
      for (std::uint32_t k = 0; k < ctx.shapes.size(); ++k) {
        const BodyId other = ctx.shapes[k].body;
        if (other == b || !box.overlaps(swept(k))) continue;
        // A pair of two changed bodies is searched once, from the one with the lower id.
        if (roles_[other] == BodyRole::kResolving && other < b) continue;
        if (in_solver(ctx, k)) {
          // Its path is the solver's, not known here: safe to leave to the next step only if
          // neither can have moved through the other by then, which takes closing the gap
          // between them at τ and then half the thinner one's thickness.
          const double reach_left =
              closing_speed_bound(ctx.shapes[i], ctx.shapes[k], motion, h) * (h - tau);
          const double thinner =
              std::min(half_thickness(ctx.shapes[i].local), half_thickness(ctx.shapes[k].local));
          if (reach_left < thinner) continue;
          const double gap = signed_distance(here, motion.placed(ctx.shapes[k], tau));
          if (reach_left >= std::max(gap, 0.0) + thinner) return false;
          continue;
        }
        const WorldShape there = motion.placed(ctx.shapes[k], tau);
        if (auto touch =
                find_touch({ctx.shapes[i], here}, {ctx.shapes[k], there}, motion, {tau, h}, f)) {
          touch->time = touch_time(*touch, ctx.shapes[i], ctx.shapes[k], motion, {tau, h});
          pending_.push_back({{std::min(i, k), std::max(i, k)}, *touch});
        }
      }
    }
  }
  return true;
}

}  // namespace gp
