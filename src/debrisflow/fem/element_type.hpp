#pragma once
#include <string>

namespace debrisflow::fem {

// Solid element types. Node order follows VTK (and Gmsh, except tet10's last two nodes).
//  - hex8: trilinear hexahedron with Wilson-Taylor incompatible modes (9 internal modes,
//    condensed; Taylor, Beresford & Wilson 1976), free of shear locking in bending;
//  - tet4: constant-strain tetrahedron;
//  - tet10: quadratic tetrahedron (4-point rule, HRZ-lumped mass);
//  - quad4: bilinear plane-strain quadrilateral in the x-z plane with incompatible modes (QM6).
enum class ElementType { hex8, tet4, tet10, quad4 };

inline int nodes_of(ElementType t) {
    switch (t) {
    case ElementType::hex8:
        return 8;
    case ElementType::tet4:
        return 4;
    case ElementType::tet10:
        return 10;
    case ElementType::quad4:
        return 4;
    }
    return 0;
}

inline int dim_of(ElementType t) {
    return t == ElementType::quad4 ? 2 : 3;
}

inline const char* name_of(ElementType t) {
    switch (t) {
    case ElementType::hex8:
        return "hex8";
    case ElementType::tet4:
        return "tet4";
    case ElementType::tet10:
        return "tet10";
    case ElementType::quad4:
        return "quad4";
    }
    return "";
}

// VTK cell type numbers (hexahedron, tetra, quadratic tetra, quad).
inline int vtk_cell_type(ElementType t) {
    switch (t) {
    case ElementType::hex8:
        return 12;
    case ElementType::tet4:
        return 10;
    case ElementType::tet10:
        return 24;
    case ElementType::quad4:
        return 9;
    }
    return 0;
}

} // namespace debrisflow::fem
