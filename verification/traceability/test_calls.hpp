#pragma once
// Which model functions a test case calls, read from its body: what makes a tagged test count as
// testing a model, rather than the tag alone.

#include <set>
#include <string>
#include <vector>

#include "gamephysics/models/registry.hpp"

namespace gp::verification {

/// The SRS ids of the model functions that `body` calls by name (`dd::torque(`, with or without
/// the `gp::` prefix or template arguments), and of the models those call in turn (their
/// registered uses), transitively.
std::set<std::string> models_called(const std::string& body,
                                    const std::vector<models::Registration>& registrations);

}  // namespace gp::verification
