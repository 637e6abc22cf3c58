#include "verification/ensemble/uncertainty.hpp"

#include <fstream>
#include <sstream>

#include "scene/input_error.hpp"
#include "scene/json_document.hpp"
#include "scene/json_fields.hpp"

namespace gp::verification {

namespace {

constexpr std::string_view kSrsTable = "SRS Table:InDataConstraints, Uncert. 10%";
constexpr std::string_view kOurs = "not in the SRS; 10% as for its other inputs";
constexpr std::string_view kFile = "uncertainty file";

}  // namespace

double Spreads::of(std::string_view field) const {
  for (const Spread& s : fields) {
    if (s.field == field) return s.relative;
  }
  return 0.0;
}

Spreads srs_spreads() {
  Spreads s;
  for (std::string_view field : kSpreadFields) {
    const bool in_srs = field != "friction" && field != "dt";
    s.fields.push_back({field, 0.1, in_srs ? kSrsTable : kOurs});
  }
  return s;
}

Spreads read_spreads(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError("(file)", "must be a readable file", file.string());
  std::ostringstream text;
  text << in.rdbuf();
  const nlohmann::json document = parse_json_document(text.str());
  const JsonObject object(document, "");
  object.allow_only({kSpreadFields[0], kSpreadFields[1], kSpreadFields[2], kSpreadFields[3],
                     kSpreadFields[4], kSpreadFields[5], kSpreadFields[6], kSpreadFields[7],
                     kSpreadFields[8]});
  Spreads s;
  for (std::string_view field : kSpreadFields) {
    const double u = object.get_or<double>(field, 0.0);
    if (!(u >= 0.0 && u < 1.0)) {
      throw InputError(object.path(field), "must be a relative spread u with 0 <= u < 1",
                       describe(u));
    }
    s.fields.push_back({field, u, kFile});
  }
  return s;
}

}  // namespace gp::verification
