#include "engine/contacts/contact_solver.hpp"

#include <algorithm>
#include <cmath>

#include "engine/geometry/transform.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/chasles_theorem.hpp"
#include "gamephysics/models/dd/impulse.hpp"
#include "gamephysics/models/dd/relative_velocity.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/collision_impulse.hpp"
#include "gamephysics/models/tm/newton_third_law.hpp"

namespace gp {

namespace {

Vec2 tangent_of(const Vec2& normal) {
  return {-normal.y(), normal.x()};
}

// Effective mass of the two bodies at a point along `direction` [kg]: GD:impulse with C_R = 0
// gives, for a unit closing speed, exactly the impulse per unit change of speed.
double effective_mass(const BodyInertia& m, const Contact& c, const Vec2& arm_a, const Vec2& arm_b,
                      const Vec2& direction) {
  return gd::collision_impulse(0.0, -direction, direction, m.inverse_mass[c.body_a],
                               m.inverse_mass[c.body_b], m.inverse_moment[c.body_a],
                               m.inverse_moment[c.body_b], arm_a, arm_b);
}

// Applies `impulse` to A at its arm and the reaction to B (DD:impulseV, DD:torque,
// TM:NewtonThirdLawMot).
void apply(const BodyInertia& m, const Contact& c, const ContactPointState& p, const Vec2& impulse,
           MotionState& s) {
  const Vec2 reaction = tm::reaction_force(impulse);
  s.velocity[c.body_a] += dd::velocity_change_from_impulse(impulse, m.inverse_mass[c.body_a]);
  s.angular_velocity[c.body_a] += dd::torque(p.arm_a, impulse) * m.inverse_moment[c.body_a];
  s.velocity[c.body_b] += dd::velocity_change_from_impulse(reaction, m.inverse_mass[c.body_b]);
  s.angular_velocity[c.body_b] += dd::torque(p.arm_b, reaction) * m.inverse_moment[c.body_b];
}

}  // namespace

Vec2 contact_relative_velocity(const MotionState& s, const Contact& c, const ContactPointState& p) {
  return dd::relative_velocity(
      dd::point_velocity(s.velocity[c.body_a], s.angular_velocity[c.body_a], p.arm_a),
      dd::point_velocity(s.velocity[c.body_b], s.angular_velocity[c.body_b], p.arm_b));
}

namespace {

// Both normal constraints of an edge-to-edge contact at once, as a 2 × 2 linear complementarity
// problem solved by enumerating its four cases (Box2D's block solver): solving the two points one
// after the other leaves a residual that turns a tall stack. Returns false, leaving the points to
// the one-by-one solver, when the two points are nearly redundant (ill-conditioned matrix).
bool solve_pair(Contact& c, const BodyInertia& inertia, MotionState& s) {
  ContactPointState& p = c.points[0];
  ContactPointState& q = c.points[1];
  const double k11 = 1.0 / p.normal_mass, k22 = 1.0 / q.normal_mass, k12 = c.coupling;
  const double determinant = k11 * k22 - k12 * k12;
  if (k11 * k11 >= 1000.0 * determinant) return false;
  const Vec2 old{p.normal_impulse, q.normal_impulse};
  // Velocities the constraints must reach, less what the impulses already applied give.
  const Vec2 b{contact_relative_velocity(s, c, p).dot(c.normal) - p.target_normal_velocity -
                   (k11 * old.x() + k12 * old.y()),
               contact_relative_velocity(s, c, q).dot(c.normal) - q.target_normal_velocity -
                   (k12 * old.x() + k22 * old.y())};
  Vec2 x;
  if (x = Vec2{(-k22 * b.x() + k12 * b.y()) / determinant,
               (k12 * b.x() - k11 * b.y()) / determinant};
      x.x() >= 0.0 && x.y() >= 0.0) {
  } else if (x = Vec2{-b.x() / k11, 0.0}; x.x() >= 0.0 && k12 * x.x() + b.y() >= 0.0) {
  } else if (x = Vec2{0.0, -b.y() / k22}; x.y() >= 0.0 && k12 * x.y() + b.x() >= 0.0) {
  } else if (x = Vec2::Zero(); b.x() >= 0.0 && b.y() >= 0.0) {
  } else {
    return false;
  }
  apply(inertia, c, p, (x.x() - old.x()) * c.normal, s);
  apply(inertia, c, q, (x.y() - old.y()) * c.normal, s);
  p.normal_impulse = x.x();
  q.normal_impulse = x.y();
  return true;
}

}  // namespace

void prepare_contacts(std::vector<Contact>& contacts, const BodyInertia& inertia,
                      const MotionState& before, double h, const Settings& settings) {
  for (Contact& c : contacts) {
    for (int k = 0; k < c.count; ++k) {
      ContactPointState& p = c.points[k];
      p.normal_mass = effective_mass(inertia, c, p.arm_a, p.arm_b, c.normal);
      if (k == 1) {
        // The off-diagonal term of the two points' effective-mass matrix, whose diagonal is
        // GD:impulse's denominator: arms of point 0 against arms of point 1.
        const ContactPointState& q = c.points[0];
        c.coupling =
            inertia.inverse_mass[c.body_a] + inertia.inverse_mass[c.body_b] +
            inertia.inverse_moment[c.body_a] * cross(q.arm_a, c.normal) * cross(p.arm_a, c.normal) +
            inertia.inverse_moment[c.body_b] * cross(q.arm_b, c.normal) * cross(p.arm_b, c.normal);
      }
      p.tangent_mass = effective_mass(inertia, c, p.arm_a, p.arm_b, tangent_of(c.normal));
      const double approach = contact_relative_velocity(before, c, p).dot(c.normal);
      p.target_normal_velocity = p.depth < 0.0 ? p.depth / h : 0.0;
      p.approach_velocity = 0.0;
      const bool touching = p.depth > -settings.linear_slop;
      if (touching && approach < -settings.restitution_threshold) {
        p.approach_velocity = approach;
      }
    }
  }
}

void warm_start(const std::vector<Contact>& contacts, const BodyInertia& inertia, MotionState& s) {
  for (const Contact& c : contacts) {
    for (int k = 0; k < c.count; ++k) {
      const ContactPointState& p = c.points[k];
      apply(inertia, c, p, p.normal_impulse * c.normal + p.tangent_impulse * tangent_of(c.normal),
            s);
    }
  }
}

void solve_velocities(std::vector<Contact>& contacts, const BodyInertia& inertia, int iterations,
                      MotionState& s) {
  for (int i = 0; i < iterations; ++i) {
    for (Contact& c : contacts) {
      if (c.friction > 0.0) {
        // Friction first, so the normal constraints, solved last, are the ones met exactly.
        const Vec2 tangent = tangent_of(c.normal);
        for (int k = 0; k < c.count; ++k) {
          ContactPointState& p = c.points[k];
          const double limit = c.friction * p.normal_impulse;
          const double change = -p.tangent_mass * contact_relative_velocity(s, c, p).dot(tangent);
          const double total = std::clamp(p.tangent_impulse + change, -limit, limit);
          apply(inertia, c, p, (total - p.tangent_impulse) * tangent, s);
          p.tangent_impulse = total;
        }
      }
      if (c.count == 2 && solve_pair(c, inertia, s)) continue;
      for (int k = 0; k < c.count; ++k) {
        ContactPointState& p = c.points[k];
        const double change = p.normal_mass * (p.target_normal_velocity -
                                               contact_relative_velocity(s, c, p).dot(c.normal));
        const double total = std::max(p.normal_impulse + change, 0.0);
        apply(inertia, c, p, (total - p.normal_impulse) * c.normal, s);
        p.normal_impulse = total;
      }
    }
  }
}

void apply_restitution(std::vector<Contact>& contacts, const BodyInertia& inertia, MotionState& s) {
  for (Contact& c : contacts) {
    if (c.restitution == 0.0) continue;
    for (int k = 0; k < c.count; ++k) {
      ContactPointState& p = c.points[k];
      if (p.approach_velocity == 0.0 || p.normal_impulse == 0.0) continue;
      const double v = contact_relative_velocity(s, c, p).dot(c.normal);
      const double change = -p.normal_mass * (v + c.restitution * p.approach_velocity);
      const double total = std::max(p.normal_impulse + change, 0.0);
      apply(inertia, c, p, (total - p.normal_impulse) * c.normal, s);
      p.normal_impulse = total;
    }
  }
}

void correct_positions(const std::vector<Contact>& contacts, const BodyInertia& inertia,
                       int iterations, double slop, MotionState& s,
                       std::vector<Transform>& rotations) {
  constexpr double kBaumgarte = 0.2;      // fraction of the excess overlap removed per pass
  constexpr double kMaxCorrection = 0.2;  // m per pass, so a deep overlap is not flung apart
  rotations.resize(s.angle.size());
  for (int i = 0; i < iterations; ++i) {
    // One rotation per body per pass rather than per contact point: the turns within a pass are
    // tiny, and the next pass starts from the corrected angles.
    for (std::size_t b = 0; b < s.angle.size(); ++b)
      rotations[b] = Transform(Vec2::Zero(), s.angle[b]);
    for (const Contact& c : contacts) {
      for (int k = 0; k < c.count; ++k) {
        const ContactPointState& p = c.points[k];
        const Vec2 arm_a = rotations[c.body_a].rotate(p.local_anchor_a);
        const Vec2 arm_b = rotations[c.body_b].rotate(p.local_anchor_b);
        const double separation =
            (s.position[c.body_a] + arm_a - s.position[c.body_b] - arm_b).dot(c.normal);
        const double excess = std::clamp(kBaumgarte * (separation + slop), -kMaxCorrection, 0.0);
        if (excess == 0.0) continue;
        // The same effective mass as for impulses, applied to a displacement instead of a velocity.
        const Vec2 shift = -excess * effective_mass(inertia, c, arm_a, arm_b, c.normal) * c.normal;
        s.position[c.body_a] +=
            dd::velocity_change_from_impulse(shift, inertia.inverse_mass[c.body_a]);
        s.angle[c.body_a] = dd::rotated_orientation(
            s.angle[c.body_a], dd::torque(arm_a, shift) * inertia.inverse_moment[c.body_a]);
        const Vec2 back = tm::reaction_force(shift);
        s.position[c.body_b] +=
            dd::velocity_change_from_impulse(back, inertia.inverse_mass[c.body_b]);
        s.angle[c.body_b] = dd::rotated_orientation(
            s.angle[c.body_b], dd::torque(arm_b, back) * inertia.inverse_moment[c.body_b]);
      }
    }
  }
}

}  // namespace gp
