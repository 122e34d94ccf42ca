// Object instancing (SceneDesc::prototypes / instances, traced as Embree instances): an
// instanced scene renders the image of the same scene with the shapes copied under the
// instances' transforms, static and moving, textured and smooth-shaded, near and far from the
// origin and at small scale; hits know the prototype's shape and the instance; the keyframe
// decomposition Embree interpolates is pdrt's; instanced convex shapes in a furnace show no
// self-intersection.
#include "renderer/render/embree_scene.h"
#include "renderer/render/instance_keys.h"
#include "sampling/core/rng.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;
using namespace pdrt::test;

namespace {

// A UV sphere of radius 1 about the origin: `rings` x `segments` quads as triangles, with
// per-vertex uvs, and unit normals when `smooth` (else flat facets).
ShapeDesc uv_sphere(int rings, int segments, bool smooth, int material) {
  ShapeDesc s;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
      const Vec3 p{float(std::sin(th) * std::cos(ph)), float(-std::cos(th)), float(std::sin(th) * std::sin(ph))};
      s.mesh.positions.push_back(p);
      if (smooth) s.mesh.normals.push_back(p);
      s.mesh.uvs.push_back({float(j) / segments, float(i) / rings});
    }
  auto v = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      // Outward (counter-clockwise seen from outside); the poles' zero-area halves dropped.
      if (i > 0) s.mesh.indices.insert(s.mesh.indices.end(), {v(i, j), v(i, j + 1), v(i + 1, j)});
      if (i + 1 < rings) s.mesh.indices.insert(s.mesh.indices.end(), {v(i, j + 1), v(i + 1, j + 1), v(i + 1, j)});
    }
  s.material = material;
  return s;
}

// A placement as an affine transform.
Affine placed(const Placement& at) { return Affine::translate(at.offset) * Affine::scale(Vec3(at.scale)); }

struct Pair {
  SceneDesc instanced, copied;
};

// Three instances of one prototype (a checkerboard-textured quad, a smooth-shaded glossy
// mesh sphere moved within the prototype, a diffuse sphere) under a square light, seen from
// the front; `moving`: the middle instance moves (motion keys) over the shutter. `copied`
// holds the same shapes copied under the instances' transforms.
Pair instanced_and_copied(const Placement& at, bool moving) {
  SceneDesc s = base_scene(64, 40, 16);
  s.camera.position = at.point({0, 2.5f, 4.5f}), s.camera.look_at = at.point({0, 0.2f, 0}), s.camera.vfov_deg = 45;
  s.environment.radiance = Vec3(0.15f);
  s.integrator.max_depth = 4;
  TextureDesc checks;
  checks.kind = TextureDesc::Kind::Checkerboard;
  checks.scale_u = checks.scale_v = 4;
  checks.color0.value = Vec3(0.8f), checks.color1.value = Vec3(0.2f, 0.3f, 0.6f);
  s.textures.push_back(checks);
  Material floor = diffuse(0.5f);
  floor.textures.push_back({MaterialParam::Albedo, 0});
  Material gloss = diffuse(0.6f);
  gloss.type = MaterialType::Glossy, gloss.roughness = 0.3f;
  const int m_floor = add_material(s, floor), m_gloss = add_material(s, gloss), m_ball = add_material(s, diffuse(0.7f));
  s.shapes.push_back(quad(at.point({-1, 3, -1}), at.vector({2, 0, 0}), at.vector({0, 0, 2}),
                          add_material(s, emitter(12))));  // faces down

  PrototypeDesc p;
  p.name = "group";
  p.shapes.push_back(quad({-0.8f, 0, 0.8f}, {1.6f, 0, 0}, {0, 0, -1.6f}, m_floor));  // faces up
  ShapeDesc smooth = uv_sphere(12, 24, true, m_gloss);
  smooth.transform = Affine::translate({0.3f, 0.45f, 0}) * Affine::scale(Vec3(0.4f));
  p.shapes.push_back(smooth);
  p.shapes.push_back(sphere({-0.4f, 0.25f, 0.3f}, 0.25f, m_ball));
  s.prototypes.push_back(p);

  const Affine local[3] = {
      Affine::translate({-1.8f, 0, 0}),
      Affine::translate({0, 0.1f, -0.5f}) * Affine::rotate({0, 1, 0}, 35) * Affine::scale(Vec3(1.1f)),
      Affine::translate({1.8f, 0, 0.3f}) * Affine::rotate({1, 0, 1}, -12) * Affine::scale(Vec3(0.9f))};
  for (int i = 0; i < 3; ++i) {
    InstanceDesc in;
    in.prototype = 0;
    in.transform = placed(at) * local[i];
    if (moving && i == 1) {
      // world(t) = T(offset + scale d(t)) R(t) S(scale) local: the placement stays outermost.
      in.transform = local[i];
      MotionKey k0, k1;
      k0.time = 0, k1.time = 1;
      k0.translate = at.offset, k1.translate = at.point({0.35f, 0, 0.1f});
      k0.scale = k1.scale = Vec3(at.scale);
      k1.rotate = Quat::from_axis_angle({0, 1, 0}, 25);
      in.motion = {k0, k1};
    }
    s.instances.push_back(in);
  }
  Pair out{s, s};
  SceneDesc& c = out.copied;
  c.prototypes.clear(), c.instances.clear();
  for (const InstanceDesc& in : s.instances)
    for (ShapeDesc sh : p.shapes) {
      sh.transform = in.transform * sh.transform;
      sh.motion = in.motion;
      c.shapes.push_back(sh);
    }
  return out;
}

