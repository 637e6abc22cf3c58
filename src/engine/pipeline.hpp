#pragma once
// The stages a step of a given space runs, each with the SRS ids it implements: a space runs only
// the stages its scene needs.

#include <cstdint>
#include <string>
#include <vector>

namespace gp {

struct PipelineStage {
  std::string name;         ///< e.g. "narrowphase: contact manifolds"
  std::string srs_ids;      ///< e.g. "FR:Determine-Collisions A:collisionType"
  std::string description;  ///< what it does for this scene
  std::string passes;       ///< "local step", "sub-steps" or both: how the step runs it
  bool needed = true;       ///< false: this scene does not need it, and the step skips it
  std::uint64_t runs = 0;   ///< how many times the steps so far ran it
  /// s: the wall time it took over those runs, threads included, while Space::time_stages is on
  double seconds = 0.0;
};

}  // namespace gp
