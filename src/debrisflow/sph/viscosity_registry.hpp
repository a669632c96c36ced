#pragma once
#include "debrisflow/models/carreau_yasuda_k.hpp"
#include "debrisflow/models/registry.hpp"
#include "debrisflow/models/rheology_k.hpp"
#include "debrisflow/models/viscosity_k.hpp"

namespace debrisflow::sph {

// The viscosity models of the WCSPH solver, selectable by name (`sph.viscosity`). A model is
// a type with `name`, its traits, `acceleration` (or `apparent_viscosity` for the generalised
// Newtonian slurries) and `from_config`; adding one is its file and a line here.
using ViscosityRegistry = models::Registry<models::ArtificialViscosity, models::LaminarViscosity,
                                           models::LaminarSpsViscosity, models::BinghamViscosity,
                                           models::HerschelBulkleyViscosity, models::MuIViscosity,
                                           models::CarreauYasudaViscosity>;
using Viscosity = ViscosityRegistry::Variant;

} // namespace debrisflow::sph
