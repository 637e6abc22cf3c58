#include "engine/collision/hull.hpp"

#include <algorithm>
#include <array>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gp {

Hull hull_of(const PolygonView& polygon) {
  return {polygon.vertices, polygon.normals, 0.0};
}

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

#if defined(__SSE2__)

// max_separation_of for four edges against four vertices (a box against a box), two edges at a
// time, one in each lane of a 128-bit register: each lane runs the scalar loop's operations in
// its order, the vertices one after the other, so the separations are the same to the bit. 122
// instructions a call against the scalar loop's 159 (callgrind, pyramid20).
EdgeSeparation max_separation_of_boxes(std::span<const Vec2, 4> vertices,
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
  EdgeSeparation best{0, -std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < 4; ++i) {
    if (separations[i] > best.separation) best = {static_cast<int>(i), separations[i]};
  }
  return best;
}

#endif

}  // namespace

EdgeSeparation max_separation(const Hull& reference, const Hull& other) {
  constexpr std::size_t kBox = 4;
  if (reference.count() == kBox && other.count() == kBox) {
#if defined(__SSE2__)
    return max_separation_of_boxes(reference.vertices.first<kBox>(),
                                   reference.normals.first<kBox>(), other.vertices.first<kBox>());
#else
    return max_separation_of(reference.vertices.first<kBox>(), reference.normals.first<kBox>(),
                             other.vertices.first<kBox>());
#endif
  }
  return max_separation_of(reference.vertices, reference.normals, other.vertices);
}

int incident_edge(const Hull& hull, const Vec2& normal) {
  int best = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < hull.count(); ++i) {
    const double alignment = normal.dot(hull.normals[i]);
    if (alignment < lowest) {
      lowest = alignment;
      best = i;
    }
  }
  return best;
}

}  // namespace gp
