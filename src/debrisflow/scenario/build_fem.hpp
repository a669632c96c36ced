#pragma once
#include "debrisflow/fem/fem_solver.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <memory>

namespace debrisflow::scenario {

// The mesh of a [[solid]] (built-in mesher or Gmsh file) with the case's [[node_set]] boxes.
fem::FemMesh build_fem_mesh(const io::FemSolidSpec& s, const io::CaseSpec& c);

// The FEM phase: every [[solid]] with its supports and [[fem_load]]s. A case with solids only
// takes one FEM step per global step.
std::unique_ptr<fem::FemSolver> make_fem_solver(const io::CaseSpec& c);

} // namespace debrisflow::scenario
