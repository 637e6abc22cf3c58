#pragma once
// A pyramid of unit boxes (1 kg, friction 0.6) on a static ground box 80 m wide, for the tests
// that build one in a Space.

#include <string>
#include <vector>

#include "gamephysics/gamephysics.hpp"

namespace gp::test {

/// Adds the ground, its top at y = 0, and `rows` rows of boxes, row r holding rows − r boxes
/// `pitch` [m] apart centre to centre (1: side by side), centred on x = 0 and standing on the row
/// below; the boxes' ids, bottom row first.
inline std::vector<BodyId> add_box_pyramid(Space& space, int rows, double pitch) {
  BodyDef ground;
  ground.name = "ground";
  ground.type = BodyType::Static;
  ground.position = {0.0, -0.5};
  ground.shapes.push_back({Shape::box(80.0, 1.0), 0.0, 0.6});
  space.add_body(ground);
  std::vector<BodyId> boxes;
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < rows - row; ++col) {
      BodyDef box;
      box.name = "box" + std::to_string(boxes.size());
      box.position = {pitch * (col - 0.5 * (rows - row - 1)), 0.5 + row};
      box.shapes.push_back({Shape::box(1.0, 1.0), 0.0, 0.6});
      boxes.push_back(space.add_body(box));
    }
  }
  return boxes;
}

}  // namespace gp::test
