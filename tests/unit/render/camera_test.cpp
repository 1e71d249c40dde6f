#include "vox/render/camera.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

namespace vox::render {
namespace {

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-9) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Camera, standardViewsPutTheEyeOnTheNamedSide) {
  struct Case {
    StandardView view;
    glm::dvec3 dir;
  };
  const double s = 1.0 / std::sqrt(3.0);
  for (const Case& c : {Case{StandardView::kPosX, {1, 0, 0}}, Case{StandardView::kNegX, {-1, 0, 0}},
                        Case{StandardView::kPosY, {0, 1, 0}}, Case{StandardView::kNegY, {0, -1, 0}},
                        Case{StandardView::kPosZ, {0, 0, 1}}, Case{StandardView::kNegZ, {0, 0, -1}},
                        Case{StandardView::kIso, {s, s, s}}}) {
    Camera cam;
    cam.setStandardView(c.view);
    expectNear(cam.eyeDirection(), c.dir);
  }
}

TEST(Camera, defaultViewIsTheThesisScreenXRightYUpLookingDownMinusZ) {
  Camera cam;  // yaw = pitch = 0
  expectNear(cam.rightAxis(), {1, 0, 0});
  expectNear(cam.upAxis(), {0, 1, 0});
  expectNear(cam.eyeDirection(), {0, 0, 1});
}

TEST(Camera, axesAreOrthonormalAndRightHandedEvenLookingStraightDown) {
  for (double yaw : {-170.0, -45.0, 0.0, 30.0, 135.0}) {
    for (double pitch : {-90.0, -35.0, 0.0, 20.0, 90.0}) {
      Camera cam;
      cam.yaw_deg = yaw;
      cam.pitch_deg = pitch;
      const glm::dvec3 r = cam.rightAxis(), u = cam.upAxis(), b = cam.eyeDirection();
      EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
      EXPECT_NEAR(glm::length(u), 1.0, 1e-12);
      EXPECT_NEAR(glm::dot(r, u), 0.0, 1e-12);
      expectNear(glm::cross(r, u), b, 1e-12);
    }
  }
}

TEST(Camera, viewMatrixPutsEyeAtOriginAndTargetStraightAhead) {
  Camera cam;
  cam.target = {10, 20, 30};
  cam.distance = 50;
  cam.yaw_deg = 37;
  cam.pitch_deg = -61;
  const glm::dmat4 v = cam.viewMatrix();
  expectNear(glm::dvec3(v * glm::dvec4(cam.eyePosition(), 1.0)), {0, 0, 0}, 1e-9);
  expectNear(glm::dvec3(v * glm::dvec4(cam.target, 1.0)), {0, 0, -50}, 1e-9);
  expectNear(glm::dvec3(v * glm::dvec4(cam.rightAxis(), 0.0)), {1, 0, 0}, 1e-12);
  expectNear(glm::dvec3(v * glm::dvec4(cam.upAxis(), 0.0)), {0, 1, 0}, 1e-12);
}

// Largest |NDC x| or |NDC y| over the box corners; all corners must also lie between the near and far planes.
double maxNdc(const Camera& cam, const Box3& box, double aspect) {
  const glm::dmat4 vp = cam.viewProjection(aspect, box);
  double m = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                       (i & 4) ? box.max.z : box.min.z);
    const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
    EXPECT_GT(c.w, 0.0);
    EXPECT_LE(std::abs(c.z / c.w), 1.0) << "corner " << i << " clipped by near/far";
    m = std::max({m, std::abs(c.x / c.w), std::abs(c.y / c.w)});
  }
  return m;
}

