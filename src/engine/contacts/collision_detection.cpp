#include "engine/contacts/collision_detection.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "engine/collision/narrowphase.hpp"
#include "engine/collision/swept_boxes.hpp"
#include "engine/geometry/transform.hpp"

namespace gp {

namespace {

// Where shape `shape` of a body at `frame` reaches deepest into the other shape, as an anchor in
// the body's frame plus a radius along the normal away from the shape (see ContactPointState).
std::pair<Vec2, double> anchor(const GeometryView& shape, const Transform& frame,
                               const Vec2& deepest) {
  if (const auto* circle = std::get_if<Circle>(&shape)) {
    return {circle->center, circle->radius};
  }
  return {frame.unrotate(deepest - frame.position()), 0.0};
}

}  // namespace

const std::vector<ProxyPair>& CollisionDetection::candidate_pairs(const BodyShapes& shapes,
                                                                  const std::vector<char>& dynamic,
                                                                  const WorldShapes& start,
                                                                  const WorldShapes& end) {
  // The shapes' bodies side by side: the broadphase and the pairs below look them up at random,
  // and a whole shape record per look-up costs a cache miss each in a large scene.
  body_of_.resize(shapes.size());
  for (std::uint32_t i = 0; i < shapes.size(); ++i) body_of_[i] = shapes[i].body;
  broadphase_.find_pairs(SweptBoxes(start, end, body_of_, dynamic), pairs_);
  // Two parts of one body never collide.
  std::erase_if(pairs_,
                [this](const ProxyPair& p) { return body_of_[p.first] == body_of_[p.second]; });
  // Sorted pairs make the order of the solver, and so the result, independent of the
  // broadphase's internal order.
  pair_order_.sort(pairs_, static_cast<std::uint32_t>(shapes.size()));
  return pairs_;
}

Contact& append_contact(const ProxyPair& pair, const BodyShapes& shapes, const ContactManifold& m,
                        const MotionState& s, ContactSet& contacts) {
  const ShapeRecord& a = shapes[pair.first];
  const ShapeRecord& b = shapes[pair.second];
  // Built in place: a contact built apart and then copied in is read back right after being
  // written, and the copy's wide loads stall on the narrower stores that wrote it.
  Contact& c = contacts.append(m.count);
  c.shape_a = pair.first;
  c.shape_b = pair.second;
  c.body_a = a.body;
  c.body_b = b.body;
  c.normal = m.normal;
  c.restitution = std::max(a.restitution, b.restitution);
  c.friction = std::sqrt(a.friction * b.friction);
  // A disc's anchor needs no frame: spare its trigonometry.
  const auto frame_of = [&s](const ShapeRecord& r) {
    return kind_of(r.local) == ShapeKind::kCircle ? Transform()
                                                  : Transform(s.position[r.body], s.angle[r.body]);
  };
  const Transform frame_a = frame_of(a);
  const Transform frame_b = frame_of(b);
  const std::span<ContactPointState> points = contacts.points(c);
  for (int k = 0; k < m.count; ++k) {
    const ContactPoint& point = m.points[k];
    ContactPointState& q = points[k];
    q.id = point.id;
    q.depth = point.depth;
    set_arms(q, m.normal, point.position - s.position[a.body], point.position - s.position[b.body]);
    // The deepest points of each shape inside the other, fixed in their bodies, measure the
    // penetration again after the bodies move (position correction).
    std::tie(q.local_anchor_a, q.anchor_radius_a) =
        anchor(a.local, frame_a, point.position - 0.5 * point.depth * m.normal);
    std::tie(q.local_anchor_b, q.anchor_radius_b) =
        anchor(b.local, frame_b, point.position + 0.5 * point.depth * m.normal);
  }
  return c;
}

void CollisionDetection::find_contacts(const std::vector<ProxyPair>& pairs,
                                       const BodyShapes& shapes, const WorldShapes& world,
                                       const MotionState& s, const std::vector<WarmStart>& previous,
                                       double impulse_scale, ContactSet& contacts) const {
  contacts.clear();
  auto old = previous.begin();
  for (const ProxyPair& p : pairs) {
    const ContactManifold m = collide(world[p.first], world[p.second], margin_);
    if (m.count == 0) continue;
    Contact& c = append_contact(p, shapes, m, s, contacts);
    // previous is sorted by key, and so are the pairs: one forward scan matches them.
    const std::uint64_t pair = WarmStart::pair_key(p);
    while (old != previous.end() && old->pair() < pair) ++old;
    for (auto same = old; same != previous.end() && same->pair() == pair; ++same) {
      for (ContactPointState& q : contacts.points(c)) {
        if (same->features() == q.id.key()) {
          q.normal_impulse = impulse_scale * same->normal;
          q.tangent_impulse = impulse_scale * same->tangent;
        }
      }
    }
  }
}

}  // namespace gp
