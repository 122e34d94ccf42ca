// Texture coordinates at real Embree hits (renderer/render/embree_scene.h): spheres at known
// points, quad corners, inline mesh "uvs" and OBJ "vt" interpolated at known barycentrics,
// and the texture footprint of a plane seen head-on.
#include "renderer/render/embree_device.h"
#include "renderer/render/embree_scene.h"
#include "renderer/render/texture_footprint.h"
#include "renderer/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace pdrt;

namespace {

class Uv : public ::testing::Test {
 protected:
  fs::path dir() const {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return fs::temp_directory_path() / ("pdrt_uv_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  }
  SceneDesc load(const std::string& objects, const std::string& obj_text = "") {
    fs::create_directories(dir());
    if (!obj_text.empty()) std::ofstream(dir() / "m.obj") << obj_text;
    std::ofstream(dir() / "s.json") << R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "film": {"width": 8, "height": 8}, "materials": {"m": {"type": "diffuse"}}, "objects": [)" +
                                           objects + "]}";
    return load_scene(dir() / "s.json");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir(), ec);
  }
};

SurfaceHit shoot(const EmbreeScene& scene, Vec3 org, Vec3 to) {
  Ray r;
  r.org = org, r.dir = normalize(to - org);
  SurfaceHit h;
  EXPECT_TRUE(scene.intersect(r, &h)) << org.x << " " << org.y << " " << org.z;
  scene.texture_coords(&h, 0);
  return h;
}

}  // namespace

// u = azimuth / 2 pi from +x toward +z, v = polar angle from -y / pi, in object space.
TEST_F(Uv, SphereUvAtKnownPoints) {
  SceneDesc d = load(R"({"type": "sphere", "center": [1, 2, 3], "radius": 2, "material": "m"})");
  EmbreeDevice dev;
  EmbreeScene scene(d, dev);
  const Vec3 c(1, 2, 3);
  struct Case {
    Vec3 dir;
    float u, v;
  };
  const float s = std::sqrt(0.5f);
  for (const Case& k : {Case{{1, 0, 0}, 0.0f, 0.5f}, Case{{0, 0, 1}, 0.25f, 0.5f}, Case{{-1, 0, 0}, 0.5f, 0.5f},
                        Case{{0, 0, -1}, 0.75f, 0.5f}, Case{{s, s, 0}, 0.0f, 0.75f}, Case{{0, -s, s}, 0.25f, 0.25f}}) {
    SurfaceHit h = shoot(scene, c + k.dir * 10, c);
    EXPECT_NEAR(h.u, k.u, 1e-5f) << k.dir.x << " " << k.dir.y << " " << k.dir.z;
    EXPECT_NEAR(h.v, k.v, 1e-5f) << k.dir.x << " " << k.dir.y << " " << k.dir.z;
    // dp/du along +phi (toward +z from +x), length 2 pi r sin(theta); dp/dv toward +y, pi r.
    EXPECT_NEAR(length(h.dpdv), kPi * 2, 1e-3f);
    EXPECT_GT(h.dpdv.y, 0);
  }
  // Near the top pole v -> 1.
  EXPECT_GT(shoot(scene, c + Vec3(0.01f, 10, 0), c).v, 0.99f);
}

// A rotated sphere measures uv in its object space: a quarter turn about +y takes object +x to world -z.
TEST_F(Uv, SphereUvFollowsTheObjectTransform) {
  SceneDesc d = load(R"({"type": "sphere", "radius": 1, "material": "m",
                         "transform": {"rotate": {"axis": [0, 1, 0], "degrees": 90}}})");
  EmbreeDevice dev;
  EmbreeScene scene(d, dev);
  SurfaceHit h = shoot(scene, Vec3(0, 0, -10), Vec3(0.0f));
  EXPECT_NEAR(h.u, 0.0f, 1e-5f);
  EXPECT_NEAR(h.v, 0.5f, 1e-5f);
}

// corner -> (0, 0), corner + edge1 -> (1, 0), corner + edge2 -> (0, 1), linear in between.
TEST_F(Uv, QuadCornersAndInterior) {
  SceneDesc d =
      load(R"({"type": "quad", "corner": [-1, -1, 0], "edge1": [2, 0, 0], "edge2": [0, 4, 0], "material": "m"})");
  EmbreeDevice dev;
  EmbreeScene scene(d, dev);
  for (auto [x, y] : {std::pair{-0.99f, -0.99f}, std::pair{0.99f, -0.99f}, std::pair{0.99f, 2.99f},
                      std::pair{-0.99f, 2.99f}, std::pair{0.2f, 0.5f}}) {
    SurfaceHit h = shoot(scene, Vec3(x, y, 5), Vec3(x, y, 0));
    EXPECT_NEAR(h.u, (x + 1) / 2, 1e-5f);
    EXPECT_NEAR(h.v, (y + 1) / 4, 1e-5f);
    EXPECT_NEAR(h.dpdu.x, 2, 1e-4f);
    EXPECT_NEAR(h.dpdv.y, 4, 1e-4f);
  }
}

