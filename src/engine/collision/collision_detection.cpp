#include "engine/collision/collision_detection.hpp"

#include "engine/step/step_context.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "engine/capacity.hpp"
#include "engine/collision/narrowphase.hpp"
#include "engine/prefetch.hpp"
#include "engine/threads.hpp"

namespace gp {

std::span<const ShapePair> CollisionDetection::drop_pairs(std::span<const ShapePair> dropped) {
  std::vector<ShapePair>& pairs = candidates_.pairs();
  std::erase_if(pairs, [dropped](const ShapePair& p) {
    return std::find(dropped.begin(), dropped.end(), p) != dropped.end();
  });
  return pairs;
}

namespace {

// Pairs a thread takes at a time, a run whose contacts are placed one after the other: a
// manifold costs about a hundred nanoseconds, a task about a microsecond to hand out.
constexpr std::size_t kCollidedPairsPerRun = 256;
constexpr std::size_t kRunsPerBlock = 64;
// Pairs whose manifolds are found side by side before their contacts are placed, 88 B each: 1.4
// MB. The threads wait for each other twice a block: blocks of 4096 pairs made many_pyramids'
// narrowphase on two threads a sixth slower.
constexpr std::size_t kCollidedPairsPerBlock = kRunsPerBlock * kCollidedPairsPerRun;

// How far ahead of the threads' stores their cache lines are asked for (prefetch.hpp), in
// manifolds and in contacts: on large_pyramid on two threads, the manifolds took a tenth less
// time and the contacts' filling in two fifths less.
constexpr std::size_t kManifoldsAhead = 4;
constexpr std::size_t kContactsAhead = 8;

// Pairs whose discs' centre gaps are found before their contacts, on one thread: a gap's square
// root and division, found for pair after pair, overlap, where between two contacts' other work
// each would be waited on.
constexpr std::size_t kGapsAhead = 32;

// The centre gaps of the pairs of two discs among the first kGapsAhead of `pairs` into `gaps`,
// each at its pair's place.
void find_centre_gaps(const WorldShapes& world, std::span<const ShapePair> pairs,
                      std::array<CentreGap, kGapsAhead>& gaps) {
  for (std::size_t k = 0; k < std::min(kGapsAhead, pairs.size()); ++k) {
    const PackedGeometry& a = world.packed(pairs[k].first);
    const PackedGeometry& b = world.packed(pairs[k].second);
    if (two_discs(a, b)) gaps[k] = centre_gap(a.circle(), b.circle());
  }
}

AnchorKind anchor_kind(const ShapeRecord& shape) {
  if (shape.centred_disc()) return AnchorKind::kCentredDisc;
  return shape.offset_disc() ? AnchorKind::kOffsetDisc : AnchorKind::kFixed;
}

// Fills in contact `c`, just appended with its `points`, from the manifold `m` of `pair` found
// in state `s`: combined friction, and per point its depth and arms.
void fill_contact(const ShapePair& pair, const BodyShapes& shapes, const ContactManifold& m,
                  const MotionState& s, Contact& c, std::span<ContactPointState> points) {
  const ShapeRecord& a = shapes[pair.first];
  const ShapeRecord& b = shapes[pair.second];
  c.shape_a = pair.first;
  c.shape_b = pair.second;
  c.body_a = a.body;
  c.body_b = b.body;
  c.normal = m.normal;
  c.friction = std::sqrt(a.friction * b.friction);
  const AnchorKind anchor_a = anchor_kind(a);
  const AnchorKind anchor_b = anchor_kind(b);
  for (int k = 0; k < m.count; ++k) {
    const ContactPoint& point = m.points[k];
    ContactPointState& q = points[k];
    q.id = point.id;
    q.anchor_a = anchor_a;
    q.anchor_b = anchor_b;
    q.depth = static_cast<float>(point.depth);
    set_arms(q, m.normal, point.position - s.position[a.body], point.position - s.position[b.body]);
  }
}

// Starts each of `points`, those of manifold `m` of the pair whose key is `pair`, from the
// impulses of the warm start with its features, scaled by `scale`. The features are the
// manifold's at hand: a point's id read back from the contact just written waits on the stores
// that wrote it. The warm starts are sorted by pair, and the pairs visited in that order: `next`
// moves forward to the first warm start of pairs not before `pair`, where the next pair's search
// starts.
void warm_start_points(std::vector<WarmStart>::const_iterator& next,
                       std::vector<WarmStart>::const_iterator end, std::uint64_t pair, double scale,
                       const ContactManifold& m, std::span<ContactPointState> points) {
  while (next != end && next->pair() < pair) ++next;
  for (auto same = next; same != end && same->pair() == pair; ++same) {
    for (int k = 0; k < m.count; ++k) {
      if (same->features() == m.points[k].id.key()) {
        points[k].normal_impulse = scale * same->normal;
        points[k].tangent_impulse = scale * same->tangent;
      }
    }
  }
}

}  // namespace

Contact& append_contact(const ShapePair& pair, const BodyShapes& shapes, const ContactManifold& m,
                        const MotionState& s, ContactSet& contacts) {
  // Built in place: a contact built apart and then copied in is read back right after being
  // written, and the copy's wide loads stall on the narrower stores that wrote it.
  Contact& c = contacts.append(m.count);
  fill_contact(pair, shapes, m, s, c, contacts.points(c));
  return c;
}

void CollisionDetection::release() {
  candidates_.release();
  manifolds_ = std::vector<ContactManifold>();
  runs_ = std::vector<ContactCursor>();
}

void CollisionDetection::find_contacts(StepContext& ctx) {
  const BodyShapes& shapes = ctx.shapes;
  const WorldShapes& world = ctx.world_start;
  const std::vector<WarmStart>& previous = ctx.warm_starts;
  const double impulse_scale = ctx.warm_start_scale();
  ContactSet& contacts = ctx.contacts;
  contacts.clear();
  const std::span<const ShapePair> pairs = ctx.pairs;
  const double slop = ctx.settings.linear_slop;
  std::vector<std::uint8_t>& touching = ctx.touching_pairs;
  reserve_for(touching, pairs.size());
  touching.assign(pairs.size(), 0);
  const bool threads = !one_thread();
  // On several threads the manifolds' room is held whatever the pairs, so that heap per body does
  // not jump where a scene's pairs cross kParallelPairs.
  if (threads) {
    manifolds_.resize(kCollidedPairsPerBlock);
    runs_.resize(kRunsPerBlock);
  }
  if (!threads || pairs.size() < kParallelPairs) {
    auto old = previous.begin();
    std::array<CentreGap, kGapsAhead> gaps;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      if (i % kGapsAhead == 0) find_centre_gaps(world, pairs.subspan(i), gaps);
      const ShapePair& p = pairs[i];
      const PackedGeometry& a = world.packed(p.first);
      const PackedGeometry& b = world.packed(p.second);
      const ContactManifold m =
          two_discs(a, b) ? collide_circles(a.circle(), b.circle(), gaps[i % kGapsAhead], margin_)
                          : collide(a, b, margin_);
      if (m.count == 0) continue;
      Contact& c = append_contact(p, shapes, m, ctx.start, contacts);
      warm_start_points(old, previous.end(), WarmStart::pair_key(p), impulse_scale, m,
                        contacts.points(c));
      touching[i] = touches(m, slop);
    }
    contacts.fit_room();
    return;
  }
  // On several threads, a block of pairs at a time (so that the manifolds take a fixed room
  // rather than room per pair), in runs: each pair's manifold into its own slot, each run
  // counting the room its contacts take; room made for the runs in the pairs' order, so that
  // the contacts do not depend on the number of threads; then each run's contacts placed one
  // after the other from the run's start, and filled in.
  for (std::size_t first = 0; first < pairs.size(); first += kCollidedPairsPerBlock) {
    const std::size_t size = std::min(kCollidedPairsPerBlock, pairs.size() - first);
    const std::size_t runs = (size + kCollidedPairsPerRun - 1) / kCollidedPairsPerRun;
    // work(first pair, last pair, run) for each run of the block, its pairs counted in the block.
    const auto each_run = [&](const auto& work) {
      for_blocks(runs, 1, false, [&](std::size_t begin, std::size_t end) {
        for (std::size_t r = begin; r < end; ++r) {
          work(r * kCollidedPairsPerRun, std::min(size, (r + 1) * kCollidedPairsPerRun), runs_[r]);
        }
      });
    };
    // Each run counted and then placed from a cursor of its own, written back once: runs side by
    // side share cache lines, which two threads would hand to and fro at every contact.
    each_run([&](std::size_t begin, std::size_t end, ContactCursor& run) {
      ContactCursor room;
      for (std::size_t i = begin; i < end; ++i) {
        if (i + kManifoldsAhead < end) {
          prefetch_for_writing(&manifolds_[i + kManifoldsAhead], sizeof(ContactManifold));
        }
        const ShapePair& p = pairs[first + i];
        manifolds_[i] = collide(world.packed(p.first), world.packed(p.second), margin_);
        if (manifolds_[i].count > 0) room.take(manifolds_[i].count);
      }
      run = room;
    });
    contacts.reserve(std::span(runs_).first(runs));
    each_run([&](std::size_t begin, std::size_t end, const ContactCursor& start) {
      ContactCursor next = start;
      // The slots kContactsAhead contacts on, taken by a cursor of their own.
      ContactCursor ahead = start;
      std::size_t pair_ahead = begin;
      const auto ask_ahead = [&] {
        while (pair_ahead < end && manifolds_[pair_ahead].count == 0) ++pair_ahead;
        if (pair_ahead == end) return;
        contacts.prefetch_for_placing(ahead.take(manifolds_[pair_ahead++].count));
      };
      for (std::size_t k = 0; k < kContactsAhead; ++k) ask_ahead();
      // A search for the run's first pair, then one forward scan (warm_start_points).
      auto old = std::lower_bound(
          previous.begin(), previous.end(), WarmStart::pair_key(pairs[first + begin]),
          [](const WarmStart& w, std::uint64_t pair) { return w.pair() < pair; });
      for (std::size_t i = begin; i < end; ++i) {
        const ContactManifold& m = manifolds_[i];
        if (m.count == 0) continue;
        const ShapePair& p = pairs[first + i];
        const ContactSlot slot = next.take(m.count);
        ask_ahead();
        const std::span<ContactPointState> points = contacts.points(slot);
        fill_contact(p, shapes, m, ctx.start, contacts.place(slot), points);
        warm_start_points(old, previous.end(), WarmStart::pair_key(p), impulse_scale, m, points);
        touching[first + i] = touches(m, slop);
      }
    });
  }
  contacts.fit_room();
}

}  // namespace gp
