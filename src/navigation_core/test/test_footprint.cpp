// Footprints: the parameter's string form, padding, and the radii planners and inflation use.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "navigation_core/footprint.h"

namespace navigation_core {
namespace {

TEST(Footprint, RectangleRadiiAreHalfTheShortSideAndHalfTheDiagonal) {
  // The Capstone lecture's m_robot footprint for us: 0.24 x 0.18 m about the base.
  const Footprint f = parseFootprint("[[-0.12, -0.09], [-0.12, 0.09], [0.12, 0.09], [0.12, -0.09]]");
  ASSERT_EQ(f.size(), 4u);
  const FootprintRadii r = footprintRadii(f);
  EXPECT_NEAR(r.inscribed, 0.09, 1e-12);
  EXPECT_NEAR(r.circumscribed, std::hypot(0.12, 0.09), 1e-12);
}

TEST(Footprint, InscribedRadiusIsTheNearestEdgeNotTheNearestVertex) {
  // A triangle whose vertices are all 1 m away; its edges pass at 0.5 m.
  const Footprint f = {{1, 0}, {-0.5, std::sqrt(3) / 2}, {-0.5, -std::sqrt(3) / 2}};
  const FootprintRadii r = footprintRadii(f);
  EXPECT_NEAR(r.inscribed, 0.5, 1e-12);
  EXPECT_NEAR(r.circumscribed, 1.0, 1e-12);
}

TEST(Footprint, PaddingMovesVerticesOutAlongEachAxis) {
  const Footprint f = padFootprint({{0.2, -0.1}, {0.0, 0.3}, {-0.2, -0.1}}, 0.01);
  EXPECT_NEAR(f[0].x, 0.21, 1e-12);
  EXPECT_NEAR(f[0].y, -0.11, 1e-12);
  EXPECT_NEAR(f[1].x, 0.0, 1e-12);  // on the axis: only along y
  EXPECT_NEAR(f[1].y, 0.31, 1e-12);
  EXPECT_NEAR(f[2].x, -0.21, 1e-12);
}

TEST(Footprint, RobotRadiusGivesSixteenPointsOnTheCircle) {
  const Footprint f = footprintFromRadius(0.2);
  ASSERT_EQ(f.size(), 16u);
  for (const Point2& p : f) EXPECT_NEAR(std::hypot(p.x, p.y), 0.2, 1e-12);
  const FootprintRadii r = footprintRadii(f);
  EXPECT_NEAR(r.circumscribed, 0.2, 1e-12);
  EXPECT_NEAR(r.inscribed, 0.2 * std::cos(M_PI / 16), 1e-12);  // the chords' midpoints
}

TEST(Footprint, TheStringFormTakesSignsExponentsAndSpaces) {
  const Footprint f = parseFootprint(" [ [+1e-1,-2] ,[3 , 4.5],[ -0.25 ,0 ] ] ");
  ASSERT_EQ(f.size(), 3u);
  EXPECT_DOUBLE_EQ(f[0].x, 0.1);
  EXPECT_DOUBLE_EQ(f[0].y, -2.0);
  EXPECT_DOUBLE_EQ(f[1].y, 4.5);
  EXPECT_DOUBLE_EQ(f[2].x, -0.25);
}

void expectError(const std::string& text, const std::string& part) {
  try {
    parseFootprint(text);
    ADD_FAILURE() << "no error for " << text;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(Footprint, MalformedTextSaysWhatWasExpected) {
  expectError("[[1, 2], [3, 4]]", "at least three points, got 2");
  expectError("[[1, 2], [3, 4], [5]]", "',' between a point's x and y");
  expectError("[[1, 2], [3, 4], [5, x]]", "expected a number at character 22");
  expectError("[[1, 2], [3, 4], [5, 6]", "',' or ']' after a point");
  expectError("[[1, 2], [3, 4], [5, 6]] extra", "nothing after the closing");
  expectError("0.2", "'[' opening the list");
  expectError("[[1, 2], [3, 4], [5, 1e999]]", "expected a number");
}

}  // namespace
}  // namespace navigation_core
