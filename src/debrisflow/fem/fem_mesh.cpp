#include "debrisflow/fem/fem_mesh.hpp"
#include "debrisflow/core/error.hpp"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace debrisflow::fem {

namespace {

Real tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return dot(b - a, cross(c - a, d - a)) / 6;
}

// Linear mesh on the unit cube [0,1]^3 (or unit square in x-z): hex8, tet4 or quad4.
FemMesh unit_mesh(ElementType t, std::array<int, 3> n) {
    FemMesh m;
    m.type = t == ElementType::tet10 ? ElementType::tet4 : t;
    const bool flat = t == ElementType::quad4;
    const int nx = n[0], ny = flat ? 0 : n[1], nz = n[2];
    auto id = [&](int i, int j, int k) { return std::int32_t((k * (ny + 1) + j) * (nx + 1) + i); };
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                m.nodes.push_back({Real(i) / nx, flat ? 0 : Real(j) / ny, Real(k) / nz});
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < std::max(ny, 1); ++j)
            for (int i = 0; i < nx; ++i) {
                if (flat) {
                    m.conn.insert(m.conn.end(), {id(i, 0, k), id(i + 1, 0, k), id(i + 1, 0, k + 1),
                                                 id(i, 0, k + 1)});
                    continue;
                }
                const std::int32_t h[8] = {id(i, j, k),
                                           id(i + 1, j, k),
                                           id(i + 1, j + 1, k),
                                           id(i, j + 1, k),
                                           id(i, j, k + 1),
                                           id(i + 1, j, k + 1),
                                           id(i + 1, j + 1, k + 1),
                                           id(i, j + 1, k + 1)};
                if (t == ElementType::hex8) {
                    m.conn.insert(m.conn.end(), h, h + 8);
                    continue;
                }
                // Six tetrahedra about the diagonal 0-6 (conforming between neighbours).
                constexpr int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                            {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
                for (const auto& tt : tets) {
                    std::int32_t v[4] = {h[tt[0]], h[tt[1]], h[tt[2]], h[tt[3]]};
                    if (tet_volume(m.nodes[std::size_t(v[0])], m.nodes[std::size_t(v[1])],
                                   m.nodes[std::size_t(v[2])], m.nodes[std::size_t(v[3])]) < 0)
                        std::swap(v[1], v[2]);
                    m.conn.insert(m.conn.end(), v, v + 4);
                }
            }
    return m;
}

// tet4 -> tet10: a node at the midpoint of each edge (shared between elements); a mid node
// joins every node set holding both ends.
void elevate_to_tet10(FemMesh& m) {
    constexpr int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
    std::unordered_map<std::uint64_t, std::int32_t> mid;
    std::vector<std::int32_t> conn;
    std::vector<std::pair<std::int32_t, std::int32_t>> ends;
    const std::size_t ne = m.conn.size() / 4;
    for (std::size_t e = 0; e < ne; ++e) {
        const std::int32_t* v = &m.conn[4 * e];
        conn.insert(conn.end(), v, v + 4);
        for (const auto& ed : edges) {
            const std::int32_t a = std::min(v[ed[0]], v[ed[1]]), b = std::max(v[ed[0]], v[ed[1]]);
            const std::uint64_t key = (std::uint64_t(a) << 32) | std::uint32_t(b);
            auto [it, fresh] = mid.emplace(key, std::int32_t(m.nodes.size()));
            if (fresh) {
                m.nodes.push_back(Real(0.5) * (m.nodes[std::size_t(a)] + m.nodes[std::size_t(b)]));
                ends.push_back({a, b});
            }
            conn.push_back(it->second);
        }
    }
    const std::int32_t first_mid = std::int32_t(m.nodes.size() - ends.size());
    for (auto& [name, set] : m.node_sets) {
        std::vector<char> in(m.nodes.size(), 0);
        for (auto i : set) in[std::size_t(i)] = 1;
        for (std::size_t k = 0; k < ends.size(); ++k)
            if (in[std::size_t(ends[k].first)] && in[std::size_t(ends[k].second)])
                set.push_back(first_mid + std::int32_t(k));
    }
    m.conn = std::move(conn);
    m.type = ElementType::tet10;
}

void face_sets(FemMesh& m, const char* const names[6]) {
    for (int f = 0; f < 6; ++f) {
        const int axis = f / 2;
        const Real at = f % 2 ? 1 : 0;
        if (m.type == ElementType::quad4 && axis == 1) continue;
        auto& set = m.node_sets[names[f]];
        for (std::size_t i = 0; i < m.nodes.size(); ++i)
            if (std::fabs(m.nodes[i][axis] - at) < 1e-9) set.push_back(std::int32_t(i));
    }
}

} // namespace

