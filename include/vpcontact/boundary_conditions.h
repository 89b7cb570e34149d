// The boundary parts of the body (clamped, rollers, traction, contact) and
// the loads: body force and surface traction as parsed functions of x and t.
#ifndef vpcontact_boundary_conditions_h
#define vpcontact_boundary_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

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
   * - traction (Gamma_N): sigma nu = f_N(x, t);
   * - contact (Gamma_C): bilateral contact u . nu = 0 with the constraint
   *   built for any boundary shape by
   *   VectorTools::compute_no_normal_flux_constraints.
   * Ids in no list are traction free. Where a contact node also lies on a
   * clamped or roller part (a corner), the Dirichlet condition wins.
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
     * not exist in the mesh, whose ids are @p mesh_ids.
     */
    void
    check_against_mesh(const std::set<types::boundary_id> &mesh_ids) const;

    /**
     * Add the homogeneous constraints of the clamped, roller and contact parts
     * to @p constraints (which must already hold the hanging node
     * constraints).
     */
    void
    make_constraints(const DoFHandler<dim>     &dof_handler,
                     AffineConstraints<double> &constraints) const;

    bool
    is_traction_boundary(const types::boundary_id id) const;

    bool
    has_contact_boundary() const;

    const std::set<types::boundary_id> &
    contact_boundary_ids() const;

    /// f_N, with dim components, time set by set_time().
    const Function<dim> &
    traction() const;

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
    std::set<types::boundary_id>                clamped_ids;
    std::map<types::boundary_id, ComponentMask> roller_ids;
    std::map<types::boundary_id, std::string>   roller_text;
    std::set<types::boundary_id>                traction_ids;
    std::set<types::boundary_id>                contact_ids;
    std::unique_ptr<FunctionParser<dim>>        traction_function;
    std::unique_ptr<FunctionParser<dim>>        body_force_function;
    bool                                        body_force_is_zero = true;
  };
} // namespace VPContact

#endif
