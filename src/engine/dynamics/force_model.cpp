#include "engine/dynamics/force_model.hpp"

#include <algorithm>

#include "engine/capacity.hpp"
#include "engine/geometry/transform.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/gravitational_acceleration.hpp"
#include "gamephysics/models/im/rotational_motion.hpp"
#include "gamephysics/models/im/translational_motion.hpp"

namespace gp {

ForceModel::ForceModel(const Settings& settings)
    : gravity_(settings.gravity),
      // No force: the same for every mass.
      falling_(im::translational_acceleration(settings.gravity, Vec2::Zero(), 1.0)),
      G_(settings.G) {}

bool ForceModel::beyond_gravity(const BodyForces& forces) {
  return forces.force != Vec2::Zero() || forces.torque != 0.0 || forces.force_at_point ||
         forces.callback;
}

ForceModel::Pushed ForceModel::pushed_by(BodyId body, const Applied& applied,
                                         bool with_next_step) const {
  // As evaluate() has them when the forces are constant.
  const BodyForces& f = applied.forces;
  const Vec2 force = with_next_step ? Vec2(f.force + applied.next_step.force) : f.force;
  const double torque = with_next_step ? f.torque + applied.next_step.torque : f.torque;
  return {body, im::translational_acceleration(gravity_, force, f.mass),
          rotates_[applied.entry] ? im::angular_acceleration(torque, 1.0 / f.inverse_moment) : 0.0};
}

void ForceModel::add(BodyId id, BodyForces forces) {
  const auto entry = static_cast<std::uint32_t>(ids_.size());
  append(ids_, id);
  append(masses_, forces.mass);
  append(rotates_, forces.inverse_moment > 0.0);
  if (!beyond_gravity(forces)) return;
  const Applied applied{entry, std::move(forces)};
  const Pushed pushed = pushed_by(id, applied, false);
  // The largest id so far: appended, the entries stay in order.
  in_each([&](std::vector<Applied>& a, std::vector<Pushed>& p) {
    a.push_back(applied);
    p.push_back(pushed);
  });
}

template <typename Change>
void ForceModel::in_each(Change change) {
  change(applied_, pushed_);
  if (before_next_step_) change(before_next_step_->applied, before_next_step_->pushed);
}

std::vector<ForceModel::Applied>::iterator ForceModel::applied_at(std::vector<Applied>& applied,
                                                                  std::uint32_t entry,
                                                                  double inverse_moment) const {
  auto at = std::lower_bound(applied.begin(), applied.end(), entry,
                             [](const Applied& a, std::uint32_t e) { return a.entry < e; });
  if (at == applied.end() || at->entry != entry) {
    // A body of gravity only so far: its constant forces are none.
    at = applied.insert(
        at,
        {entry, {masses_[entry], inverse_moment, Vec2::Zero(), 0.0, false, Vec2::Zero(), nullptr}});
  }
  return at;
}

void ForceModel::set_callback(BodyId id, double inverse_moment, ForceCallback callback) {
  const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
  if (it == ids_.end() || *it != id) return;
  const auto entry = static_cast<std::uint32_t>(it - ids_.begin());
  in_each([&](std::vector<Applied>& applied, std::vector<Pushed>&) {
    applied_at(applied, entry, inverse_moment)->forces.callback = callback;
  });
}

void ForceModel::add_for_next_step(BodyId id, double inverse_moment, const Wrench& wrench) {
  const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
  if (it == ids_.end() || *it != id) return;
  if (!before_next_step_) before_next_step_ = Saved{applied_, pushed_};
  const auto at =
      applied_at(applied_, static_cast<std::uint32_t>(it - ids_.begin()), inverse_moment);
  at->next_step.force += wrench.force;
  at->next_step.torque += wrench.torque;
  const Pushed now = pushed_by(id, *at, true);
  const auto p = std::lower_bound(pushed_.begin(), pushed_.end(), id,
                                  [](const Pushed& q, BodyId b) { return q.body < b; });
  if (p != pushed_.end() && p->body == id) {
    *p = now;
  } else {
    pushed_.insert(p, now);
  }
}

void ForceModel::end_step() {
  if (!before_next_step_) return;
  applied_ = std::move(before_next_step_->applied);
  pushed_ = std::move(before_next_step_->pushed);
  before_next_step_.reset();
}

void ForceModel::remove(BodyId id) {
  const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
  if (it == ids_.end() || *it != id) return;
  const auto entry = static_cast<std::uint32_t>(it - ids_.begin());
  ids_.erase(it);
  masses_.erase(masses_.begin() + entry);
  rotates_.erase(rotates_.begin() + entry);
  // The entries after the body's move down by one.
  in_each([entry, id](std::vector<Applied>& applied, std::vector<Pushed>& pushed) {
    std::erase_if(applied, [entry](const Applied& a) { return a.entry == entry; });
    for (Applied& a : applied) a.entry -= a.entry > entry ? 1 : 0;
    std::erase_if(pushed, [id](const Pushed& p) { return p.body == id; });
  });
}

bool ForceModel::constant() const {
  if (G_) return false;
  return std::none_of(applied_.begin(), applied_.end(), [](const Applied& a) {
    return a.forces.force_at_point || a.forces.callback;
  });
}

bool ForceModel::any_applied() const {
  return std::any_of(applied_.begin(), applied_.end(), [](const Applied& a) {
    return a.forces.force != Vec2::Zero() || a.forces.torque != 0.0 || a.forces.callback;
  });
}

void ForceModel::evaluate(double t, const MotionState& s, Accelerations& out) const {
  auto applied = applied_.begin();
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    const BodyId j = ids_[k];
    Vec2 g = gravity_;
    if (G_) {
      for (std::size_t other = 0; other < ids_.size(); ++other) {
        if (other == k) continue;
        const BodyId i = ids_[other];
        g += gd::gravitational_acceleration(*G_, masses_[other], s.position[j] - s.position[i]);
      }
    }
    if (applied == applied_.end() || applied->entry != k) {
      out.linear[j] = im::translational_acceleration(g, Vec2::Zero(), masses_[k]);
      out.angular[j] = 0.0;
      continue;
    }
    const Applied& a = *applied++;
    const BodyForces& f = a.forces;
    Vec2 force = f.force;
    double torque = f.torque;
    if (before_next_step_) {
      force += a.next_step.force;
      torque += a.next_step.torque;
    }
    if (f.force_at_point) {
      // The point turns with the body, so its arm, and the torque, change with ϕ.
      torque += dd::torque(Transform(Vec2::Zero(), s.angle[j]).rotate(f.arm), f.force);
    }
    if (f.callback) {
      const Wrench w = f.callback(t, j, s.of(j));
      force += w.force;
      torque += w.torque;
    }
    out.linear[j] = im::translational_acceleration(g, force, masses_[k]);
    out.angular[j] = rotates_[k] ? im::angular_acceleration(torque, 1.0 / f.inverse_moment) : 0.0;
  }
}

}  // namespace gp