std::vector<std::int32_t> FemMesh::nodes_in(Vec3 lo, Vec3 hi, Real tol) const {
    std::vector<std::int32_t> out;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        bool in = true;
        for (int k = 0; k < 3; ++k)
            in = in && nodes[i][k] >= lo[k] - tol && nodes[i][k] <= hi[k] + tol;
        if (in) out.push_back(std::int32_t(i));
    }
    return out;
}

FemMesh box_mesh(ElementType t, Vec3 lo, Vec3 hi, std::array<int, 3> n) {
    FemMesh m = unit_mesh(t, n);
    static const char* const names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
    face_sets(m, names);
    for (auto& p : m.nodes)
        p = {lo.x + p.x * (hi.x - lo.x), t == ElementType::quad4 ? 0 : lo.y + p.y * (hi.y - lo.y),
             lo.z + p.z * (hi.z - lo.z)};
    if (t == ElementType::tet10) elevate_to_tet10(m);
    return m;
}

FemMesh trapezoid_mesh(ElementType t, const TrapezoidSpec& s, std::array<int, 3> n) {
    FemMesh m = unit_mesh(t, n);
    static const char* const names[6] = {"upstream", "downstream", "left",
                                         "right",    "base",       "crest"};
    face_sets(m, names);
    for (auto& p : m.nodes) {
        const Real x_left = s.x0 + p.z * s.upstream_offset;
        const Real x_right =
            s.x0 + s.base_width + p.z * (s.upstream_offset + s.crest_width - s.base_width);
        p = {x_left + p.x * (x_right - x_left), t == ElementType::quad4 ? 0 : s.y0 + p.y * s.length,
             s.z0 + p.z * s.height};
    }
    if (t == ElementType::tet10) elevate_to_tet10(m);
    return m;
}

