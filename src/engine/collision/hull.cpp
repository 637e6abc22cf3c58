#include "engine/collision/hull.hpp"

#include <algorithm>
#include <array>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if GP_LANES_AVX2
#include "engine/avx2_lanes.hpp"
#endif

namespace gp {

SegmentOutline::SegmentOutline(const Segment& segment)
    : vertices_{segment.a, segment.b}, radius_(segment.radius) {
  const Vec2 edge = segment.b - segment.a;
  const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
  normals_ = {normal, -normal};
}

namespace {

// max_separation over spans of `ReferenceCount` and `OtherCount` vertices: with a box's four
// known when compiled, the loops unroll, and a box against a box takes a third fewer
// instructions (callgrind, pyramid20).
template <std::size_t ReferenceCount, std::size_t OtherCount>
EdgeSeparation max_separation_of(std::span<const Vec2, ReferenceCount> vertices,
                                 std::span<const Vec2, ReferenceCount> normals,
                                 std::span<const Vec2, OtherCount> other) {
  EdgeSeparation best{0, -std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2& normal = normals[i];
    const Vec2& origin = vertices[i];
    double separation = std::numeric_limits<double>::infinity();
    for (const Vec2& v : other) separation = std::min(separation, normal.dot(v - origin));
    if (separation > best.separation) best = {static_cast<int>(i), separation};
  }
  return best;
}

// The edge of the greatest of a box's four separations, the first on a tie: the scalar loop's
// choice.
EdgeSeparation best_of(const std::array<double, 4>& separations) {
  EdgeSeparation best{0, -std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < 4; ++i) {
    if (separations[i] > best.separation) best = {static_cast<int>(i), separations[i]};
  }
  return best;
}

#if defined(__SSE2__)

// max_separation_of for four edges against four vertices (a box against a box), two edges at a
// time, one in each lane of a 128-bit register: each lane runs the scalar loop's operations in
// its order, the vertices one after the other, so the separations are the same to the bit. 122
// instructions a call against the scalar loop's 159 (callgrind, pyramid20).
EdgeSeparation two_edges_at_a_time(std::span<const Vec2, 4> vertices,
                                   std::span<const Vec2, 4> normals,
                                   std::span<const Vec2, 4> other) {
  __m128d other_x[4];  // a plain array: std::array would drop the type's alignment attribute
  __m128d other_y[4];
  for (std::size_t j = 0; j < 4; ++j) {
    const __m128d v = _mm_loadu_pd(other[j].data());
    other_x[j] = _mm_unpacklo_pd(v, v);
    other_y[j] = _mm_unpackhi_pd(v, v);
  }
  alignas(16) std::array<double, 4> separations;
  for (std::size_t i = 0; i < 4; i += 2) {
    const __m128d origin_i = _mm_loadu_pd(vertices[i].data());
    const __m128d origin_k = _mm_loadu_pd(vertices[i + 1].data());
    const __m128d normal_i = _mm_loadu_pd(normals[i].data());
    const __m128d normal_k = _mm_loadu_pd(normals[i + 1].data());
    const __m128d origin_x = _mm_unpacklo_pd(origin_i, origin_k);
    const __m128d origin_y = _mm_unpackhi_pd(origin_i, origin_k);
    const __m128d normal_x = _mm_unpacklo_pd(normal_i, normal_k);
    const __m128d normal_y = _mm_unpackhi_pd(normal_i, normal_k);
    __m128d separation = _mm_set1_pd(std::numeric_limits<double>::infinity());
    for (std::size_t j = 0; j < 4; ++j) {
      // normal · (v − origin), then std::min(separation, it): it where it is less, else
      // separation, as _mm_min_pd(it, separation) gives.
      const __m128d along = _mm_add_pd(_mm_mul_pd(normal_x, _mm_sub_pd(other_x[j], origin_x)),
                                       _mm_mul_pd(normal_y, _mm_sub_pd(other_y[j], origin_y)));
      separation = _mm_min_pd(along, separation);
    }
    _mm_store_pd(separations.data() + i, separation);
  }
  return best_of(separations);
}

#endif

#if GP_LANES_AVX2

// Four consecutive points from `first` into their x and y lanes.
[[gnu::target("avx2"), gnu::always_inline]] inline void split_lanes(const Vec2* first, __m256d& x,
                                                                    __m256d& y) {
  split_xy(_mm256_loadu_pd(first[0].data()), _mm256_loadu_pd(first[2].data()), x, y);
}

// The separations along each of the four edges (vertices, normals) of `other`'s four vertices,
// the edges in the lanes of a 256-bit register, each lane with the SSE2 lanes' operations in their
// order; compiled for AVX2 alone, which has no fused multiply-add to round differently. Inlined
// into both of its callers.
[[gnu::target("avx2"), gnu::always_inline]] inline __m256d edge_separations(
    std::span<const Vec2, 4> vertices, std::span<const Vec2, 4> normals,
    std::span<const Vec2, 4> other) {
  __m256d origin_x, origin_y, normal_x, normal_y;
  split_lanes(vertices.data(), origin_x, origin_y);
  split_lanes(normals.data(), normal_x, normal_y);
  __m256d separation = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  for (std::size_t j = 0; j < 4; ++j) {
    const __m256d x = _mm256_broadcast_sd(&other[j].x());
    const __m256d y = _mm256_broadcast_sd(&other[j].y());
    const __m256d along = _mm256_add_pd(_mm256_mul_pd(normal_x, _mm256_sub_pd(x, origin_x)),
                                        _mm256_mul_pd(normal_y, _mm256_sub_pd(y, origin_y)));
    separation = _mm256_min_pd(along, separation);
  }
  return separation;
}

// The same as two_edges_at_a_time, the four edges at once. With max_separation's own, 85
// instructions a call against 122 (callgrind, pyramid20).
[[gnu::target("avx2")]] EdgeSeparation four_edges_at_once(std::span<const Vec2, 4> vertices,
                                                          std::span<const Vec2, 4> normals,
                                                          std::span<const Vec2, 4> other) {
  alignas(32) std::array<double, 4> separations;
  _mm256_store_pd(separations.data(), edge_separations(vertices, normals, other));
  return best_of(separations);
}

// Both boxes' edges four at once, in one call: a box pile's narrowphase asks for both at every
// pair of boxes.
[[gnu::target("avx2")]] BoxSeparations four_edges_both_ways(const BoxHull& a, const BoxHull& b) {
  alignas(32) std::array<double, 4> of_a;
  alignas(32) std::array<double, 4> of_b;
  _mm256_store_pd(of_a.data(), edge_separations(a.vertices, a.normals, b.vertices));
  _mm256_store_pd(of_b.data(), edge_separations(b.vertices, b.normals, a.vertices));
  return {best_of(of_a), best_of(of_b)};
}

#endif

}  // namespace

const char* box_lanes_name(Lanes lanes) {
  switch (lanes) {
    case Lanes::kFour:
      return "its edges four at a time (AVX2)";
    case Lanes::kTwo:
      return "its edges two at a time (SSE2)";
    case Lanes::kOne:
      break;
  }
  return "its edges one at a time";
}

EdgeSeparation max_separation_of_boxes(std::span<const Vec2, 4> vertices,
                                       std::span<const Vec2, 4> normals,
                                       std::span<const Vec2, 4> other, Lanes lanes) {
  switch (lanes) {
#if GP_LANES_AVX2
    case Lanes::kFour:
      return four_edges_at_once(vertices, normals, other);
#endif
#if defined(__SSE2__)
    case Lanes::kTwo:
      return two_edges_at_a_time(vertices, normals, other);
#endif
    default:
      return max_separation_of(vertices, normals, other);
  }
}

EdgeSeparation max_separation(const Hull& reference, const Hull& other) {
  constexpr std::size_t kBox = 4;
  if (reference.count() == kBox && other.count() == kBox) {
    return max_separation_of_boxes(reference.vertices.first<kBox>(),
                                   reference.normals.first<kBox>(), other.vertices.first<kBox>(),
                                   widest_lanes());
  }
  return max_separation_of(reference.vertices, reference.normals, other.vertices);
}

BoxSeparations box_separations(const BoxHull& a, const BoxHull& b) {
  const Lanes lanes = widest_lanes();
#if GP_LANES_AVX2
  if (lanes == Lanes::kFour) return four_edges_both_ways(a, b);
#endif
  return {max_separation_of_boxes(a.vertices, a.normals, b.vertices, lanes),
          max_separation_of_boxes(b.vertices, b.normals, a.vertices, lanes)};
}

}  // namespace gp
