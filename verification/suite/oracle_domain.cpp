#include "verification/suite/oracle_domain.hpp"

#include <algorithm>
#include <utility>

#include "verification/suite/oracle_trajectory.hpp"

namespace gp::verification {

namespace {

// The declared list: a shipped scene or hard case ("hard case …", hard_cases.cpp) here is never
// run by the oracle in `verify`; every other one must stay in the domain.
constexpr std::pair<std::string_view, std::string_view> kOutside[] = {
    {"pyramid20",
     "210 boxes resting on each other: at each event the oracle's Lemke's method works on about "
     "1,700 unknowns, and every right-hand side solves a dense system of about 840 forces; far "
     "too slow (pyramid6, 21 boxes, takes 0.5 s a simulated second)"},
    {"rain1000",
     "1000 discs falling into a pile: the event-driven oracle watches about 500,000 pairs of "
     "hulls (every two discs) at every stop of its root finder and resolves the pile one event "
     "at a time (settle50, 50 discs, passes 10,000 events by t = 1.58 s); its time-stepping "
     "tests those pairs at every step and solves the heap as one dense LCP of about 3,000 "
     "contacts (settle50's takes 7 s of CPU for 3 s); not tried"},
    {"hard case cradle, balls touching",
     "five touching balls struck at once: the oracle resolves simultaneous impacts by Newton's "
     "law at every contact at once (one LCP), which does not pass the velocity along ball by "
     "ball as the closed form and the engine's sequential impacts do (measured 1.2 m/s apart "
     "after the impact); the case checks the sequential model, the closed form is its "
     "reference"},
};

// The chaotic piles: their trajectories are never compared with a reference; the pile section
// (pile.cpp) compares what is well posed with the oracle's time-stepping reference.
constexpr std::pair<std::string_view, std::string_view> kChaoticPiles[] = {
    {"settle50",
     "50 discs settling into a heap: which disc ends where is chaotic (the oracle's own "
     "time-stepping at 0.5 and 0.25 ms ends in different packings, heights up to 0.22 m apart), "
     "so trajectories are not compared; the energy over time, the time to settle and the settled "
     "profile are, against the oracle's time-stepping (section 'chaotic pile')"},
};

template <std::size_t N>
std::optional<std::string_view> reason_in(
    const std::pair<std::string_view, std::string_view> (&list)[N], std::string_view name) {
  for (const auto& [scene, reason] : list) {
    if (scene == name) return reason;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string_view> chaotic_pile(std::string_view name) {
  return reason_in(kChaoticPiles, name);
}

std::optional<std::string_view> outside_oracle_domain(std::string_view name) {
  return reason_in(kOutside, name);
}

std::optional<std::string_view> no_oracle_trajectory(std::string_view name) {
  if (const auto reason = outside_oracle_domain(name)) return reason;
  return chaotic_pile(name);
}

OracleOptions reference_options(const Scene& scene) {
  OracleOptions options;
  options.rtol = options.atol = scene.settings.G ? 1e-14 : 1e-12;
  return options;
}

void cannot_run(CheckList& list, const std::string& name, const std::string& who,
                const std::string& what) {
  list.check(name + ": " + who, "", who + " failed: " + what,
             "runs every scene not declared outside its domain", false);
}

namespace {

// How much tighter the tolerances of the solution that estimates a reference's own error are.
constexpr double kEstimateTightening = 100.0;

// The row of a reference's own error estimate and cost.
void report_estimate(CheckList& list, const std::string& name, const OracleOptions& options,
                     const OracleReference& r) {
  list.within(name + ": oracle's own error, rtol = atol = " + figure(options.rtol) + " against " +
                  figure(options.rtol / kEstimateTightening),
              "NFR:Correctness",
              "position " + figure(r.estimate.position) + " m, velocity " +
                  figure(r.estimate.velocity) + " m/s, relative " + figure(r.relative_estimate) +
                  "; CPU " + figure(r.cpu_per_simulated_second) + " s per simulated second",
              "relative estimate ≤ 1e-9", {{r.relative_estimate, 1e-9}},
              "the accuracy a reference solution promises (issue 14), on every scene alike");
}

}  // namespace

std::optional<OracleReference> oracle_reference(CheckList& list, const std::string& name,
                                                const Scene& scene, std::span<const double> times,
                                                const OracleOptions& options) {
  if (const auto reason = outside_oracle_domain(name)) {
    list.report(name + ": oracle", "",
                "declared outside the oracle's domain: " + std::string(*reason));
    return std::nullopt;
  }
  if (const auto reason = chaotic_pile(name)) {
    list.report(name + ": oracle", "",
                "a chaotic pile, compared on what is well posed: " + std::string(*reason));
    return std::nullopt;
  }
  OracleReference r;
  OracleOptions tighter = options;
  tighter.rtol /= kEstimateTightening;
  tighter.atol /= kEstimateTightening;
  try {
    r.trajectory = run_oracle_trajectory(scene, times, options);
    r.estimate = compare(r.trajectory, run_oracle_trajectory(scene, times, tighter));
  } catch (const OracleDomainError& e) {
    cannot_run(list, name, "oracle (" + std::string(oracle_method_name(options.method)) + ")",
               std::string("left the oracle's domain, not on the declared list: ") + e.what());
    return std::nullopt;
  }
  const Scales scale = scales_of(r.trajectory);
  r.relative_estimate = std::max(r.estimate.position / std::max(scale.position, 1.0),
                                 r.estimate.velocity / std::max(scale.velocity, 1.0));
  r.cpu_per_simulated_second =
      r.trajectory.cpu_seconds / std::max(times.empty() ? 0.0 : times.back(), 1e-9);
  report_estimate(list, name, options, r);
  return r;
}

std::optional<OracleReference> OracleReferences::find(CheckList& list, const std::string& name,
                                                      const Scene& scene,
                                                      std::span<const double> times,
                                                      const OracleOptions& options) {
  for (const Entry& e : entries_) {
    if (e.name == name && e.options == options && std::ranges::equal(e.times, times)) {
      report_estimate(list, name, options, e.reference);
      return e.reference;
    }
  }
  auto reference = oracle_reference(list, name, scene, times, options);
  if (reference) {
    entries_.push_back(
        {name, std::vector<double>(times.begin(), times.end()), options, *reference});
  }
  return reference;
}

}  // namespace gp::verification