struct Difference {
  double mean_relative = 0;  // mean |a - b| / mean b
  double outliers = 0;       // fraction of pixels differing by more than 1 % of the mean
  double mean = 0;
};

Difference difference(const Image& a, const Image& b) {
  Difference d;
  double sum = 0;
  const int n = a.width * a.height;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      d.mean += mean_rgb(b, x, y), sum += std::abs(mean_rgb(a, x, y) - mean_rgb(b, x, y));
  d.mean /= n;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (std::abs(mean_rgb(a, x, y) - mean_rgb(b, x, y)) > 0.01 * d.mean) d.outliers += 1.0 / n;
  d.mean_relative = sum / n / d.mean;
  return d;
}

const std::vector<Placement> kPlacements = {
    {{0, 0, 0}, 1}, {{1e4f, -1e4f, 1e4f}, 1}, {{0, 0, 0}, 1e-3f}, {{10, 5, 3}, 1e-3f}};

// Float spacing at the placement's offset relative to the scene's size: how far a copied
// vertex (stored in world space) may sit from the instanced one (stored in the prototype's
// space and transformed by Embree per ray).
double relative_spacing(const Placement& at) {
  const float far = std::max({std::abs(at.offset.x), std::abs(at.offset.y), std::abs(at.offset.z)});
  return far == 0 ? 0.0 : double(std::nextafter(far, INFINITY) - far) / at.scale;
}

// Embree intersects an instance in the prototype's space (the ray carried through the inverse
// transform), a copy in world space: t and the hit point differ in their last bits, and a copy
// far from the origin has its vertices rounded to the float spacing there (2^-10 of the scene's
// size at 10^4, scale 1). Measured: at the origin (any scale) mean difference 3e-7 of the image
// mean and no pixel off by 1 %; where the spacing is ~1e-3 of the scene, mean 3.3e-3 to 3.9e-3
// and 2.6 % to 3.0 % of the pixels (silhouettes and checker edges move by the rounding). Allowed:
// 1e-5 + 6 x spacing, and 5 % of the pixels when the spacing is not 0. Self-intersection, or a
// wrong transform, normal or uv, makes whole regions differ (tens of %).
void expect_same_image(const Pair& p, const Placement& at) {
  Image a = render_quietly(p.instanced).image, b = render_quietly(p.copied).image;
  Difference d = difference(a, b);
  const double spacing = relative_spacing(at);
  EXPECT_GT(d.mean, 0.1) << describe(at);
  EXPECT_LT(d.mean_relative, 1e-5 + 6 * spacing) << describe(at);
  EXPECT_LE(d.outliers, spacing > 0 ? 0.05 : 0.0) << describe(at);
}

}  // namespace

TEST(Instances, StaticInstancesRenderTheImageOfCopiedShapesAtEveryPlacement) {
  for (const Placement& at : kPlacements) expect_same_image(instanced_and_copied(at, false), at);
}

TEST(Instances, MovingInstancesRenderTheImageOfCopiedMovingShapesAtEveryPlacement) {
  for (const Placement& at : kPlacements) expect_same_image(instanced_and_copied(at, true), at);
}

