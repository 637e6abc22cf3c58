#pragma once
// The stages a step of a given space runs, each with the SRS ids it implements: a space runs only
// the stages its scene needs.

#include <string>
#include <vector>

namespace gp {

struct PipelineStage {
  std::string name;         ///< e.g. "uniform gravity"
  std::string srs_ids;      ///< e.g. "IM:transMot GD:accelGravity"
  std::string description;  ///< what it does for this scene
};

}  // namespace gp
