#include "engine/collision/collision_detection.hpp"

#include "engine/step/step_context.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/collision/narrowphase.hpp"
#include "engine/collision/swept_boxes.hpp"
#include "engine/threads.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

namespace gp {

const std::vector<ShapePair>& CollisionDetection::candidate_pairs(const BodyShapes& shapes,
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
                [this](const ShapePair& p) { return body_of_[p.first] == body_of_[p.second]; });
  // Sorted pairs make the order of the solver, and so the result, independent of the
  // broadphase's internal order.
  pair_order_.sort(pairs_, static_cast<std::uint32_t>(shapes.size()));
  return pairs_;
}

namespace {

// Pairs a thread takes at a time: a manifold costs about a hundred nanoseconds, a task about a
// microsecond to hand out.
constexpr std::size_t kPairsPerTask = 256;
// Pairs whose manifolds are found side by side before they are appended: two blocks take 280 kB
// of slots.
constexpr std::size_t kPairsPerBlock = 4 * kPairsPerTask;

AnchorKind anchor_kind(const ShapeRecord& shape) {
  if (shape.centred_disc()) return AnchorKind::kCentredDisc;
  return shape.local.kind() == ShapeKind::kCircle ? AnchorKind::kOffsetDisc : AnchorKind::kFixed;
}

}  // namespace

Contact& append_contact(const ShapePair& pair, const BodyShapes& shapes, const ContactManifold& m,
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
  c.friction = std::sqrt(a.friction * b.friction);
  const AnchorKind anchor_a = anchor_kind(a);
  const AnchorKind anchor_b = anchor_kind(b);
  const std::span<ContactPointState> points = contacts.points(c);
  for (int k = 0; k < m.count; ++k) {
    const ContactPoint& point = m.points[k];
    ContactPointState& q = points[k];
    q.id = point.id;
    q.anchor_a = anchor_a;
    q.anchor_b = anchor_b;
    q.depth = static_cast<float>(point.depth);
    set_arms(q, m.normal, point.position - s.position[a.body], point.position - s.position[b.body]);
  }
  return c;
}

void CollisionDetection::find_contacts(StepContext& ctx) {
  const BodyShapes& shapes = ctx.shapes;
  const WorldShapes& world = ctx.world_start;
  const std::vector<WarmStart>& previous = ctx.warm_starts;
  const double impulse_scale = ctx.warm_start_scale();
  ContactSet& contacts = ctx.contacts;
  contacts.clear();
  const std::span<const ShapePair> pairs = ctx.pairs;
  auto old = previous.begin();
  const auto append = [&](const ShapePair& p, const ContactManifold& m) {
    if (m.count == 0) return;
    Contact& c = append_contact(p, shapes, m, ctx.start, contacts);
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
  };
  if (one_thread()) {
    for (const ShapePair& p : pairs) append(p, collide(world[p.first], world[p.second], margin_));
    return;
  }
  // On several threads, each pair's manifold into its own slot first; then appended in the
  // pairs' order, so the contacts do not depend on the number of threads. A block of pairs at a
  // time, so that the slots take a fixed room rather than room per body; the next block's
  // manifolds are found on the other threads while this one's are appended.
  manifolds_.resize(2 * kPairsPerBlock);
  const auto slots_of = [](std::size_t first) {
    return (first / kPairsPerBlock) % 2 * kPairsPerBlock;
  };
  const auto collide_block = [&](std::size_t first) {
    const std::size_t slots = slots_of(first);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(
                          first, std::min(first + kPairsPerBlock, pairs.size()), kPairsPerTask),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i < r.end(); ++i) {
                          manifolds_[slots + i - first] =
                              collide(world[pairs[i].first], world[pairs[i].second], margin_);
                        }
                      });
  };
  if (!pairs.empty()) collide_block(0);
  tbb::task_group next_block;
  for (std::size_t first = 0; first < pairs.size(); first += kPairsPerBlock) {
    const std::size_t next = first + kPairsPerBlock;
    if (next < pairs.size()) next_block.run([&collide_block, next] { collide_block(next); });
    const std::size_t slots = slots_of(first);
    for (std::size_t i = first; i < std::min(next, pairs.size()); ++i) {
      append(pairs[i], manifolds_[slots + i - first]);
    }
    next_block.wait();
  }
}

}  // namespace gp