// A hit inside an instance names the prototype's shape (its material, normals, uvs) and the
// instance, and its normal and dp/du are in world space.
TEST(Instances, AHitInsideAnInstanceKnowsThePrototypeShapeAndTheInstance) {
  Pair p = instanced_and_copied({{0, 0, 0}, 1}, false);
  EmbreeDevice device;
  EmbreeScene scene(p.instanced, device);
  ASSERT_EQ(scene.shape_count(), 1 + 3);
  // Straight down onto instance 2's floor quad, away from its balls.
  const Affine& m = p.instanced.instances[2].transform;
  Ray r;
  r.org = m.point({0.6f, 2, -0.6f}), r.dir = normalize(m.vector({0, -1, 0}));
  r.tmin = 0, r.tmax = 1e30f, r.time = 0.5f;
  SurfaceHit h;
  ASSERT_TRUE(scene.intersect(r, &h));
  EXPECT_EQ(h.instance, 2);
  EXPECT_EQ(h.shape, scene.prototype_first_shape(0) + 0);
  EXPECT_EQ(scene.material(h.shape), p.instanced.prototypes[0].shapes[0].material);
  const Vec3 up = normalize(m.normal({0, 1, 0}));
  EXPECT_NEAR(dot(h.ng, up), 1, 1e-6);
  EXPECT_NEAR(length(h.p - m.point({0.6f, 0, -0.6f})), 0, 1e-5);
  scene.texture_coords(&h, r.time);
  // The quad's uv: (0,0) at its corner (-0.8, 0, 0.8), u along +x over 1.6, v along -z.
  EXPECT_NEAR(h.u, 1.4f / 1.6f, 1e-5);
  EXPECT_NEAR(h.v, 1.4f / 1.6f, 1e-5);
  const Vec3 dpdu = m.vector({1.6f, 0, 0});
  EXPECT_NEAR(length(h.dpdu - dpdu), 0, 1e-5 * length(dpdu));
  // A scene shape outside the instances keeps its index.
  Ray up_ray;
  up_ray.org = {0, 2, 0}, up_ray.dir = {0, 1, 0}, up_ray.tmin = 0, up_ray.tmax = 1e30f, up_ray.time = 0.5f;
  ASSERT_TRUE(scene.intersect(up_ray, &h));
  EXPECT_EQ(h.shape, 0);
  EXPECT_EQ(h.instance, -1);
}

// instance_key() decomposes key.matrix() * static_part exactly at the keys, and Embree's
// interpolation of the decomposition follows pdrt's interpolate(keys, t) * static_part between
// them (embree_follows_keys) — or, when it cannot, the keys are resampled so it stays close.
TEST(Instances, EmbreeInstanceTransformsFollowPdrtsKeyframeInterpolation) {
  Rng rng(18);  // pcg32 (sampling/core/rng.h)
  auto u = [&](float lo, float hi) { return float(rng.uniform(lo, hi)); };
  int exact_cases = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const bool uniform = trial % 2 == 0, rotated = trial % 3 != 0;
    SceneDesc s = base_scene(4, 4, 1);
    PrototypeDesc p;
    p.shapes.push_back(sphere({0, 0, 0}, 1, add_material(s, diffuse(0.5f))));
    s.prototypes.push_back(p);
    InstanceDesc in;
    Affine upper;  // upper triangular 3x3 when not rotated
    upper.m = {{{u(0.5f, 2), u(-0.5f, 0.5f), u(-0.5f, 0.5f), u(-3, 3)},
                {0, u(0.5f, 2), u(-0.5f, 0.5f), u(-3, 3)},
                {0, 0, u(-2, -0.5f), u(-3, 3)}}};
    in.transform = rotated ? Affine::rotate({u(-1, 1), u(-1, 1), 1}, u(-170, 170)) * upper : upper;
    for (int k = 0; k < 3; ++k) {
      MotionKey key;
      key.time = 0.5f * float(k);
      key.translate = {u(-5, 5), u(-5, 5), u(-5, 5)};
      key.rotate = Quat::from_axis_angle({u(-1, 1), u(-1, 1), u(-1, 1) + 2}, u(-90, 90));
      const float g = u(0.5f, 2);
      key.scale = uniform ? Vec3(g) : Vec3(u(0.5f, 2), u(0.5f, 2), u(0.5f, 2));
      in.motion.push_back(key);
    }
    s.instances.push_back(in);
    const bool exact = embree_follows_keys(in.motion, in.transform);
    EXPECT_EQ(exact, uniform || !rotated) << trial;
    exact_cases += exact;
    EmbreeDevice device;
    EmbreeScene scene(s, device);
    for (float t : {0.0f, 0.13f, 0.25f, 0.5f, 0.71f, 1.0f}) {
      const MotionKey k = interpolate(in.motion.data(), 3, t);
      const Affine want = k.matrix() * in.transform, got = scene.instance_transform(0, t);
      // Exact decompositions agree to float rounding; resampled ones (129 steps) to the
      // chord error of the slerp between steps.
      const float tol = exact ? 2e-5f : 5e-3f;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
          EXPECT_NEAR(got.m[r][c], want.m[r][c], tol * (1 + std::abs(want.m[r][c])))
              << "trial " << trial << " t " << t << " [" << r << "][" << c << "]";
    }
  }
  EXPECT_GT(exact_cases, 8);
}

