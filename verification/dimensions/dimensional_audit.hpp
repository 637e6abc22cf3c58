#pragma once
// Dimensional audit of every SRS equation (TM, GD, DD, IM), computed by the compiler with
// Boost.Units: each side of an equation is a Boost.Units quantity type built from the units the
// SRS declares for its symbols, and two sides agree when their dimension types are the same.

#include <string>
#include <vector>

namespace gp::verification {

/// A symbol of an equation with the unit the check gave it, in the catalogue's ASCII notation.
struct SymbolUnit {
  std::string symbol;  ///< as the SRS names it, e.g. "n"
  std::string unit;    ///< e.g. "m", "m/s^2", "1"
};

/// One equation checked for dimensional consistency.
struct DimensionalCheck {
  std::string id;        ///< SRS id, e.g. "DD:linDisp"
  std::string form;      ///< "as written" (the SRS's units) or "in the code" (the model function)
  std::string equation;  ///< the equation checked, in plain text
  std::vector<SymbolUnit> symbols;  ///< the unit of each symbol used
  std::string lhs_dimension;        ///< dimension of the left side, in SI base units
  std::string rhs_dimension;        ///< dimension of the right side, or "inconsistent sum: ..."
  bool consistent;
};

/// Every check: one "as written" per SRS model, then one "in the code" per model function
/// (code_dimensional_audit).
std::vector<DimensionalCheck> dimensional_audit();

}  // namespace gp::verification
