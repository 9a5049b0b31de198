#include "candela/ecs/rotation.h"

#include <algorithm>
#include <cmath>

namespace candela::ecs {

std::optional<Quat> lookAtRotation(Vec3 position, Vec3 target) {
    const double dx = double(target.x) - position.x;
    const double dy = double(target.y) - position.y;
    const double dz = double(target.z) - position.z;
    const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (!(length > 1e-6)) return std::nullopt;
    const double yaw = std::atan2(-dx, -dz);
    const double pitch = std::asin(std::clamp(dy / length, -1.0, 1.0));
    // yaw(Y) * pitch(X), with half angles.
    const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
    const double cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
    return Quat{float(cy * sp), float(sy * cp), float(-sy * sp), float(cy * cp)};
}

Quat fromToRotation(Vec3 from, Vec3 to) {
    const double fx = from.x, fy = from.y, fz = from.z, tx = to.x, ty = to.y, tz = to.z;
    const double fl = std::sqrt(fx * fx + fy * fy + fz * fz);
    const double tl = std::sqrt(tx * tx + ty * ty + tz * tz);
    if (!(fl > 0) || !(tl > 0) || !std::isfinite(fl) || !std::isfinite(tl)) return {};
    const double ax = fx / fl, ay = fy / fl, az = fz / fl;
    const double bx = tx / tl, by = ty / tl, bz = tz / tl;
    const double d = ax * bx + ay * by + az * bz;
    if (d < -1.0 + 1e-12) {
        // Half a turn about an axis perpendicular to `from`: the cross product with the
        // coordinate axis `from` is least along (never near parallel to it).
        double px = 0, py = 0, pz = 0;
        if (std::fabs(ax) <= std::fabs(ay) && std::fabs(ax) <= std::fabs(az)) {
            py = -az, pz = ay;
        } else if (std::fabs(ay) <= std::fabs(az)) {
            px = az, pz = -ax;
        } else {
            px = -ay, py = ax;
        }
        const double pl = std::sqrt(px * px + py * py + pz * pz);
        return Quat{float(px / pl), float(py / pl), float(pz / pl), 0.0f};
    }
    // q = (a x b, 1 + a.b), normalised: the half-angle form of the shortest arc.
    const double cx = ay * bz - az * by, cyy = az * bx - ax * bz, cz = ax * by - ay * bx;
    const double w = 1.0 + d;
    const double n = std::sqrt(cx * cx + cyy * cyy + cz * cz + w * w);
    return Quat{float(cx / n), float(cyy / n), float(cz / n), float(w / n)};
}

}  // namespace candela::ecs
