#include "engine/contacts/local_impacts.hpp"

#include <algorithm>

#include "engine/collision/narrowphase.hpp"
#include "engine/collision/signed_distance.hpp"
#include "engine/contacts/collision_detection.hpp"
#include "engine/geometry/shape_extent.hpp"

namespace gp {

void LocalImpacts::classify(const std::vector<ProxyPair>& pairs, const WorldShapes& start,
                            const WorldShapes& end, const Ballistic& motion, double h, bool search,
                            ContactSet& contacts) {
  pending_.clear();
  if (!search) return;
  const ImpactFilter f = impact_filter(settings_);
  // Both lists are sorted by pair: one forward scan finds each pair's contact.
  auto contact = contacts.begin();
  for (const ProxyPair& p : pairs) {
    while (contact != contacts.end() && contact->key() < key_of(p)) ++contact;
    const bool has_contact = contact != contacts.end() && contact->key() == key_of(p);
    // Touching already: the contact solver's, and no distance to compute.
    if (has_contact && touching(contacts, *contact)) continue;
    const auto tau = impact_time(shapes_[p.first], shapes_[p.second], start[p.first],
                                 start[p.second], end[p.first], end[p.second], motion, 0.0, h, f);
    if (tau) pending_.push_back({p, *tau});
  }
  if (pending_.empty()) return;
  // An impact is resolved at its t_c; its speculative contact must not close the gap before.
  auto impact = pending_.begin();
  contacts.erase_if([&](const Contact& c) {
    while (impact != pending_.end() && key_of(impact->pair) < c.key()) ++impact;
    return impact != pending_.end() && key_of(impact->pair) == c.key();
  });
}

bool LocalImpacts::touching(const ContactSet& contacts, const Contact& c) const {
  for (const ContactPointState& p : contacts.points(c)) {
    if (p.depth > -settings_.linear_slop) return true;
  }
  return false;
}

bool LocalImpacts::engaged(const ContactSet& contacts, const Contact& c, const MotionState& s,
                           double h) const {
  for (const ContactPointState& p : contacts.points(c)) {
    const double closing = -contact_normal_velocity(s, c, p) * h;  // m
    if (p.depth + std::max(closing, 0.0) > -settings_.linear_slop) return true;
  }
  return false;
}

void LocalImpacts::hand_over(const WorldShapes& start, const MotionState& s, double h,
                             ContactSet& contacts, ContactSet& speculative) {
  marks_.assign(dynamic_.size(), 0);
  const auto join = [this](BodyId b) {
    if (dynamic_[b]) marks_[b] |= kInSolver;
  };
  for (const Contact& c : contacts) {
    if (!engaged(contacts, c, s, h)) continue;
    join(c.body_a);
    join(c.body_b);
  }
  speculative.clear();
  for (bool grew = true; grew;) {
    grew = false;
    std::erase_if(pending_, [&](const Pending& e) {
      if (!in_solver(e.pair.first) && !in_solver(e.pair.second)) return false;
      const WorldShapeView& a = start[e.pair.first];
      const WorldShapeView& b = start[e.pair.second];
      // A margin that reaches the other shape, so that the solver holds the gap closed.
      const ContactManifold m = collide(a, b, signed_distance(a, b) + settings_.contact_margin);
      if (m.count > 0) append_contact(e.pair, shapes_, m, s, speculative);
      join(shapes_[e.pair.first].body);
      join(shapes_[e.pair.second].body);
      grew = true;
      return true;
    });
  }
  // The bodies left with impacts are the exact path's alone: a contact of theirs that is not
  // engaged (apart, not closing within the step) is searched for impacts after theirs instead.
  if (!pending_.empty()) {
    for (const Pending& e : pending_) {
      marks_[shapes_[e.pair.first].body] |= kWithImpact;
      marks_[shapes_[e.pair.second].body] |= kWithImpact;
    }
    drop_contacts_with_impacts(contacts);
  }
}

void LocalImpacts::drop_contacts_with_impacts(ContactSet& contacts) const {
  contacts.erase_if([this](const Contact& c) {
    return (dynamic_[c.body_a] && (marks_[c.body_a] & kWithImpact)) ||
           (dynamic_[c.body_b] && (marks_[c.body_b] & kWithImpact));
  });
}

void LocalImpacts::follow_path(BodyId b, double tau, MotionState& start,
                               const StepAccelerations& acceleration) const {
  const Ballistic path{start, acceleration};
  start.set(b, {path.position(b, tau), path.angle(b, tau), path.velocity(b, tau),
                path.angular_velocity(b, tau)});
}

bool LocalImpacts::resolve(double t, double h, MotionState& start,
                           const StepAccelerations& acceleration, WorldShapes& world_start,
                           WorldShapes& end, ContactSet& contacts, int& impacts,
                           std::vector<Impact>& log) {
  if (pending_.empty()) return true;
  const Ballistic motion{start, acceleration};
  const double same_time = simultaneity(h);
  while (!pending_.empty() && impacts < settings_.max_impacts_per_step) {
    const double tau =
        std::min_element(pending_.begin(), pending_.end(), [](const Pending& x, const Pending& y) {
          return x.time < y.time;
        })->time;
    group_.clear();
    changed_.clear();
    held_.clear();
    // The group's bodies are moved to the impact in `start` itself, which is the step's scratch:
    // only the static and kinematic ones, whose paths the impact does not change, are held aside
    // to be put back after it.
    for (const Pending& e : pending_) {
      if (e.time > tau + same_time) continue;
      group_.push_back(e.pair);
      for (std::uint32_t shape : {e.pair.first, e.pair.second}) {
        const BodyId b = shapes_[shape].body;
        if (dynamic_[b]) {
          if (marks_[b] & kChanged) continue;
          marks_[b] |= kChanged;
          changed_.push_back(b);
        } else {
          if (std::any_of(held_.begin(), held_.end(), [b](const Held& x) { return x.body == b; }))
            continue;
          held_.push_back({b, start.of(b)});
        }
        follow_path(b, tau, start, acceleration);
      }
    }
    std::sort(group_.begin(), group_.end());
    resolve_impacts(group_, shapes_, inertia_, settings_, t + tau, start, impact_contacts_, log);
    ++impacts;
    // Under constant accelerations the path through the state just after the impact, followed
    // back by τ, starts where the body must start to pass through that state.
    for (BodyId b : changed_) follow_path(b, -tau, start, acceleration);
    for (const Held& x : held_) start.set(x.body, x.state);
    std::erase_if(pending_, [this](const Pending& e) {
      return changed(shapes_[e.pair.first]) || changed(shapes_[e.pair.second]);
    });
    if (!search_after(changed_, tau, h, motion, world_start, end)) return false;
    for (BodyId b : changed_) marks_[b] = (marks_[b] & ~kChanged) | kWithImpact;
  }
  if (!pending_.empty()) return false;
  drop_contacts_with_impacts(contacts);
  return true;
}

bool LocalImpacts::search_after(std::span<const BodyId> changed, double tau, double h,
                                const Ballistic& motion, WorldShapes& rest_start,
                                WorldShapes& end) {
  const auto frame_at = [&](std::uint32_t i, double when) {
    const BodyId b = shapes_[i].body;
    return Transform(motion.position(b, when), motion.angle(b, when));
  };
  // First every changed shape placed where the rest of its path starts and ends, so that two
  // changed shapes see each other's.
  for (BodyId b : changed) {
    for (auto [i, last] = shapes_.of_body(b); i < last; ++i) {
      end.place(i, shapes_[i].local, frame_at(i, h));
      rest_start.place(i, shapes_[i].local, frame_at(i, tau));
    }
  }
  const double half_margin = 0.5 * settings_.contact_margin;
  // The box of a shape over the rest of its path, + margin / 2.
  const auto swept = [&](std::uint32_t i) {
    return rest_start.bounds(i).united(end.bounds(i)).fattened(half_margin);
  };
  const ImpactFilter f = impact_filter(settings_);
  for (BodyId b : changed) {
    for (auto [i, last] = shapes_.of_body(b); i < last; ++i) {
      const Aabb box = swept(i);
      const WorldShapeView here = rest_start[i];
      for (std::uint32_t k = 0; k < shapes_.size(); ++k) {
        const BodyId other = shapes_[k].body;
        if (other == b || !box.overlaps(swept(k))) continue;
        // A pair of two changed bodies is searched once, from the one with the lower id.
        if ((marks_[other] & kChanged) && other < b) continue;
        if (in_solver(k)) {
          // Its path is the solver's, not known here: safe to leave to the next step only if
          // neither can have moved through the other by then.
          const double reach_left =
              closing_speed_bound(shapes_[i], shapes_[k], motion, h) * (h - tau);
          if (reach_left >=
              std::min(half_thickness(shapes_[i].local), half_thickness(shapes_[k].local))) {
            return false;
          }
          continue;
        }
        const auto when =
            impact_time(shapes_[i], shapes_[k], here, to_world(shapes_[k].local, frame_at(k, tau)),
                        end[i], end[k], motion, tau, h, f);
        if (when) pending_.push_back({{std::min(i, k), std::max(i, k)}, *when});
      }
    }
  }
  return true;
}

}  // namespace gp
