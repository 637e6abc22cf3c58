#include "verification/ensemble/sampler.hpp"

#include <boost/random/sobol.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gp::verification {

namespace {

// SplitMix64's finaliser: a bijective mix, so distinct counters give independent-looking words.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A double in [0, 1) from the top 53 bits of a word.
double unit(std::uint64_t word) {
  return static_cast<double>(word >> 11) * 0x1.0p-53;
}

}  // namespace

std::string_view sampler_name(Sampler sampler) {
  return sampler == Sampler::Sobol ? "sobol" : "random";
}

std::optional<Sampler> sampler_from_name(std::string_view name) {
  if (name == "sobol") return Sampler::Sobol;
  if (name == "random") return Sampler::Random;
  return std::nullopt;
}

std::size_t sobol_max_dimension() {
  return boost::random::default_sobol_table::max_dimension;
}

std::vector<double> unit_point(Sampler sampler, std::uint64_t seed, std::size_t dimension,
                               std::uint64_t index) {
  std::vector<double> u(dimension);
  if (dimension == 0) return u;
  const std::uint64_t stream = mix(seed);
  if (sampler == Sampler::Random) {
    for (std::size_t k = 0; k < dimension; ++k)
      u[k] = unit(mix(stream ^ mix(index * dimension + k)));
    return u;
  }
  if (dimension > sobol_max_dimension()) {
    throw std::invalid_argument("the Sobol sequence has at most " +
                                std::to_string(sobol_max_dimension()) + " dimensions, the scene " +
                                std::to_string(dimension) +
                                " perturbed inputs (--sampler random has no such limit)");
  }
  boost::random::sobol sequence(dimension);
  sequence.discard(index * dimension);
  for (std::size_t k = 0; k < dimension; ++k) {
    // The engine gives 64-bit words; the seeded shift (a Cranley–Patterson rotation) keeps the
    // sequence's uniformity and makes seeds give different, equally good point sets.
    const double x = unit(sequence()) + unit(mix(stream ^ mix(k)));
    u[k] = x - std::floor(x);
  }
  return u;
}

}  // namespace gp::verification
