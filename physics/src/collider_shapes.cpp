#include "collider_shapes.h"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <algorithm>
#include <cmath>

namespace candela::physics {
namespace {

// Bullet keeps boxes and cylinders a collision margin inside their surface; the default 4 cm
// would swallow a small box whole, so small shapes get a fifth of their smallest half size.
constexpr float kMaxMargin = 0.04f;

float marginFor(float smallestHalfSize) {
    return std::min(kMaxMargin, 0.2f * smallestHalfSize);
}

bool positiveFinite(float v) {
    return std::isfinite(v) && v > 0.0f;
}

float largest(float a, float b) {
    return std::max(std::fabs(a), std::fabs(b));
}

bool finitePoint(const content::Float3& p, ecs::Vec3 scale) {
    return std::isfinite(p[0] * scale.x) && std::isfinite(p[1] * scale.y) &&
           std::isfinite(p[2] * scale.z);
}

btVector3 scaled(const content::Float3& p, ecs::Vec3 scale) {
    return {p[0] * scale.x, p[1] * scale.y, p[2] * scale.z};
}

ShapeData hullOf(const content::Mesh& mesh, ecs::Vec3 scale, std::string& problem) {
    auto hull = std::make_unique<btConvexHullShape>();
    std::size_t skipped = 0;
    for (const content::Primitive& primitive : mesh.primitives) {
        for (const content::Float3& p : primitive.positions) {
            if (!finitePoint(p, scale)) {
                ++skipped;
                continue;
            }
            hull->addPoint(scaled(p, scale), false);
        }
    }
    hull->recalcLocalAabb();
    if (hull->getNumPoints() < 4) {
        problem = "shape: convexHull needs at least 4 finite mesh points";
        return {};
    }
    if (skipped) problem = "shape: " + std::to_string(skipped) + " non-finite mesh points skipped";
    // A hull collides with its points plus its margin: keep that margin thin.
    hull->setMargin(0.001f);
    hull->optimizeConvexHull();
    // Its faces: exact ray tests (ray_shape_intersection.h) and better contacts.
    hull->initializePolyhedralFeatures();
    return {nullptr, std::move(hull), {}};
}

ShapeData triangleMeshOf(const content::Mesh& mesh, ecs::Vec3 scale, std::string& problem) {
    auto triangles = std::make_unique<btTriangleMesh>(true, false);
    std::size_t skipped = 0;
    for (const content::Primitive& primitive : mesh.primitives) {
        for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
            const content::Float3& a = primitive.positions[primitive.indices[i]];
            const content::Float3& b = primitive.positions[primitive.indices[i + 1]];
            const content::Float3& c = primitive.positions[primitive.indices[i + 2]];
            if (!finitePoint(a, scale) || !finitePoint(b, scale) || !finitePoint(c, scale)) {
                ++skipped;
                continue;
            }
            triangles->addTriangle(scaled(a, scale), scaled(b, scale), scaled(c, scale), false);
        }
    }
    if (triangles->getNumTriangles() == 0) {
        problem = "shape: triangleMesh has no triangle with finite vertices";
        return {};
    }
    if (skipped) {
        problem =
            "shape: " + std::to_string(skipped) + " triangles with non-finite vertices skipped";
    }
    auto shape = std::make_unique<btBvhTriangleMeshShape>(triangles.get(), true);
    return {std::move(triangles), std::move(shape), {}};
}

}  // namespace

ShapeData makeColliderShape(const content::Collider& collider, ecs::Vec3 scale,
                            const content::Mesh* mesh, bool dynamic, std::string& problem) {
    using content::ColliderShape;
    if (!std::isfinite(scale.x) || !std::isfinite(scale.y) || !std::isfinite(scale.z) ||
        scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f) {
        problem = "transform: a zero or non-finite scale leaves the collider no size";
        return {};
    }
    const float radius = collider.radius.value_or(content::kDefaultColliderRadius);
    switch (collider.shape) {
        case ColliderShape::Sphere: {
            const float r = radius * std::max(largest(scale.x, scale.y), std::fabs(scale.z));
            if (!positiveFinite(r)) break;
            return {nullptr, std::make_unique<btSphereShape>(r), {}};
        }
        case ColliderShape::Box: {
            const ecs::Vec3 h = collider.halfExtents.value_or(content::kDefaultColliderHalfExtents);
            const btVector3 half(std::fabs(h.x * scale.x), std::fabs(h.y * scale.y),
                                 std::fabs(h.z * scale.z));
            if (!positiveFinite(half.x()) || !positiveFinite(half.y()) ||
                !positiveFinite(half.z())) {
                problem = "halfExtents: every half extent must be positive and finite";
                return {};
            }
            const float margin = marginFor(half.minAxis() == 0   ? half.x()
                                           : half.minAxis() == 1 ? half.y()
                                                                 : half.z());
            auto box = std::make_unique<btBoxShape>(half);
            box->setMargin(margin);  // keeps the outer size (btBoxShape::setMargin)
            return {nullptr, std::move(box), {}};
        }
        case ColliderShape::Capsule:
        case ColliderShape::Cylinder: {
            const bool capsule = collider.shape == ColliderShape::Capsule;
            const float r = radius * largest(scale.x, scale.z);
            const float height =
                collider.height.value_or(capsule ? content::kDefaultCapsuleHeight
                                                 : content::kDefaultCylinderHeight) *
                std::fabs(scale.y);
            if (!positiveFinite(r)) break;
            if (!positiveFinite(height)) {
                problem = "height: must be positive and finite";
                return {};
            }
            if (capsule) {
                // Bullet's height is between the two hemisphere centres.
                return {nullptr,
                        std::make_unique<btCapsuleShape>(r, std::max(0.0f, height - 2 * r)),
                        {}};
            }
            auto cylinder = std::make_unique<btCylinderShape>(btVector3(r, 0.5f * height, r));
            cylinder->setMargin(marginFor(std::min(r, 0.5f * height)));
            return {nullptr, std::move(cylinder), {}};
        }
        case ColliderShape::ConvexHull:
        case ColliderShape::TriangleMesh:
            if (!mesh) {
                problem = "shape: a convexHull or triangleMesh collider needs a mesh on its entity";
                return {};
            }
            if (collider.shape == ColliderShape::ConvexHull || dynamic) {
                if (collider.shape == ColliderShape::TriangleMesh) {
                    problem =
                        "shape: a moving body cannot be a triangleMesh; using its convex hull";
                    std::string hullProblem;
                    ShapeData data = hullOf(*mesh, scale, hullProblem);
                    if (!hullProblem.empty()) problem = hullProblem;
                    return data;
                }
                return hullOf(*mesh, scale, problem);
            }
            return triangleMeshOf(*mesh, scale, problem);
    }
    problem = "radius: must be positive and finite";
    return {};
}

}  // namespace candela::physics
