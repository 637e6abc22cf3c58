#pragma once
// Points of the unit hypercube [0, 1)^d, one per sample: sample i's point depends on i, d and the
// seed alone, so that any process can draw any sample (threads, MPI ranks, a resumed run).

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace gp::verification {

enum class Sampler {
  Sobol,   ///< Boost.Random's Sobol sequence, shifted modulo 1 by a seeded offset per dimension
  Random,  ///< independent uniform numbers from a counter-based hash of (seed, i, k)
};

/// "sobol", "random".
std::string_view sampler_name(Sampler sampler);
std::optional<Sampler> sampler_from_name(std::string_view name);

/// Most dimensions the Sobol sequence supports (Boost's direction numbers).
std::size_t sobol_max_dimension();

/// The point of sample `index` in [0, 1)^dimension. Throws std::invalid_argument when Sobol is
/// asked for more than sobol_max_dimension() dimensions.
std::vector<double> unit_point(Sampler sampler, std::uint64_t seed, std::size_t dimension,
                               std::uint64_t index);

}  // namespace gp::verification
