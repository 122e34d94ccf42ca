#pragma once
// The scene as Embree sees it: one top-level BVH holding every static shape (already in
// world space) and, for each moving shape, a motion-blurred instance of a child scene whose
// transform is keyframed over the shutter (Embree slerps the rotation between time steps).
// Top-level geometry IDs below desc.shapes.size() equal shape indices, so a hit names its
// ShapeDesc directly. Each prototype (SceneDesc::prototypes) is one child scene, built once;
// each InstanceDesc is an Embree instance of it (static, or keyframed like a moving shape) at
// top-level ID desc.shapes.size() + instance index. Shape indices continue past the scene's
// shapes with every prototype's shapes in order (shape_desc()), so a hit in an instance names
// the prototype's shape (material, uvs, normals) and, in SurfaceHit::instance, its placement.
#include "renderer/render/embree_device.h"
#include "renderer/render/ray.h"
#include "renderer/render/ray_spawn.h"
#include "renderer/scene/scene_desc.h"

#include <embree3/rtcore.h>

#include <array>
#include <atomic>
#include <vector>

namespace pdrt {

struct SurfaceHit {
  float t = 0;
  Vec3 p;             // world position, reprojected onto the surface (not org + t dir)
  Vec3 p_error;       // per-component bound on p's floating-point error (ray_spawn.h)
  Vec3 ng;            // unit geometric normal, on the front side (CCW winding / sphere outside)
  Vec3 ns;            // unit shading normal (interpolated vertex normals), same side as ng
  int shape = -1;     // EmbreeScene's shape index: desc.shapes, then the prototypes' shapes
  int instance = -1;  // the InstanceDesc hit (its transform places the shape), -1 outside instances
  int prim = -1;
  bool front = true;             // the ray arrived from the side ng points to
  float bary_u = 0, bary_v = 0;  // Embree's barycentrics (triangles)
  Vec3 p_local;                  // p before a moving shape's or an instance's transform
  // Texture coordinates (docs/scene-format.md, "Texture coordinates") and the world-space
  // surface derivatives dp/du, dp/dv the texture footprint needs (texture_footprint.h): only
  // set by EmbreeScene::texture_coords, which textured materials call (the rest never pay).
  float u = 0, v = 0;
  Vec3 dpdu, dpdv;
  ErrorPoint point() const { return {p, p_error}; }
};

class EmbreeScene {
 public:
  EmbreeScene(const SceneDesc& desc, const EmbreeDevice& device);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  bool intersect(const Ray& ray, SurfaceHit* hit) const;
  bool occluded(const Ray& ray) const;
  // Fills hit->u, v, dpdu, dpdv for a hit this scene returned (`time`: the ray's).
  void texture_coords(SurfaceHit* hit, float time) const;
  // Four camera rays of one pixel as an Embree packet (much cheaper per ray when they are
  // coherent); lanes with live[k] false are not traced. found[k] says whether hits[k] is set.
  // Packet and single-ray kernels may differ in the last bit of t, u, v, so a caller that
  // needs replayable images must always trace the same rays the same way.
  void intersect4(const Ray* rays, const bool* live, SurfaceHit* hits, bool* found) const;

  // Object-to-world transform of `shape` at normalised shutter time (identity for static
  // shapes, whose geometry is stored in world space).
  Affine transform(int shape, float time) const;
  bool moving(int shape) const { return shapes_[shape].instance != nullptr; }
  // The transform that takes a hit's stored geometry to world space at `time` (normalised
  // shutter time): its instance's, a moving shape's, or the identity.
  Affine hit_transform(const SurfaceHit& hit, float time) const;
  // Prototype to world of instance `i` at `time`.
  Affine instance_transform(int i, float time) const;
  bool instanced(int shape) const { return shape >= int(desc_.shapes.size()); }
  int shape_count() const { return int(shapes_.size()); }
  // The description of shape index `shape` (a scene shape or a prototype's).
  const ShapeDesc& shape_desc(int shape) const { return *shapes_[shape].desc; }
  int material(int shape) const { return shapes_[shape].desc->material; }
  // The shape index of prototype p's first shape.
  int prototype_first_shape(int p) const { return prototype_first_[p]; }

  // Geometry after the static transform (world space for static shapes, instance space
  // for moving ones).
  const std::vector<Vec3>& positions(int shape) const { return shapes_[shape].positions; }
  const std::vector<uint32_t>& indices(int shape) const { return shapes_[shape].indices; }
  Vec3 sphere_center(int shape) const { return shapes_[shape].center; }
  float sphere_radius(int shape) const { return shapes_[shape].radius; }

  const SceneDesc& desc() const { return desc_; }
  // Radius of a sphere about the bounding box centre that bounds the scene (whole shutter).
  float bounds_radius() const { return bounds_radius_; }
  std::size_t triangle_count() const { return triangles_; }  // stored once per prototype
  RTCScene rtc_scene() const { return scene_; }

 private:
  void finish_hit(const Ray& ray, unsigned inst_id, unsigned geom_id, unsigned prim_id, float u, float v,
                  const Vec3& embree_ng, float t, SurfaceHit* hit) const;

  struct Shape {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<uint32_t> indices;
    std::vector<std::array<float, 2>> uvs;
    Vec3 center;
    float radius = 0;
    Affine to_world;   // sphere: the shape's static transform (object to the stored space)
    Affine to_object;  // its inverse: uv are measured in object space
    float object_radius = 1;
    bool sphere = false;
    RTCScene child = nullptr;
    RTCGeometry instance = nullptr;
    const ShapeDesc* desc = nullptr;
  };
  struct Instance {
    Affine to_world, to_prototype;   // static instances
    RTCGeometry geometry = nullptr;  // moving instances: kept for transform queries
  };
  RTCGeometry make_geometry(const Shape& s) const;
  void add_shape(Shape& s, const ShapeDesc& d);
  RTCGeometry make_moving_instance(RTCScene child, const std::vector<MotionKey>& motion,
                                   const Affine& static_part) const;

  const SceneDesc& desc_;
  const EmbreeDevice& device_;
  RTCScene scene_ = nullptr;
  std::vector<Shape> shapes_;
  std::vector<RTCScene> prototypes_;
  std::vector<int> prototype_first_;
  std::vector<Instance> instances_;
  float bounds_radius_ = 1;
  std::size_t triangles_ = 0;
};

}  // namespace pdrt
