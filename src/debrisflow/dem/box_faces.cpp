#include "debrisflow/dem/box_faces.hpp"

namespace debrisflow::dem {

WallPrimitive wall_triangle(Vec3 a, Vec3 b, Vec3 c) {
    Vec3 n = cross(b - a, c - a);
    n = (1 / norm(n)) * n;
    return {a, b, c, n, PrimitiveType::triangle, 0};
}

void box_faces(std::vector<WallPrimitive>& out, Vec3 lo, Vec3 hi, BoxFaceSet faces,
               std::int32_t solid) {
    const Vec3 p000{lo.x, lo.y, lo.z}, p100{hi.x, lo.y, lo.z}, p110{hi.x, hi.y, lo.z},
        p010{lo.x, hi.y, lo.z}, p001{lo.x, lo.y, hi.z}, p101{hi.x, lo.y, hi.z},
        p111{hi.x, hi.y, hi.z}, p011{lo.x, hi.y, hi.z};
    const auto quad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        for (WallPrimitive t : {wall_triangle(a, b, c), wall_triangle(a, c, d)}) {
            t.solid = solid;
            out.push_back(t);
        }
    };
    if (faces.bottom) quad(p000, p100, p110, p010);
    if (faces.top) quad(p001, p011, p111, p101);
    if (faces.xsides) {
        quad(p000, p010, p011, p001);
        quad(p100, p101, p111, p110);
    }
    if (faces.ysides) {
        quad(p000, p001, p101, p100);
        quad(p010, p110, p111, p011);
    }
}

} // namespace debrisflow::dem
