// The boundary parts of the body (clamped, rollers, traction, contact) and
// the loads: body force and surface traction as parsed functions of x and t.
#ifndef vpcontact_boundary_conditions_h
#define vpcontact_boundary_conditions_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/problem_data/boundary_functions.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <map>
#include <memory>
#include <set>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Boundary conditions".
   *
   * Every boundary id of the mesh belongs to at most one part:
   * - clamped (Gamma_D): u = 0;
   * - rollers: the listed displacement components vanish, the others are
   *   traction free (a symmetry plane, or the supports of a tension test);
   * - prescribed displacement: the listed components follow the function
   *   "Prescribed displacement" g(x, t), the others are traction free
   *   (displacement-controlled loading);
   * - traction (Gamma_N): sigma nu = f_N(x, t), one function for the ids
   *   of "Traction boundary ids" and one of its own for each id of
   *   "Tractions";
   * - contact (Gamma_C): bilateral contact u . nu = 0 with the constraint
   *   built for any boundary shape by
   *   VectorTools::compute_no_normal_flux_constraints.
   * - free: traction free.
   * A mesh read from a file must name each of its boundary ids in one list;
   * on the built-in box an id in none is traction free. Where a contact node
   * also lies on a clamped or roller part (a corner), the Dirichlet condition
   * wins.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Stop with a message naming the parameter if a listed boundary id does
     * not exist in the mesh, whose ids are @p mesh_ids, and, for a mesh
     * read from a file (@p mesh_source names it, "" for the built-in box),
     * if an id of the mesh is in no list.
     */
    void
    check_against_mesh(const std::set<types::boundary_id> &mesh_ids,
                       const std::string                  &mesh_source) const;

    /**
     * Add the constraints of the clamped, roller, prescribed and contact
     * parts to @p constraints (which must already hold the hanging node
     * constraints). The unknown of a time step is the displacement increment
     * u_n - u_{n-1}: on the prescribed part it is g(x, @p time) minus the
     * nodal values of @p previous_displacement (a ghosted vector; nullptr
     * stands for zero); all other constraints are homogeneous. The contact
     * part's normal constraint u.nu = 0 is added only for
     * @p bilateral_contact (unilateral contact leaves the normal to the
     * contact's active set).
     */
    void
    make_constraints(const DoFHandler<dim>     &dof_handler,
                     AffineConstraints<double> &constraints,
                     const double               time,
                     const LA::MPI::Vector     *previous_displacement,
                     const bool                 bilateral_contact) const;

    /// Whether the constraints change with time (prescribed displacements).
    bool
    has_prescribed_displacement() const;

    bool
    is_traction_boundary(const types::boundary_id id) const;

    bool
    has_contact_boundary() const;

    const std::set<types::boundary_id> &
    contact_boundary_ids() const;

    /// f_N on the boundary @p id, with dim components, time set by
    /// set_time().
    const Function<dim> &
    traction(const types::boundary_id id) const;

    /// f_B, with dim components, time set by set_time().
    const Function<dim> &
    body_force() const;

    bool
    has_body_force() const;

    /// Set the time of the load functions.
    void
    set_time(const double time);

    /// A one-line description of the boundary parts for the screen.
    std::string
    summary() const;

  private:
    /// Each list of boundary ids with the name of its entry.
    std::vector<std::pair<std::string, std::set<types::boundary_id>>>
    named_parts() const;

    std::set<types::boundary_id>                clamped_ids;
    std::map<types::boundary_id, ComponentMask> roller_ids;
    std::map<types::boundary_id, std::string>   roller_text;
    std::map<types::boundary_id, ComponentMask> prescribed_ids;
    std::map<types::boundary_id, std::string>   prescribed_text;
    std::unique_ptr<FunctionParser<dim>>        prescribed_function;
    std::set<types::boundary_id>                traction_ids;
    std::set<types::boundary_id>                contact_ids;
    std::unique_ptr<FunctionParser<dim>>        traction_function;
    BoundaryFunctions<dim>                      tractions;
    std::set<types::boundary_id>                free_ids;
    std::unique_ptr<FunctionParser<dim>>        body_force_function;
    bool                                        body_force_is_zero = true;
  };
} // namespace VPContact

#endif
