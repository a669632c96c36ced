#include "debrisflow/scenario/stl_mesh.hpp"
#include "debrisflow/core/error.hpp"
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace debrisflow::scenario {

Vec3 Triangle::normal() const {
    Vec3 n = cross(b - a, c - a);
    const Real l = norm(n);
    return l > 0 ? (1 / l) * n : n;
}

namespace {

bool read_binary(const std::string& bytes, std::vector<Triangle>& out, Real s, Vec3 o) {
    if (bytes.size() < 84) return false;
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (bytes.size() != 84 + std::size_t(n) * 50) return false;
    for (std::uint32_t i = 0; i < n; ++i) {
        float v[12];
        std::memcpy(v, bytes.data() + 84 + std::size_t(i) * 50, sizeof v);
        auto pt = [&](int k) { return Vec3{s * v[k], s * v[k + 1], s * v[k + 2]} + o; };
        out.push_back({pt(3), pt(6), pt(9)});
    }
    return true;
}

void read_ascii(const std::string& path, const std::string& text, std::vector<Triangle>& out,
                Real s, Vec3 o) {
    std::istringstream in(text);
    std::string word;
    std::vector<Vec3> verts;
    long line_hint = 0;
    while (in >> word) {
        if (word == "vertex") {
            Vec3 v;
            if (!(in >> v.x >> v.y >> v.z))
                throw InputError(path + ": malformed 'vertex' line in ASCII STL (facet " +
                                 std::to_string(line_hint) + ")");
            verts.push_back(s * v + o);
        } else if (word == "endfacet") {
            if (verts.size() != 3)
                throw InputError(path + ": facet " + std::to_string(line_hint) +
                                 " does not have three vertices");
            out.push_back({verts[0], verts[1], verts[2]});
            verts.clear();
            ++line_hint;
        }
    }
}

} // namespace

TriangleMesh TriangleMesh::read_stl(const std::string& path, Real scale, Vec3 offset) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path + ": cannot open mesh file");
    std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    TriangleMesh m;
    if (!read_binary(bytes, m.triangles, scale, offset)) {
        if (bytes.rfind("solid", 0) != 0)
            throw InputError(path + ": neither a binary STL nor an ASCII STL ('solid ...')");
        read_ascii(path, bytes, m.triangles, scale, offset);
    }
    if (m.triangles.empty()) throw InputError(path + ": mesh has no triangles");
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
        for (const Vec3& v : {m.triangles[k].a, m.triangles[k].b, m.triangles[k].c})
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                throw InputError(path + ": facet " + std::to_string(k) +
                                 " has a vertex that is not a finite number (after scale and "
                                 "offset)");
    return m;
}

void TriangleMesh::bounds(Vec3& lo, Vec3& hi) const {
    const Real big = std::numeric_limits<Real>::max();
    lo = {big, big, big};
    hi = {-big, -big, -big};
    for (const auto& t : triangles)
        for (const Vec3& v : {t.a, t.b, t.c})
            for (int d = 0; d < 3; ++d) {
                lo[d] = std::min(lo[d], v[d]);
                hi[d] = std::max(hi[d], v[d]);
            }
}

bool TriangleMesh::contains(Vec3 p) const {
    // Majority of three ray-parity tests along unrelated directions, so that a ray grazing an
    // edge or a vertex cannot decide alone.
    const Vec3 dirs[3] = {{0.5773503, 0.2113249, 0.7886751},
                          {-0.3826834, 0.8535534, 0.3535534},
                          {0.7071068, -0.4082483, -0.5773503}};
    int inside = 0;
    for (const Vec3& d : dirs) inside += crossings(p, d) % 2;
    return inside >= 2;
}

int TriangleMesh::crossings(Vec3 p, Vec3 dir) const {
    // Moller-Trumbore ray-triangle intersection, counting hits with t > 0.
    int hits = 0;
    for (const auto& t : triangles) {
        const Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
        const Vec3 pv = cross(dir, e2);
        const Real det = dot(e1, pv);
        if (std::abs(det) < 1e-14) continue;
        const Real inv = 1 / det;
        const Vec3 tv = p - t.a;
        const Real u = dot(tv, pv) * inv;
        if (u < 0 || u > 1) continue;
        const Vec3 qv = cross(tv, e1);
        const Real v = dot(dir, qv) * inv;
        if (v < 0 || u + v > 1) continue;
        if (dot(e2, qv) * inv > 0) ++hits;
    }
    return hits;
}

} // namespace debrisflow::scenario
