#include "verification/oracle/contact/contact_kinematics.hpp"

#include <cmath>

namespace gp::oracle {

namespace {

Vec2 rotated(const Vec2& v, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// u rotated by +90°: ω × u = ω·perp(u) for a rotation rate ω about z.
Vec2 perp(const Vec2& u) {
  return {-u.y(), u.x()};
}

// The velocity of a body's material point at arm r from its centre of mass.
Vec2 point_velocity(const Motion& m, const Vec2& arm) {
  return m.velocity + m.angular_velocity * perp(arm);
}

// The row of d(n·Δv)/dt for a force along unit `direction` at `point`: (dir, r × dir) per body.
ContactRow row_along(const Vec2& direction, const Vec2& point, const Motion& first,
                     const Motion& second, double bias) {
  const Vec2 r1 = point - first.position;
  const Vec2 r2 = point - second.position;
  return {Eigen::Vector3d(direction.x(), direction.y(), cross(r1, direction)),
          Eigen::Vector3d(-direction.x(), -direction.y(), -cross(r2, direction)), bias};
}

}  // namespace

ContactKinematics contact_kinematics(const ActiveContact& c, const Motion& first,
                                     const Motion& second) {
  const double w1 = first.angular_velocity;
  const double w2 = second.angular_velocity;
  const Vec2 rho1 = rotated(c.vertex, first.angle);
  const Vec2 rho2 = rotated(c.anchor, second.angle);
  const Vec2 p = first.position + rho1;
  const Vec2 q = second.position + rho2;
  const Vec2 p_dot = point_velocity(first, rho1);
  const Vec2 q_dot = point_velocity(second, rho2);
  const Vec2 d = p - q;
  const Vec2 d_dot = p_dot - q_dot;

  ContactKinematics k{};
  Vec2 normal_dot;
  if (c.on_edge) {
    k.normal = rotated(c.edge_normal, second.angle);
    normal_dot = w2 * perp(k.normal);
    k.gap = d.dot(k.normal) - c.radius;
    k.gap_rate = d_dot.dot(k.normal) + d.dot(normal_dot);
    // g̈ = (P̈ − Q̈)·N + 2(Ṗ − Q̇)·Ṅ + d·N̈, with P̈ = a₁ + α₁ ρ₁⊥ − ω₁²ρ₁ (likewise Q̈) and
    // N̈ = α₂ N⊥ − ω₂² N. The α₂ terms gather into the arm P − c₂.
    const double bias = -w1 * w1 * rho1.dot(k.normal) + w2 * w2 * (rho2 - d).dot(k.normal) +
                        2.0 * d_dot.dot(normal_dot);
    k.normal_row = row_along(k.normal, p, first, second, bias);
    const Vec2 edge = rotated(c.edge_end - c.anchor, second.angle);
    k.edge_length = edge.norm();
    k.along_edge = d.dot(edge) / k.edge_length;
  } else {
    const double length = d.norm();
    k.normal = d / length;
    const double rate = k.normal.dot(d_dot);
    normal_dot = (d_dot - rate * k.normal) / length;
    k.gap = length - c.radius;
    k.gap_rate = rate;
    // g̈ = N·d̈ + (|ḋ|² − (N·ḋ)²)/|d|.
    const double bias = k.normal.dot(-w1 * w1 * rho1 + w2 * w2 * rho2) +
                        (d_dot.squaredNorm() - rate * rate) / length;
    ContactRow row = row_along(k.normal, p, first, second, bias);
    // Both points are material points of their own bodies: the second's arm is ρ₂, not P − c₂.
    row.second.z() = -cross(rho2, k.normal);
    k.normal_row = row;
    k.along_edge = 0.0;
    k.edge_length = 0.0;
  }
  k.tangent = perp(k.normal);
  const Vec2 tangent_dot = perp(normal_dot);
  k.point = p - c.first_radius * k.normal;
  k.first_arm = k.point - first.position;
  k.second_arm = k.point - second.position;
  const Vec2 point_dot = p_dot - c.first_radius * normal_dot;
  const Vec2 slip_velocity =
      point_velocity(first, k.first_arm) - point_velocity(second, k.second_arm);
  k.slip = k.tangent.dot(slip_velocity);
  // ṡ = ṫ·Δv + t·(a₁ + α₁(C − c₁)⊥ + ω₁(Ċ − v₁)⊥ − the same for the second body), C moving
  // along both surfaces as they roll.
  const double tangent_bias = tangent_dot.dot(slip_velocity) +
                              w1 * cross(point_dot - first.velocity, k.tangent) -
                              w2 * cross(point_dot - second.velocity, k.tangent);
  k.tangent_row = row_along(k.tangent, k.point, first, second, tangent_bias);
  return k;
}

std::vector<ContactKinematics> kinematics_of(std::span<const ActiveContact> contacts,
                                             std::span<const Motion> motions) {
  std::vector<ContactKinematics> k;
  k.reserve(contacts.size());
  for (const ActiveContact& c : contacts) {
    k.push_back(contact_kinematics(c, motions[c.first], motions[c.second]));
  }
  return k;
}

}  // namespace gp::oracle
