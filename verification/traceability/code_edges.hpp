#pragma once
// The edges between models that the code itself shows: the model functions each model's file
// calls, found by reading the file, so that a registration cannot claim what the code does not do.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "gamephysics/models/registry.hpp"

namespace gp::verification {

/// For each registered SRS id, the SRS ids of the other model functions its file calls
/// (gp::tm::, gp::gd::, gp::dd::, gp::im:: calls), sorted.
std::map<std::string, std::vector<std::string>> called_models(
    const std::filesystem::path& root, const std::vector<models::Registration>& registrations);

}  // namespace gp::verification
