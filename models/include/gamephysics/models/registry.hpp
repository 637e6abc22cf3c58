#pragma once
// Each model function registers its SRS id, its qualified name, its file and the SRS ids of the
// models it calls, so that the traceability tool derives the code's edges from the code itself.

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace gp::models {

/// One model function as it declares itself.
struct Registration {
  std::string id;                 ///< SRS id as the SRS spells it, e.g. "DD:ctrOfMass".
  std::string function;           ///< Qualified C++ name, e.g. "gp::dd::center_of_mass".
  std::string file;               ///< Header that defines it, relative to the repository root.
  std::vector<std::string> uses;  ///< SRS ids of the models the function calls.
};

/// Adds a registration to the process-wide list; returns true so it can initialise a variable.
bool register_model(Registration registration);

/// Every registration, sorted by SRS id. Includes every header of gamephysics/models.hpp.
const std::vector<Registration>& registrations();

}  // namespace gp::models

// Registers FUNCTION (unqualified, in the enclosing namespace NS) as the implementation of ID.
// The variable is inline so the registration happens once however many files include the header.
#define GP_REGISTER_MODEL(ID, NS, FUNCTION, ...)                          \
  inline const bool registered_##FUNCTION = ::gp::models::register_model( \
      {ID, "gp::" #NS "::" #FUNCTION, __FILE__, std::vector<std::string>{__VA_ARGS__}})
