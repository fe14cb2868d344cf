#pragma once
// User-defined parts, registered by name at run time and then used
// everywhere the built-in ones are: ParameterizeOptions::energy and
// ::preconditioner, DeformOptions, experiment manifests run in the same
// process, akvf::energies_2d().entries() listings. Register before runs
// start (registries are not guarded against concurrent use); a name that is
// taken is an OptionsError. docs/extending.md has worked examples.
#include <memory>
#include <set>
#include <string>

#include "akvf/autodiff_density.h"
#include "akvf/catalog.h"

namespace akvf {

// An energy from its density alone: `functor` maps J (Dim x Dim, scalar
// type T, det J > 0) to D(J), written once as a template over T (see
// akvf/autodiff_density.h); gradient, Hessian, PSD projection and the
// singular-value derivative SLIM needs come from automatic differentiation.
// `lower_bound` is inf_J D(J) (the value at J = I for isometric energies),
// reported as the energy's lower bound. `tags`: facts about the energy the
// library asks for (akvf/catalog.h): {kCollapseBarrier} when D grows without
// bound as det J falls to 0, so the default method takes its local Newton
// sweeps (--local-sweep auto) as for the built-in barrier energies.
template <int Dim, class Functor>
void register_autodiff_energy(const std::string& name, const std::string& description, double lower_bound,
                              Functor functor, std::set<std::string> tags = {}) {
  static_assert(Dim == 2 || Dim == 3, "densities are 2D (parameterization) or 3D (deformation)");
  auto factory = [name, lower_bound, functor](const EnergySettings&) {
    return std::make_unique<AutodiffDensity<Dim, Functor>>(name, lower_bound, functor);
  };
  if constexpr (Dim == 2)
    mutable_energies_2d().add(name, description, factory, std::move(tags));
  else
    mutable_energies_3d().add(name, description, factory, std::move(tags));
}

// Any DistortionDensity (hand-written derivatives; `tags` as above), or any
// Preconditioner, through its factory. A 2D preconditioner is built from the objective and
// the settings: (const MeshObjective2D&, const PreconditionerSettings2D&).
inline void register_energy_2d(const std::string& name, const std::string& description,
                               DensityRegistry2D::Factory factory, std::set<std::string> tags = {}) {
  mutable_energies_2d().add(name, description, std::move(factory), std::move(tags));
}
inline void register_energy_3d(const std::string& name, const std::string& description,
                               DensityRegistry3D::Factory factory, std::set<std::string> tags = {}) {
  mutable_energies_3d().add(name, description, std::move(factory), std::move(tags));
}
inline void register_preconditioner_2d(const std::string& name, const std::string& description,
                                       PreconditionerRegistry2D::Factory factory) {
  mutable_preconditioners_2d().add(name, description, std::move(factory));
}
inline void register_preconditioner_3d(const std::string& name, const std::string& description,
                                       PreconditionerRegistry3D::Factory factory) {
  mutable_preconditioners_3d().add(name, description, std::move(factory));
}
// A line search, from the line-search settings (akvf/line_search.h).
inline void register_line_search(const std::string& name, const std::string& description,
                                 LineSearchRegistry::Factory factory) {
  mutable_line_searches().add(name, description, std::move(factory));
}

}  // namespace akvf
