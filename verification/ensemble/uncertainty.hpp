#pragma once
// How far each input of a scene may be off: relative half-widths, the SRS's typical uncertainties
// or a user's JSON file of them (docs/ensembles.md). An ensemble draws each input uniformly from
// [x (1 − u), x (1 + u)].

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace gp::verification {

/// One input field of the scene format with its relative half-width u [1], 0 ≤ u < 1.
struct Spread {
  std::string_view field;   ///< "mass", "moment", "position", ... (the names of the JSON file)
  double relative;          ///< u [1]
  std::string_view source;  ///< where the value comes from (an SRS table row, or the file)
};

/// The fields an uncertainty file may give, in the order of Spreads.
inline constexpr std::string_view kSpreadFields[] = {"mass",        "moment",   "position",
                                                     "angle",       "velocity", "angular_velocity",
                                                     "restitution", "friction", "dt"};

/// Relative half-widths of every field of kSpreadFields, in that order.
struct Spreads {
  std::vector<Spread> fields;
  /// u of `field` (one of kSpreadFields).
  double of(std::string_view field) const;
};

/// The SRS's typical uncertainties: 10% for m, I, p, ϕ, v, ω and C_R (Table:InDataConstraints,
/// column "Uncert."). μ and the step are not in that table (the SRS is frictionless and says
/// nothing of the step); they get the same 10%, stated as ours.
Spreads srs_spreads();

/// The spreads of an uncertainty file: a JSON object whose fields are among kSpreadFields, each
/// a number u with 0 ≤ u < 1; a field left out is not perturbed (u = 0). Throws InputError
/// naming the field, the rule and the value ("(file)" for the file as a whole).
Spreads read_spreads(const std::filesystem::path& file);

}  // namespace gp::verification