// A convex instanced shape (a sphere, then a flat-faceted mesh sphere; diffuse 0.5) in a white
// furnace reads 0.5 over its inner pixels, and the same image (to 2 % a pixel) far from the
// origin and at small scale as at the origin: a spawned ray that re-hit its own surface would
// darken pixels where the error bound is too small (far, or small), not at the origin.
TEST(Instances, InstancedConvexShapesInAFurnaceLookTheSameAtEveryPlacement) {
  const int W = 32;
  for (bool mesh : {false, true}) {
    Image origin;
    for (const Placement& at : kPlacements) {
      SceneDesc s = base_scene(W, W, 16);
      s.camera.position = at.point({0, 0, 6}), s.camera.look_at = at.point({0, 0, 0}), s.camera.vfov_deg = 25;
      s.environment.radiance = Vec3(1.0f);
      s.integrator.max_depth = 1;
      const int m = add_material(s, diffuse(0.5f));
      PrototypeDesc p;
      p.shapes.push_back(mesh ? uv_sphere(10, 20, false, m) : sphere({0, 0, 0}, 1, m));
      s.prototypes.push_back(p);
      InstanceDesc in;
      in.transform = placed(at) * Affine::rotate({0, 0, 1}, 3);
      s.instances.push_back(in);
      Image im = render_quietly(s).image;
      if (origin.rgb.empty()) origin = im;
      double sum = 0, worst = 0;
      int n = 0;
      for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x) {
          const double dx = x + 0.5 - W / 2.0, dy = y + 0.5 - W / 2.0;
          if (dx * dx + dy * dy > 0.5 * (W / 4.0) * (W / 4.0)) continue;  // inside the silhouette
          sum += mean_rgb(im, x, y), ++n;
          worst = std::max(worst, std::abs(mean_rgb(im, x, y) - mean_rgb(origin, x, y)));
        }
      ASSERT_GT(n, 60);
      EXPECT_NEAR(sum / n, 0.5, 0.01) << (mesh ? "mesh " : "sphere ") << describe(at);
      EXPECT_LT(worst, 0.02) << (mesh ? "mesh " : "sphere ") << describe(at) << " (self-intersection)";
    }
  }
}

// A scene of instances only has the instances' bounds.
TEST(Instances, SceneBoundsCoverTheInstances) {
  SceneDesc s = base_scene(4, 4, 1);
  PrototypeDesc p;
  p.shapes.push_back(sphere({0, 0, 0}, 1, add_material(s, diffuse(0.5f))));
  s.prototypes.push_back(p);
  for (float x : {-10.0f, 10.0f}) {
    InstanceDesc in;
    in.transform = Affine::translate({x, 0, 0});
    s.instances.push_back(in);
  }
  EmbreeDevice device;
  EmbreeScene scene(s, device);
  // Half the diagonal of the box [-11, 11] x [-1, 1] x [-1, 1].
  EXPECT_NEAR(scene.bounds_radius(), std::sqrt(123.0), 1e-3);
}

// An emitter inside a prototype (the loader refuses it; a SceneDesc built in code may hold one)
// is not in the light set, so only BSDF sampling reaches it, with MIS weight 1: unbiased.
// A diffuse plane (0.5) under an instanced 2 x 2 square of radiance 1 at height 1 reads
// rho * L * F at the point below its centre (F = 0.5541, the square's form factor), within
// 3 % (16 384 cosine-sampled directions over the 8 x 8 patch seen: about 1 % standard error).
TEST(Instances, AnEmitterInsideAnInstanceIsReachedByBsdfSamplingWithoutBias) {
  const int W = 8;
  SceneDesc s = base_scene(W, W, 256);
  s.camera.position = {0, 0.05f, 0}, s.camera.look_at = {0, 0, 0}, s.camera.up = {0, 0, -1}, s.camera.vfov_deg = 90;
  s.integrator.max_depth = 1;
  s.shapes.push_back(quad({-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, add_material(s, diffuse(0.5f))));
  PrototypeDesc p;
  p.shapes.push_back(quad({-1, 0, -1}, {2, 0, 0}, {0, 0, 2}, add_material(s, emitter(1))));  // faces down
  s.prototypes.push_back(p);
  InstanceDesc in;
  in.transform = Affine::translate({0, 1, 0});
  s.instances.push_back(in);
  Image im = render_quietly(s).image;
  double sum = 0;
  for (int y = 0; y < W; ++y)
    for (int x = 0; x < W; ++x) sum += mean_rgb(im, x, y);
  const double expected = 0.5 * rect_form_factor(0, 0, -1, 1, -1, 1, 1);
  EXPECT_NEAR(expected, 0.5 * 0.5541, 1e-3);
  EXPECT_NEAR(sum / (W * W), expected, 0.03 * expected);
}
