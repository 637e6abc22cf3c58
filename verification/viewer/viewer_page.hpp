#pragma once
// The viewer page of `gamephysics view`: one self-contained HTML file (its script, style and the
// run's data inline; nothing fetched at view time) that animates a recorded run on a canvas and
// plots its energies and momenta. The page is verification/viewer/page/, compiled in.

#include <optional>
#include <ostream>
#include <string>

#include "engine/space.hpp"
#include "scene/scene.hpp"
#include "verification/oracle/oracle.hpp"
#include "verification/viewer/recording.hpp"

namespace gp::verification {

struct ViewerRun {
  std::string title;        ///< shown as the page's heading: the scene file
  std::string description;  ///< the scene's "description", if any
  const Scene& scene;
  const Space& space;  ///< the space that made `recording` (names, types, masses, shapes)
  const Recording& recording;
  /// The oracle's solution at the same instants, to overlay, and the name of its method.
  const OracleResult* oracle = nullptr;
  std::string oracle_method;
  /// The audit page as the page links to it ("audit.html"); empty: SRS ids are not links.
  std::string audit_page;
};

/// Writes the page of `run` to `out`.
void write_viewer_page(std::ostream& out, const ViewerRun& run);

}  // namespace gp::verification
