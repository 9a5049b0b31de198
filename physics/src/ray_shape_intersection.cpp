#include "ray_shape_intersection.h"

#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela::physics {
namespace {

// In doubles: a 1e-4 m answer far from the origin needs more than a float's 24 bits.
struct V {
    double x, y, z;
};
V operator+(V a, V b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V operator-(V a, V b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V operator*(V a, double s) {
    return {a.x * s, a.y * s, a.z * s};
}
double dot(V a, V b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
V of(const btVector3& v) {
    return {v.x(), v.y(), v.z()};
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The parameter interval [enter, exit] a ray spends inside a part, and the normal at entry.
struct Span {
    double enter = -kInfinity;
    double exit = kInfinity;
    V normal{0, 0, 0};
    bool empty() const { return !(enter <= exit); }
};

Span sphere(V f, V d, V centre, double r) {
    const V o = f - centre;
    const double a = dot(d, d), b = dot(o, d), c = dot(o, o) - r * r;
    const double disc = b * b - a * c;
    if (disc < 0) return {1, 0, {}};
    const double root = std::sqrt(disc);
    const double enter = (-b - root) / a;
    const V p = o + d * enter;
    return {enter, (-b + root) / a, p * (1.0 / r)};
}

// Slab |p_axis| <= h: intersected into `span`, the normal following the later entry.
void slab(Span& span, double f, double d, double h, V axis) {
    if (d == 0) {
        if (std::fabs(f) > h) span = {1, 0, {}};
        return;
    }
    double t0 = (-h - f) / d, t1 = (h - f) / d;
    V normal = axis * -1.0;
    if (t0 > t1) {
        std::swap(t0, t1);
        normal = axis;
    }
    if (t0 > span.enter) {
        span.enter = t0;
        span.normal = normal;
    }
    span.exit = std::min(span.exit, t1);
}

// The infinite Y cylinder x^2 + z^2 <= r^2, intersected into `span`.
void tube(Span& span, V f, V d, double r) {
    const double a = d.x * d.x + d.z * d.z;
    const double b = f.x * d.x + f.z * d.z;
    const double c = f.x * f.x + f.z * f.z - r * r;
    if (a == 0) {
        if (c > 0) span = {1, 0, {}};
        return;
    }
    const double disc = b * b - a * c;
    if (disc < 0) {
        span = {1, 0, {}};
        return;
    }
    const double root = std::sqrt(disc);
    const double enter = (-b - root) / a, exit = (-b + root) / a;
    if (enter > span.enter) {
        span.enter = enter;
        const V p = f + d * enter;
        span.normal = {p.x / r, 0, p.z / r};
    }
    span.exit = std::min(span.exit, exit);
}

Span cylinder(V f, V d, double r, double halfHeight) {
    Span span;
    tube(span, f, d, r);
    if (!span.empty()) slab(span, f.y, d.y, halfHeight, {0, 1, 0});
    return span;
}

Span box(V f, V d, V half) {
    Span span;
    slab(span, f.x, d.x, half.x, {1, 0, 0});
    slab(span, f.y, d.y, half.y, {0, 1, 0});
    slab(span, f.z, d.z, half.z, {0, 0, 1});
    return span;
}

// The intersection of the hull's face half-spaces n.p + d <= 0 (outward normals).
Span polyhedron(V f, V dir, const btConvexPolyhedron& hull) {
    Span span;
    for (int i = 0; i < hull.m_faces.size(); ++i) {
        const btScalar* plane = hull.m_faces[i].m_plane;
        const V n{plane[0], plane[1], plane[2]};
        const double denom = dot(n, dir);
        const double distance = dot(n, f) + plane[3];
        if (denom == 0) {
            if (distance > 0) return {1, 0, {}};
            continue;
        }
        const double t = -distance / denom;
        if (denom < 0 && t > span.enter) {
            span.enter = t;
            span.normal = n;
        } else if (denom > 0) {
            span.exit = std::min(span.exit, t);
        }
    }
    return span;
}

// The first entry into a union of convex parts, or none when the segment starts inside one.
std::optional<LocalHit> firstEntry(std::initializer_list<Span> parts) {
    std::optional<LocalHit> best;
    for (const Span& part : parts) {
        if (part.empty()) continue;
        if (part.enter < 0 && part.exit > 0) return std::nullopt;  // starts inside
        if (part.enter < 0 || part.enter > 1) continue;
        if (!best || part.enter < best->fraction) {
            const V n = part.normal;
            const double length = std::sqrt(dot(n, n));
            best = LocalHit{
                static_cast<btScalar>(part.enter),
                btVector3(static_cast<btScalar>(n.x / length), static_cast<btScalar>(n.y / length),
                          static_cast<btScalar>(n.z / length))};
        }
    }
    return best;
}

}  // namespace

bool isPrimitive(const btCollisionShape& shape) {
    switch (shape.getShapeType()) {
        case SPHERE_SHAPE_PROXYTYPE:
        case BOX_SHAPE_PROXYTYPE:
        case CAPSULE_SHAPE_PROXYTYPE:
        case CYLINDER_SHAPE_PROXYTYPE:
            return true;
        case CONVEX_HULL_SHAPE_PROXYTYPE:
            return static_cast<const btPolyhedralConvexShape&>(shape).getConvexPolyhedron() !=
                   nullptr;
        default:
            return false;
    }
}

std::optional<LocalHit> intersectPrimitive(const btCollisionShape& shape, const btVector3& from,
                                           const btVector3& to) {
    const V f = of(from);
    const V d = of(to) - f;
    switch (shape.getShapeType()) {
        case SPHERE_SHAPE_PROXYTYPE:
            return firstEntry(
                {sphere(f, d, {0, 0, 0}, static_cast<const btSphereShape&>(shape).getRadius())});
        case BOX_SHAPE_PROXYTYPE:
            return firstEntry(
                {box(f, d, of(static_cast<const btBoxShape&>(shape).getHalfExtentsWithMargin()))});
        case CAPSULE_SHAPE_PROXYTYPE: {
            const auto& capsule = static_cast<const btCapsuleShape&>(shape);
            const double r = capsule.getRadius(), h = capsule.getHalfHeight();
            return firstEntry(
                {cylinder(f, d, r, h), sphere(f, d, {0, h, 0}, r), sphere(f, d, {0, -h, 0}, r)});
        }
        case CYLINDER_SHAPE_PROXYTYPE: {
            const btVector3 half =
                static_cast<const btCylinderShape&>(shape).getHalfExtentsWithMargin();
            return firstEntry({cylinder(f, d, half.x(), half.y())});
        }
        case CONVEX_HULL_SHAPE_PROXYTYPE: {
            const btConvexPolyhedron* hull =
                static_cast<const btPolyhedralConvexShape&>(shape).getConvexPolyhedron();
            if (!hull) return std::nullopt;
            return firstEntry({polyhedron(f, d, *hull)});
        }
        default:
            return std::nullopt;
    }
}

}  // namespace candela::physics