// Inline "uvs" interpolate with Embree's barycentrics: at b = (0.2, 0.3, 0.5) of the vertices
// a, b, c, uv = 0.2 uv_a + 0.3 uv_b + 0.5 uv_c.
TEST_F(Uv, InlineMeshUvsInterpolateAtKnownBarycentrics) {
  SceneDesc d = load(R"({"type": "mesh", "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]], "indices": [0, 1, 2],
                         "uvs": [[0.1, 0.2], [0.9, 0.3], [0.4, 1.7]], "material": "m"})");
  EmbreeDevice dev;
  EmbreeScene scene(d, dev);
  const Vec3 p = Vec3(0, 0, 0) * 0.2f + Vec3(2, 0, 0) * 0.3f + Vec3(0, 2, 0) * 0.5f;
  SurfaceHit h = shoot(scene, p + Vec3(0, 0, 3), p);
  EXPECT_NEAR(h.u, 0.2f * 0.1f + 0.3f * 0.9f + 0.5f * 0.4f, 1e-5f);
  EXPECT_NEAR(h.v, 0.2f * 0.2f + 0.3f * 0.3f + 0.5f * 1.7f, 1e-5f);
}

// A mesh without uvs: the barycentrics themselves (vertex 1 -> (1, 0), vertex 2 -> (0, 1)).
TEST_F(Uv, MeshWithoutUvsGetsBarycentrics) {
  SceneDesc d =
      load(R"({"type": "mesh", "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]], "indices": [0, 1, 2], "material": "m"})");
  EmbreeDevice dev;
  EmbreeScene scene(d, dev);
  SurfaceHit h = shoot(scene, Vec3(0.6f, 1.0f, 3), Vec3(0.6f, 1.0f, 0));
  EXPECT_NEAR(h.u, 0.3f, 1e-5f);
  EXPECT_NEAR(h.v, 0.5f, 1e-5f);
}

// OBJ "vt" through tinyobjloader, per face corner (the same position with two vt splits).
TEST_F(Uv, ObjTexcoordsInterpolateAtKnownBarycentrics) {
  SceneDesc d = load(R"({"type": "obj", "file": "m.obj", "material": "m"})",
                     "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\nvt 0.1 0.2\nvt 0.9 0.3\nvt 0.4 1.7\nvt 0.5 0.5\nvt 0.7 0.7\n"
                     "f 1/1 2/2 3/3\nf 2/4 4/5 3/5\n");
  EmbreeDevice dev;
  EmbreeScene scene(d, dev);
  const Vec3 p = Vec3(2, 0, 0) * 0.3f + Vec3(0, 2, 0) * 0.5f;
  SurfaceHit h = shoot(scene, p + Vec3(0, 0, 3), p);
  EXPECT_NEAR(h.u, 0.2f * 0.1f + 0.3f * 0.9f + 0.5f * 0.4f, 1e-5f);
  EXPECT_NEAR(h.v, 0.2f * 0.2f + 0.3f * 0.3f + 0.5f * 1.7f, 1e-5f);
  // The second face's corners at (2,0,0) and (0,2,0) use vt 4 and 5, not the first face's.
  SurfaceHit g = shoot(scene, Vec3(1.9f, 1.9f, 3), Vec3(1.9f, 1.9f, 0));
  EXPECT_GT(g.u, 0.5f);
  EXPECT_LT(g.u, 0.7f + 1e-5f);
}

// Head-on view of a plane with uv = position: one pixel spans 2 tan(vfov/2) dist / height in
// u, scaled by max(1/8, 1/sqrt(spp)) (pbrt-v4 Camera::Approximate_dp_dxy).
TEST_F(Uv, FootprintOfAPlaneSeenHeadOn) {
  SceneDesc d =
      load(R"({"type": "quad", "corner": [-10, -10, 0], "edge1": [20, 0, 0], "edge2": [0, 20, 0], "material": "m"})");
  EmbreeDevice dev;
  EmbreeScene scene(d, dev);
  SurfaceHit h = shoot(scene, Vec3(0, 0, 5), Vec3(0.0f));
  CameraDesc cam;
  cam.position = {0, 0, 5}, cam.look_at = {0, 0, 0}, cam.vfov_deg = 90;
  const TextureCoords one = TextureFootprint(cam, 100, 100, 1).at(h),
                      sixteen = TextureFootprint(cam, 100, 100, 16).at(h);
  const float pixel_u = 2 * 1 * 5 / 100.0f / 20;  // world width of a pixel at distance 5, in u (20 units per u)
  EXPECT_NEAR(one.dudx, pixel_u, 1e-4f * pixel_u * 100);
  EXPECT_NEAR(one.dvdy, pixel_u, 1e-4f * pixel_u * 100);
  EXPECT_NEAR(one.dvdx, 0, 1e-6f);
  EXPECT_NEAR(sixteen.dudx, pixel_u / 4, 1e-2f * pixel_u);
}