TEST(Camera, fitToBoxContainsTheBoxAndFillsTheView) {
  const Box3 box{{3, -2, 10}, {203, 48, 90}};
  for (Projection proj : {Projection::kPerspective, Projection::kOrthographic}) {
    for (double aspect : {0.5, 1.0, 16.0 / 9.0}) {
      for (double yaw : {0.0, 30.0, 90.0, -135.0}) {
        for (double pitch : {-90.0, -20.0, 0.0, 45.0}) {
          Camera cam;
          cam.projection = proj;
          cam.yaw_deg = yaw;
          cam.pitch_deg = pitch;
          cam.fitToBox(box, aspect, 1.0);
          const double m = maxNdc(cam, box, aspect);
          EXPECT_LE(m, 1.0 + 1e-9) << "yaw " << yaw << " pitch " << pitch;
          EXPECT_GE(m, 1.0 - 1e-6) << "not tight: yaw " << yaw << " pitch " << pitch;
          expectNear(cam.target, box.centre());
        }
      }
    }
  }
}

TEST(Camera, fitMarginLeavesRoom) {
  const Box3 box{{0, 0, 0}, {64, 64, 64}};
  Camera cam;
  cam.projection = Projection::kOrthographic;
  cam.yaw_deg = 30;
  cam.fitToBox(box, 1.0, 1.25);
  EXPECT_NEAR(maxNdc(cam, box, 1.0), 0.8, 1e-9);
}

TEST(Camera, orbitWrapsYawAndClampsPitch) {
  Camera cam;
  cam.orbit(190, 100);
  EXPECT_NEAR(cam.yaw_deg, -170, 1e-12);
  EXPECT_EQ(cam.pitch_deg, 90);
  cam.orbit(-20, -250);
  EXPECT_NEAR(cam.yaw_deg, 170, 1e-12);
  EXPECT_EQ(cam.pitch_deg, -90);
}

TEST(Camera, panMovesTargetInTheViewPlaneByTheDraggedPixels) {
  Camera cam;
  cam.yaw_deg = 40;
  cam.pitch_deg = 10;
  cam.distance = 100;
  const glm::dvec3 before = cam.target;
  const double units_per_px = 2 * cam.halfHeightAtTarget() / 500.0;
  cam.pan(10, -20, 500);  // right and up
  const glm::dvec3 moved = cam.target - before;
  EXPECT_NEAR(glm::dot(moved, cam.eyeDirection()), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(moved, cam.rightAxis()), -10 * units_per_px, 1e-12);  // the model follows the cursor
  EXPECT_NEAR(glm::dot(moved, cam.upAxis()), -20 * units_per_px, 1e-12);
}

TEST(Camera, zoomDividesDistanceAndOrthoExtentFollows) {
  Camera cam;
  cam.distance = 100;
  const double h = cam.halfHeightAtTarget();
  cam.zoom(2);
  EXPECT_DOUBLE_EQ(cam.distance, 50);
  EXPECT_DOUBLE_EQ(cam.halfHeightAtTarget(), h / 2);
  cam.zoom(0);  // ignored
  cam.zoom(-3);
  EXPECT_DOUBLE_EQ(cam.distance, 50);
}

TEST(Camera, pixelsPerVoxelMatchesTheProjectionMatrix) {
  for (Projection proj : {Projection::kPerspective, Projection::kOrthographic}) {
    Camera cam;
    cam.projection = proj;
    cam.distance = 300;
    const double h = 720, depth = 280;
    const glm::dmat4 p = cam.projectionMatrix(16.0 / 9.0, 10, 1000);
    // A unit segment along view Y at this depth spans p[1][1] / w NDC units, NDC 2 = h pixels.
    const double w = proj == Projection::kPerspective ? depth : 1.0;
    EXPECT_NEAR(pixelsPerVoxel(cam, h, depth), p[1][1] / w * h / 2, 1e-9);
  }
  Camera ortho;
  ortho.projection = Projection::kOrthographic;
  ortho.distance = 100;
  EXPECT_NEAR(pixelsPerVoxel(ortho, 600, 0), 600 / (2 * ortho.halfHeightAtTarget()), 1e-12);
}

}  // namespace
}  // namespace vox::render
