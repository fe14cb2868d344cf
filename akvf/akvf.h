#pragma once
// akvf: isometry-aware preconditioning for mesh parameterization and
// deformation (Claici, Bessmeltsev, Schaefer, Solomon, SGP 2017), as a
// library. The umbrella header of the public API:
//
//   akvf::parameterize(V, F, options)        triangle mesh -> UV map (parameterize.h)
//   akvf::Parameterizer, akvf::Deformer      repeated solves on one mesh
//   akvf::deform(V, T, constraints, options) tet mesh deformation (deform.h)
//   akvf::register_autodiff_energy<2>(...)   user-defined energies (extend.h)
//   akvf::energies_2d(), preconditioners_2d(), line_searches()   the names (catalog.h)
//   akvf::read_triangle_mesh, read_tet_mesh, write_obj_with_uv   files (framework/*_io.h)
//   akvf::InputError, ValidationError, OptionsError, NumericalError   errors (akvf/error.h)
//
// docs/api.md describes shapes, ownership, threads and errors.
#include "akvf/catalog.h"
#include "akvf/deform.h"
#include "akvf/error.h"
#include "akvf/extend.h"
#include "akvf/mesh_io.h"
#include "akvf/parameterize.h"
#include "akvf/pictures.h"
#include "akvf/tet_mesh_io.h"
#include "akvf/threads.h"
#include "akvf/version.h"