FemMesh read_gmsh(const std::string& path, ElementType t) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": mesh file not found");
    auto fail = [&](const std::string& why) { throw InputError(path + ": " + why); };
    // Every count in the file is bounded by the file's size (each item takes bytes of it), and
    // every read is checked, so a corrupt count can neither allocate nor loop without end.
    std::error_code size_error;
    const auto file_bytes = long(std::filesystem::file_size(path, size_error));
    auto count = [&](long n, const char* section) {
        if (!in) fail(fmt::format("malformed or truncated {} section", section));
        if (n < 0 || n > file_bytes)
            fail(fmt::format("{} count {} is impossible in a file of {} bytes", section, n,
                             file_bytes));
        return n;
    };
    auto ok = [&](const char* section) {
        if (!in) fail(fmt::format("malformed or truncated {} section", section));
    };
    const int want = t == ElementType::quad4  ? 3
                     : t == ElementType::tet4 ? 4
                     : t == ElementType::hex8 ? 5
                                              : 11;
    const int per = nodes_of(t);
    std::map<int, std::string> phys_names;                       // tag -> name
    std::map<std::pair<int, int>, std::vector<int>> entity_phys; // (dim, tag) -> physical tags
    std::unordered_map<long, Vec3> coords;
    std::vector<long> raw_conn;
    std::map<std::string, std::vector<long>> raw_sets;
    std::string line;
    bool version_ok = false;
    while (std::getline(in, line)) {
        if (line == "$MeshFormat") {
            double version = 0;
            int binary = 0;
            in >> version >> binary;
            ok("$MeshFormat");
            if (version < 4 || version >= 5)
                fail(fmt::format("MSH version {} (need 4.x)", version));
            if (binary) fail("binary MSH (save as ASCII: gmsh -save_all -format msh4)");
            version_ok = true;
        } else if (line == "$PhysicalNames") {
            long n = 0;
            in >> n;
            count(n, "$PhysicalNames");
            for (long k = 0; k < n; ++k) {
                int dim, tag;
                std::string name;
                in >> dim >> tag;
                std::getline(in, name);
                ok("$PhysicalNames");
                const auto a = name.find('"'), b = name.rfind('"');
                phys_names[tag] =
                    a != std::string::npos && b > a ? name.substr(a + 1, b - a - 1) : name;
            }
        } else if (line == "$Entities") {
            long counts[4] = {0, 0, 0, 0};
            in >> counts[0] >> counts[1] >> counts[2] >> counts[3];
            for (long n : counts) count(n, "$Entities");
            for (int dim = 0; dim < 4; ++dim)
                for (long k = 0; k < counts[dim]; ++k) {
                    int tag = 0;
                    double box[6];
                    in >> tag;
                    for (int b = 0; b < (dim == 0 ? 3 : 6); ++b) in >> box[b];
                    long np = 0;
                    in >> np;
                    count(np, "$Entities");
                    auto& tags = entity_phys[{dim, tag}];
                    for (long p = 0; p < np; ++p) {
                        int ptag = 0;
                        in >> ptag;
                        ok("$Entities");
                        tags.push_back(std::abs(ptag));
                    }
                    if (dim > 0) {
                        long nb = 0;
                        in >> nb;
                        count(nb, "$Entities");
                        for (long b = 0; b < nb; ++b) {
                            int btag;
                            in >> btag;
                            ok("$Entities");
                        }
                    }
                }
        } else if (line == "$Nodes") {
            long blocks = 0, total = 0, lo, hi;
            in >> blocks >> total >> lo >> hi;
            count(blocks, "$Nodes");
            count(total, "$Nodes");
            for (long b = 0; b < blocks; ++b) {
                int edim = 0, etag, param = 0;
                long n = 0;
                in >> edim >> etag >> param >> n;
                count(n, "$Nodes");
                if (edim < 0 || edim > 3) fail("$Nodes: entity dimension must be 0..3");
                std::vector<long> tags(static_cast<std::size_t>(n));
                for (auto& tg : tags) in >> tg;
                ok("$Nodes");
                for (long k = 0; k < n; ++k) {
                    Vec3 p;
                    in >> p.x >> p.y >> p.z;
                    if (param)
                        for (int d = 0; d < edim; ++d) {
                            double u;
                            in >> u;
                        }
                    ok("$Nodes");
                    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                        fail(fmt::format("$Nodes: node {} has a non-finite coordinate",
                                         tags[std::size_t(k)]));
                    coords[tags[std::size_t(k)]] = p;
                }
            }
        } else if (line == "$Elements") {
            long blocks = 0, total = 0, lo, hi;
            in >> blocks >> total >> lo >> hi;
            count(blocks, "$Elements");
            count(total, "$Elements");
            for (long b = 0; b < blocks; ++b) {
                int edim, etag, type;
                long n = 0;
                in >> edim >> etag >> type >> n;
                count(n, "$Elements");
                std::getline(in, line);
                const auto phys = entity_phys.find({edim, etag});
                for (long k = 0; k < n; ++k) {
                    std::getline(in, line);
                    ok("$Elements");
                    std::istringstream ls(line);
                    long tag, v;
                    ls >> tag;
                    std::vector<long> nodes;
                    while (ls >> v) nodes.push_back(v);
                    if (type == want) {
                        if (int(nodes.size()) != per)
                            fail(fmt::format("element {} has {} nodes", tag, nodes.size()));
                        if (t == ElementType::tet10) std::swap(nodes[8], nodes[9]); // Gmsh -> VTK
                        raw_conn.insert(raw_conn.end(), nodes.begin(), nodes.end());
                    }
                    if (phys != entity_phys.end())
                        for (int p : phys->second) {
                            const auto nm =
                                phys_names.count(p) ? phys_names[p] : fmt::format("physical_{}", p);
                            auto& set = raw_sets[nm];
                            set.insert(set.end(), nodes.begin(), nodes.end());
                        }
                }
            }
        }
    }
    if (!version_ok) fail("no $MeshFormat section (not a Gmsh MSH file)");
    if (raw_conn.empty()) fail(fmt::format("no {} elements in the mesh", name_of(t)));
    FemMesh m;
    m.type = t;
    std::unordered_map<long, std::int32_t> index;
    for (long tag : raw_conn) {
        auto [it, fresh] = index.emplace(tag, std::int32_t(m.nodes.size()));
        if (fresh) {
            const auto c = coords.find(tag);
            if (c == coords.end()) fail(fmt::format("element node {} has no coordinates", tag));
            Vec3 p = c->second;
            if (t == ElementType::quad4) p = {p.x, 0, p.y};
            m.nodes.push_back(p);
        }
        m.conn.push_back(it->second);
    }
    for (auto& [name, raw] : raw_sets) {
        auto& set = m.node_sets[name];
        for (long tag : raw) {
            const auto it = index.find(tag);
            if (it != index.end()) set.push_back(it->second);
        }
        std::sort(set.begin(), set.end());
        set.erase(std::unique(set.begin(), set.end()), set.end());
    }
    // Gmsh quads and tets may come with either orientation: make every element positive.
    for (std::size_t e = 0; e < m.elements(); ++e) {
        std::int32_t* v = &m.conn[e * std::size_t(per)];
        if (t == ElementType::tet4 || t == ElementType::tet10) {
            if (tet_volume(m.nodes[std::size_t(v[0])], m.nodes[std::size_t(v[1])],
                           m.nodes[std::size_t(v[2])], m.nodes[std::size_t(v[3])]) < 0) {
                std::swap(v[1], v[2]);
                if (t == ElementType::tet10) { // edges (0,1)<->(0,2), (1,3)<->(2,3)
                    std::swap(v[4], v[6]);
                    std::swap(v[8], v[9]);
                }
            }
        } else if (t == ElementType::quad4) {
            const Vec3 a = m.nodes[std::size_t(v[1])] - m.nodes[std::size_t(v[0])];
            const Vec3 b = m.nodes[std::size_t(v[3])] - m.nodes[std::size_t(v[0])];
            if (a.x * b.z - a.z * b.x < 0) std::swap(v[1], v[3]); // counter-clockwise in (x, z)
        }
    }
    return m;
}

} // namespace debrisflow::fem
