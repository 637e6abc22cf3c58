// The oracle against the closed forms of the shipped contact scenes: a block sliding down a
// ramp, a disc rolling without slipping, a box held by static friction, a box dropped flat that
// comes to rest, a stack at rest. The closed forms read the scene's geometry, not the oracle's.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "verification/suite/oracle_trajectory.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

namespace {

struct Motion {
  Vec2 position;
  Vec2 velocity;
  double angular_velocity;
};

// The motion of dynamic body `body` at time t [s].
using ClosedForm = std::function<Motion(std::size_t body, double t)>;

// μ = √(μ_a μ_b) of the first shapes of bodies 0 (the ground or ramp) and 1.
double friction(const Scene& s) {
  return std::sqrt(s.bodies[0].shapes[0].friction * s.bodies[1].shapes[0].friction);
}

// m: the largest y of a body's first shape (a polygon or circle) in its unturned frame.
double half_height(const BodyDef& b) {
  const auto& g = b.shapes[0].shape.geometry();
  if (const auto* c = std::get_if<Circle>(&g)) return c->radius;
  const auto& p = std::get<ConvexPolygon>(g);
  double top = 0.0;
  for (int i = 0; i < p.count; ++i) top = std::max(top, p.vertices[i].y());
  return top;
}

Motion at_rest(const Scene& s, std::size_t body) {
  return {s.bodies[body].position, Vec2::Zero(), 0.0};
}

// Uniform acceleration `a` [m/s²] from rest down the ramp (body 0, turned by θ, rising to +x);
// a disc of radius r rolls with ω = a t / r.
ClosedForm down_the_ramp(const Scene& s, double a, double rolling_radius) {
  const double theta = s.bodies[0].angle;
  const Vec2 down(-std::cos(theta), -std::sin(theta));
  return [&s, a, rolling_radius, down](std::size_t body, double t) -> Motion {
    return {s.bodies[body].position + 0.5 * a * t * t * down, a * t * down,
            rolling_radius > 0 ? a * t / rolling_radius : 0.0};
  };
}

struct Case {
  const char* scene;
  const char* law;
  std::function<ClosedForm(const Scene&, double g)> closed_form;
};

const Case kCases[] = {
    {"ramp_slide", "a = g (sin θ − μ cos θ)",
     [](const Scene& s, double g) {
       const double theta = s.bodies[0].angle;
       return down_the_ramp(s, g * (std::sin(theta) - friction(s) * std::cos(theta)), 0.0);
     }},
    {"disc_roll", "a = 2/3 g sin θ, ω = v / r",
     [](const Scene& s, double g) {
       return down_the_ramp(s, 2.0 / 3.0 * g * std::sin(s.bodies[0].angle),
                            half_height(s.bodies[1]));
     }},
    {"static_friction", "at rest (μ > tan θ)",
     [](const Scene& s, double) {
       return ClosedForm([&s](std::size_t body, double) { return at_rest(s, body); });
     }},
    {"box_drop", "free fall, lands at √(2h/g), then at rest (C_R = 0)",
     [](const Scene& s, double g) {
       const double start = s.bodies[1].position.y();
       const double rest =
           s.bodies[0].position.y() + half_height(s.bodies[0]) + half_height(s.bodies[1]);
       const double landing = std::sqrt(2.0 * (start - rest) / g);
       return ClosedForm([&s, g, start, rest, landing](std::size_t body, double t) -> Motion {
         const double x = s.bodies[body].position.x();
         if (t >= landing) return {Vec2(x, rest), Vec2::Zero(), 0.0};
         return {Vec2(x, start - 0.5 * g * t * t), Vec2(0.0, -g * t), 0.0};
       });
     }},
    {"stack3", "every box at rest",
     [](const Scene& s, double) {
       return ClosedForm([&s](std::size_t body, double) { return at_rest(s, body); });
     }},
};

}  // namespace

std::vector<Check> closed_form_checks(const std::vector<NamedScene>& scenes,
                                      const SuiteOptions& o) {
  CheckList list("oracle against closed forms (contact)");
  for (const Case& c : kCases) {
    const auto named = std::find_if(scenes.begin(), scenes.end(),
                                    [&c](const NamedScene& s) { return s.name == c.scene; });
    if (named == scenes.end()) {
      list.check(c.scene, "", "scene missing from scenes/", "the scene is shipped", false);
      continue;
    }
    const Scene& scene = named->scene;
    if (o.progress) *o.progress << "  closed forms: " << c.scene << "\n";
    const std::vector<double> times = output_instants(scene.duration, scene.output_dt);
    Trajectory oracle;
    try {
      oracle = run_oracle_trajectory(scene, times, OracleOptions{});
    } catch (const OracleDomainError& e) {
      list.check(c.scene, "", std::string("left the oracle's domain: ") + e.what(), "in the domain",
                 false);
      continue;
    }
    const ClosedForm expected = c.closed_form(scene, scene.settings.gravity.norm());
    double worst = 0.0;  // |Δ| / max(|expected|, 1), over instants, bodies and components
    const auto relative = [](double actual, double exact) {
      return std::abs(actual - exact) / std::max(std::abs(exact), 1.0);
    };
    for (std::size_t k = 0; k < oracle.times.size(); ++k) {
      for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
        if (scene.bodies[b].type != BodyType::Dynamic) continue;
        const Motion m = expected(b, oracle.times[k]);
        const BodyState& s = oracle.states[k][b];
        for (int i = 0; i < 2; ++i) {
          worst = std::max({worst, relative(s.position[i], m.position[i]),
                            relative(s.velocity[i], m.velocity[i])});
        }
        worst = std::max(worst, relative(s.angular_velocity, m.angular_velocity));
      }
    }
    list.within(std::string(c.scene) + ": " + c.law + ", cvode-adams, rtol = atol = 1e-12",
                "IM:transMot IM:rotMot", "largest relative difference " + figure(worst), "≤ 1e-9",
                {{worst, 1e-9}},
                "1e-9 is the accuracy the oracle claims (docs/oracle.md), which this row "
                "establishes; at rest or in free fall it is exact to rounding");
  }
  return list.rows();
}

}  // namespace gp::verification
