// The oracle's impacts against the laws they must satisfy and against hand computations:
// Newton's law of restitution and Coulomb's law on the impulses at random sets of simultaneous
// contacts (read back from the velocities after the impact, not from the LCP's own variables),
// no energy gained with C_R = 0, and one frictionless contact resolved as IM:col2D.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "gamephysics/models/dd/kinetic_energy.hpp"
#include "gamephysics/models/im/collision_response.hpp"
#include "verification/oracle/contact/impacts.hpp"

using gp::Vec2;
using gp::oracle::ActiveContact;
using gp::oracle::ContactKinematics;
using gp::oracle::Motion;
using gp::oracle::World;

namespace {
namespace test_oracle_impacts {

// A dynamic body of mass m and moment I at the origin's side, for contacts given by hand.
gp::oracle::RigidBody body(double mass, double moment) {
  gp::oracle::RigidBody b{};
  b.type = gp::BodyType::Dynamic;
  b.mass = mass;
  b.moment = moment;
  b.inverse_mass = 1.0 / mass;
  b.inverse_moment = 1.0 / moment;
  return b;
}

gp::oracle::RigidBody fixed() {
  gp::oracle::RigidBody b{};
  b.type = gp::BodyType::Static;
  return b;
}

// A vertex `vertex` of body `first` (its CoM frame) on the edge through `anchor` with outward
// normal `normal` of body `second` (its frame), touching with rounding `radius`.
ActiveContact vertex_on_edge(std::size_t first, std::size_t second, const Vec2& vertex,
                             const Vec2& anchor, const Vec2& normal, double friction,
                             double restitution) {
  ActiveContact c{};
  c.first = first;
  c.second = second;
  c.vertex = vertex;
  c.on_edge = true;
  c.anchor = anchor;
  c.edge_normal = normal;
  c.edge_end = anchor + 10.0 * Vec2(-normal.y(), normal.x());
  c.friction = friction;
  c.restitution = restitution;
  return c;
}

double energy(const World& w, const std::vector<Vec2>& v, const std::vector<double>& omega) {
  double e = 0.0;
  for (std::size_t b = 0; b < w.bodies.size(); ++b) {
    if (w.bodies[b].type == gp::BodyType::Dynamic) {
      e += gp::dd::kinetic_energy(w.bodies[b].mass, v[b], w.bodies[b].moment, omega[b]);
    }
  }
  return e;
}

std::vector<ContactKinematics> kinematics(const std::vector<ActiveContact>& contacts,
                                          const std::vector<Motion>& motions) {
  return gp::oracle::kinematics_of(contacts, motions);
}

TEST_CASE("oracle impacts: Newton's and Coulomb's laws hold at random simultaneous contacts",
          "[oracle][impacts]") {
  std::mt19937 random(23);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  constexpr double kRest = 1e-4;
  for (int trial = 0; trial < 300; ++trial) {
    INFO("trial " << trial);
    // Body 0 lands on a static floor (body 1) and on body 2 at once, at up to three points.
    World w;
    w.bodies = {body(1.0 + uniform(random) * 0.5, 0.2 + 0.1 * uniform(random)), fixed(),
                body(2.0 + uniform(random), 0.5 + 0.2 * uniform(random))};
    const double mu = trial % 4 == 0 ? 0.0 : 1.5 * (1.0 + uniform(random));
    const double e = trial % 3 == 0 ? 0.0 : 0.5 * (1.0 + uniform(random));
    std::vector<ActiveContact> contacts = {
        vertex_on_edge(0, 1, {-0.5, -0.5}, {0.0, 0.0}, {0.0, 1.0}, mu, e),
        vertex_on_edge(0, 1, {0.5, -0.5}, {0.0, 0.0}, {0.0, 1.0}, mu, e),
        vertex_on_edge(0, 2, {0.5 + 0.1 * uniform(random), 0.2}, {-0.3, 0.0},
                       Vec2(-1.0, 0.3 * uniform(random)).normalized(), mu, e)};
    if (trial % 2 == 1) contacts.pop_back();
    std::vector<Motion> motions = {
        {{0.0, 0.5}, 0.0, {uniform(random), -1.0 + 0.5 * uniform(random)}, uniform(random)},
        {{0.0, 0.0}, 0.0, Vec2::Zero(), 0.0},
        {{1.3, 0.5}, 0.0, {-0.5 + 0.3 * uniform(random), 0.1 * uniform(random)}, uniform(random)}};
    const auto before = kinematics(contacts, motions);
    std::vector<Vec2> v = {motions[0].velocity, motions[1].velocity, motions[2].velocity};
    std::vector<double> omega = {motions[0].angular_velocity, motions[1].angular_velocity,
                                 motions[2].angular_velocity};
    const double e_before = energy(w, v, omega);
    const auto p = gp::oracle::resolve_impacts(w, contacts, before, kRest, v, omega);
    for (std::size_t b = 0; b < motions.size(); ++b) {
      motions[b].velocity = v[b];
      motions[b].angular_velocity = omega[b];
    }
    const auto after = kinematics(contacts, motions);
    const double scale = 3.0;  // m/s, N·s: the speeds and impulses of the trial are below this
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      INFO("contact " << i << ": p = " << p[i].normal << ", p_t = " << p[i].tangent
                      << ", ġ⁻ = " << before[i].gap_rate << ", ġ⁺ = " << after[i].gap_rate
                      << ", s⁺ = " << after[i].slip);
      const double restitution = before[i].gap_rate < -kRest ? e : 0.0;
      const double newton = after[i].gap_rate + restitution * before[i].gap_rate;
      CHECK(p[i].normal >= 0.0);
      CHECK(newton >= -1e-12 * scale);
      CHECK(std::abs(newton * p[i].normal) <= 1e-12 * scale * scale);
      CHECK(std::abs(p[i].tangent) <= mu * p[i].normal + 1e-12 * scale);
      if (std::abs(p[i].tangent) < mu * p[i].normal - 1e-9 * scale) {
        CHECK(std::abs(after[i].slip) <= 1e-12 * scale);  // inside the cone: sticks
      } else {
        CHECK(after[i].slip * p[i].tangent <= 1e-12 * scale * scale);  // on it: opposes slip
      }
    }
    if (e == 0.0) CHECK(energy(w, v, omega) <= e_before * (1.0 + 1e-12));
  }
}

TEST_CASE("oracle impacts: one frictionless contact is IM:col2D", "[oracle][impacts]") {
  World w;
  w.bodies = {body(2.0, 0.3), body(1.0, 0.1)};
  const std::vector<ActiveContact> contacts = {
      vertex_on_edge(0, 1, {0.2, -0.5}, {0.0, 0.5}, {0.0, 1.0}, 0.0, 0.6)};
  const std::vector<Motion> motions = {{{0.0, 1.0}, 0.0, {0.4, -2.0}, 1.5},
                                       {{0.1, 0.0}, 0.0, {0.0, 1.0}, -0.5}};
  const auto k = kinematics(contacts, motions);
  std::vector<Vec2> v = {motions[0].velocity, motions[1].velocity};
  std::vector<double> omega = {motions[0].angular_velocity, motions[1].angular_velocity};
  const auto p = gp::oracle::resolve_impacts(w, contacts, k, 1e-4, v, omega);
  // IM:col2D by hand: j = −(1 + C_R) v_rel·n / (1/m_A + 1/m_B + (r_A × n)²/I_A + (r_B × n)²/I_B).
  const Vec2 n(0.0, 1.0);
  const Vec2 ra = k[0].first_arm, rb = k[0].second_arm;
  const auto point_velocity = [](const Vec2& vc, double w_, const Vec2& r) {
    return Vec2(vc.x() - w_ * r.y(), vc.y() + w_ * r.x());
  };
  const double closing =
      (point_velocity(motions[0].velocity, 1.5, ra) - point_velocity(motions[1].velocity, -0.5, rb))
          .dot(n);
  const double ca = ra.x() * n.y() - ra.y() * n.x(), cb = rb.x() * n.y() - rb.y() * n.x();
  const double j = -(1.6) * closing / (0.5 + 1.0 + ca * ca / 0.3 + cb * cb / 0.1);
  CHECK(p[0].normal == Approx(j).epsilon(1e-14));
  CHECK(p[0].tangent == 0.0);
  CHECK(v[0].y() == Approx(-2.0 + j / 2.0).epsilon(1e-14));
  CHECK(omega[0] == Approx(1.5 + ca * j / 0.3).epsilon(1e-14));
}

}  // namespace test_oracle_impacts
}  // namespace
