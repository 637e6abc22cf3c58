#pragma once
// What a Space is made of, behind its public header: the step context its stages share, the
// runner of the stage table, and the bodies' names, types and removal marks.

#include <vector>

#include "engine/body_names.hpp"
#include "engine/space.hpp"
#include "engine/step/step_context.hpp"
#include "engine/step/step_runner.hpp"

namespace gp {

struct Space::Impl {
  explicit Impl(const Settings& settings) : context(settings), runner(settings) {}

  StepContext context;
  StepRunner runner;
  BodyNames names;
  std::vector<BodyType> types;
  std::vector<char> removed;
  std::size_t bodies_with_shapes = 0;
  bool dynamic_with_shapes = false;  ///< a dynamic body has a shape
};

/// For the engine's own tests and the verifier: the step context and runner of a space.
struct SpaceInternals {
  static const StepContext& context(const Space& space) { return space.impl_->context; }
  static const StepRunner& runner(const Space& space) { return space.impl_->runner; }
};

}  // namespace gp
