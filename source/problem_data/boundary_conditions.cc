// The section "Boundary conditions": boundary parts, their constraints, and
// the load functions.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parsed_function.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/problem_data/boundary_conditions.h>

#include <deal.II/base/utilities.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/numerics/vector_tools.h>

namespace VPContact
{
  namespace
  {
    // Read a list of boundary ids, refusing an id listed twice.
    std::set<types::boundary_id>
    parse_id_list(const ParameterHandler &prm, const std::string &entry)
    {
      std::set<types::boundary_id> ids;
      for (const int id : Utilities::string_to_int(
             Utilities::split_string_list(prm.get(entry))))
        {
          VPContactCheckParameter(ids.insert(id).second,
                                  "Boundary conditions/" + entry,
                                  prm.get(entry),
                                  "boundary id " + std::to_string(id)
                                    + " is listed twice.");
        }
      return ids;
    }

    std::string
    id_list_text(const std::set<types::boundary_id> &ids)
    {
      std::string s;
      for (const auto id : ids)
        s += (s.empty() ? "" : ",") + std::to_string(id);
      return "{" + s + "}";
    }

    // Read a list of id:components pairs, such as '0:x, 2:y', into the
    // displacement components each boundary id names in @p ids (and their
    // text in @p text), refusing an id listed twice.
    template <int dim>
    void
    parse_component_map(const ParameterHandler                      &prm,
                        const std::string                           &section,
                        const std::string                           &entry,
                        std::map<types::boundary_id, ComponentMask> &ids,
                        std::map<types::boundary_id, std::string>   &text)
    {
      ids.clear();
      text.clear();
      for (const std::string &pair :
           Utilities::split_string_list(prm.get(entry)))
        {
          const auto key_value        = Utilities::split_string_list(pair, ':');
          const types::boundary_id id = Utilities::string_to_int(key_value[0]);
          std::vector<bool>        mask(dim, false);
          for (const char c : key_value[1])
            mask[c - 'x'] = true;
          VPContactCheckParameter(ids.emplace(id, ComponentMask(mask)).second,
                                  section + "/" + entry,
                                  prm.get(entry),
                                  "boundary id " + std::to_string(id)
                                    + " is listed twice.");
          text[id] = key_value[1];
        }
    }

    // Refuse a boundary id that is in more than one of the lists: two
    // conditions on the same face would make the problem ill posed or
    // silently drop one of them. An id belongs to the first of the lists
    // (in the order of @p parts) that has it; the message names a later one.
    void
    check_one_part_per_id(
      const ParameterHandler &prm,
      const std::string      &section,
      const std::vector<std::pair<std::string, std::set<types::boundary_id>>>
        &parts)
    {
      std::map<types::boundary_id, std::string> owner;
      for (const auto &[entry, ids] : parts)
        for (const auto id : ids)
          {
            const auto [it, inserted] = owner.emplace(id, entry);
            VPContactCheckParameter(inserted,
                                    section + "/" + entry,
                                    prm.get(entry),
                                    "boundary id " + std::to_string(id)
                                      + " is also in '" + it->second
                                      + "'. A boundary id belongs to one part "
                                        "only.");
          }
    }



    // The entries of the boundary ids that carry a function of their own
    // or nothing (in the current subsection).
    void
    declare_named_load_entries(ParameterHandler &prm)
    {
      const Patterns::List id_list(Patterns::Integer(0, 254));
      prm.declare_entry(
        "Tractions",
        "",
        Patterns::Anything(),
        "Boundary ids of Gamma_N with a traction of their own, as 'id: "
        "expression' pairs separated by commas, each expression with one "
        "component per direction separated by ';', e.g. '1: 55*exp(t); 0, "
        "3: 0; -200*t' (functions of x, y (z) and t [N/m^2]). An id listed "
        "here is in no other entry, 'Traction boundary ids' included.");
      prm.declare_entry("Free boundary ids",
                        "",
                        id_list,
                        "Boundary ids that are traction free. A mesh read "
                        "from a file must name each of its boundary ids in "
                        "one of the entries of this section; on the built-in "
                        "box an id in none of them is traction free.");
    }



    template <typename Value>
    std::set<types::boundary_id>
    keys(const std::map<types::boundary_id, Value> &map)
    {
      std::set<types::boundary_id> ids;
      for (const auto &[id, value] : map)
        ids.insert(id);
      return ids;
    }



    // The mask of the finite element's @p n_components components that
    // selects the displacement components of @p displacement_mask (the
    // element may have more components than the displacement: the damage).
    template <int dim>
    ComponentMask
    on_components(const ComponentMask &displacement_mask,
                  const unsigned int   n_components)
    {
      ComponentMask mask(n_components, false);
      for (unsigned int d = 0; d < dim; ++d)
        mask.set(d, displacement_mask[d]);
      return mask;
    }

    // Constrain the listed components on the parts of @p prescribed_ids to
    // the increment of a step: g(x, @p time) minus the current nodal value
    // (of @p previous_displacement, or zero), so that u_n = g(t_n) holds
    // exactly even if u_0 did not satisfy g(0). Degrees of freedom that are
    // already constrained keep their constraint.
    template <int dim>
    void
    add_prescribed_constraints(
      const DoFHandler<dim>                             &dof_handler,
      const std::map<types::boundary_id, ComponentMask> &prescribed_ids,
      FunctionParser<dim>                               &g,
      const double                                       time,
      const LA::MPI::Vector                             *previous_displacement,
      AffineConstraints<double>                         &constraints)
    {
      const unsigned int n_components = dof_handler.get_fe().n_components();
      g.set_time(time);
      const DisplacementFunction<dim> g_on_all_components(g, n_components);
      std::map<types::global_dof_index, double> values;
      for (const auto &[id, mask] : prescribed_ids)
        VectorTools::interpolate_boundary_values(
          dof_handler,
          id,
          g_on_all_components,
          values,
          on_components<dim>(mask, n_components));
      for (const auto &[dof, value] : values)
        if (constraints.can_store_line(dof) && !constraints.is_constrained(dof))
          {
            constraints.add_line(dof);
            constraints.set_inhomogeneity(dof,
                                          value
                                            - (previous_displacement ?
                                                 (*previous_displacement)(dof) :
                                                 0.));
          }
    }
  } // namespace



  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    const Patterns::List id_list(Patterns::Integer(0, 254));
    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry("Clamped boundary ids",
                        "0",
                        id_list,
                        "Boundary ids of Gamma_D, where u = 0.");
      prm.declare_entry(
        "Roller boundary ids",
        "",
        Patterns::Map(Patterns::Integer(0, 254),
                      Patterns::Selection(dim == 2 ? "x|y" : "x|y|z|xy|xz|yz")),
        "Boundary ids where only some displacement components vanish, as "
        "id:components pairs, e.g. '0:x, 2:y' (u_x = 0 on id 0, u_y = 0 on id "
        "2). The other components are traction free.");
      prm.declare_entry(
        "Prescribed displacement boundary ids",
        "",
        Patterns::Map(Patterns::Integer(0, 254),
                      Patterns::Selection(dim == 2 ? "x|y|xy" :
                                                     "x|y|z|xy|xz|yz|xyz")),
        "Boundary ids where the listed displacement components follow "
        "'Prescribed displacement', as id:components pairs, e.g. '1:x'. The "
        "other components are traction free.");
      declare_function_entry(prm,
                             "Prescribed displacement",
                             zero_expression(dim),
                             "Displacement g(x, t) imposed on the prescribed "
                             "boundary components [m] (only the listed "
                             "components are used).");
      prm.declare_entry("Traction boundary ids",
                        "1",
                        id_list,
                        "Boundary ids of Gamma_N, where sigma nu = Traction.");
      declare_named_load_entries(prm);
      prm.declare_entry("Contact boundary ids",
                        "",
                        id_list,
                        "Boundary ids of Gamma_C, in bilateral contact "
                        "(u . nu = 0) with a foundation.");
      declare_function_entry(prm,
                             "Traction",
                             "55*exp(t); 0"
                               + std::string(dim == 3 ? "; 0" : ""),
                             "Surface traction f_N on the traction boundary "
                             "[N/m^2].");
      declare_function_entry(prm,
                             "Body force",
                             zero_expression(dim),
                             "Body force density f_B [N/m^3].");
      prm.declare_entry("Function constants",
                        "",
                        Patterns::Map(Patterns::Anything(), Patterns::Double()),
                        "Named constants for the expressions of this "
                        "section, as name:value pairs, e.g. 'p:55, E:1000'.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string section = "Boundary conditions";
    prm.enter_subsection(section);
    clamped_ids  = parse_id_list(prm, "Clamped boundary ids");
    traction_ids = parse_id_list(prm, "Traction boundary ids");
    contact_ids  = parse_id_list(prm, "Contact boundary ids");
    parse_component_map<dim>(prm,
                             section,
                             "Roller boundary ids",
                             roller_ids,
                             roller_text);
    parse_component_map<dim>(prm,
                             section,
                             "Prescribed displacement boundary ids",
                             prescribed_ids,
                             prescribed_text);
    free_ids             = parse_id_list(prm, "Free boundary ids");
    const auto constants = parse_function_constants(prm,
                                                    section,
                                                    "Function constants",
                                                    coordinate_variables(dim));
    tractions.parse(prm.get("Tractions"), section + "/Tractions", constants);
    check_one_part_per_id(prm, section, named_parts());

    traction_function
      = parse_function_entry<dim>(prm, section, "Traction", dim, constants);
    body_force_function
      = parse_function_entry<dim>(prm, section, "Body force", dim, constants);
    body_force_is_zero  = (prm.get("Body force") == zero_expression(dim));
    prescribed_function = parse_function_entry<dim>(prm,
                                                    section,
                                                    "Prescribed displacement",
                                                    dim,
                                                    constants);
    prm.leave_subsection();
  }



  template <int dim>
  std::vector<std::pair<std::string, std::set<types::boundary_id>>>
  BoundaryConditions<dim>::named_parts() const
  {
    return {{"Clamped boundary ids", clamped_ids},
            {"Roller boundary ids", keys(roller_ids)},
            {"Prescribed displacement boundary ids", keys(prescribed_ids)},
            {"Traction boundary ids", traction_ids},
            {"Tractions", tractions.ids()},
            {"Contact boundary ids", contact_ids},
            {"Free boundary ids", free_ids}};
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_against_mesh(
    const std::set<types::boundary_id> &mesh_ids,
    const std::string                  &mesh_source) const
  {
    std::set<types::boundary_id> unnamed = mesh_ids;
    for (const auto &[entry, ids] : named_parts())
      for (const auto id : ids)
        {
          VPContactCheckParameter(mesh_ids.count(id) == 1,
                                  "Boundary conditions/" + entry,
                                  std::to_string(id),
                                  "the mesh has no boundary with this id; its "
                                  "boundary ids are "
                                    + id_list_text(mesh_ids) + ".");
          unnamed.erase(id);
        }
    // A face the user forgot would otherwise get a condition without a
    // word: traction free, or clamped through the default id 0.
    AssertThrow(
      unnamed.empty() || mesh_source.empty(),
      ExcMessage(
        mesh_source + ": the mesh has the boundary ids "
        + id_list_text(mesh_ids) + ", and " + id_list_text(unnamed)
        + " is named by no entry of the section Boundary conditions. Name "
          "every boundary id of the mesh once: in Clamped, Roller, "
          "Prescribed displacement, Traction or Contact boundary ids, in "
          "Tractions, or in Free boundary ids (traction free)."));
  }



  template <int dim>
  void
  BoundaryConditions<dim>::make_constraints(
    const DoFHandler<dim>     &dof_handler,
    AffineConstraints<double> &constraints,
    const double               time,
    const LA::MPI::Vector     *previous_displacement,
    const bool                 bilateral_contact) const
  {
    // Dirichlet parts first: interpolate_boundary_values leaves alone the
    // degrees of freedom that are already constrained, and so does the
    // normal-flux function below, so whatever is constrained first wins.
    // Clamping first makes "the clamp wins at a corner" hold.
    //
    // The element may have more components than the displacement (the
    // damage): functions and masks cover all of them, and only the
    // displacement components are ever selected.
    const unsigned int n_components = dof_handler.get_fe().n_components();
    const Functions::ZeroFunction<dim> zero(n_components);
    const ComponentMask                all_displacements
      = on_components<dim>(ComponentMask(dim, true), n_components);
    for (const auto id : clamped_ids)
      VectorTools::interpolate_boundary_values(dof_handler,
                                               id,
                                               zero,
                                               constraints,
                                               all_displacements);
    for (const auto &[id, mask] : roller_ids)
      VectorTools::interpolate_boundary_values(
        dof_handler,
        id,
        zero,
        constraints,
        on_components<dim>(mask, n_components));

    if (!prescribed_ids.empty())
      add_prescribed_constraints(dof_handler,
                                 prescribed_ids,
                                 *prescribed_function,
                                 time,
                                 previous_displacement,
                                 constraints);

    if (bilateral_contact && !contact_ids.empty())
      VectorTools::compute_no_normal_flux_constraints(
        dof_handler,
        0,
        contact_ids,
        constraints,
        get_default_linear_mapping(dof_handler.get_triangulation()));
  }



  template <int dim>
  bool
  BoundaryConditions<dim>::has_prescribed_displacement() const
  {
    return !prescribed_ids.empty();
  }



  template <int dim>
  bool
  BoundaryConditions<dim>::is_traction_boundary(
    const types::boundary_id id) const
  {
    return traction_ids.count(id) == 1 || tractions.has(id);
  }



  template <int dim>
  bool
  BoundaryConditions<dim>::has_contact_boundary() const
  {
    return !contact_ids.empty();
  }



  template <int dim>
  const std::set<types::boundary_id> &
  BoundaryConditions<dim>::contact_boundary_ids() const
  {
    return contact_ids;
  }



  template <int dim>
  const Function<dim> &
  BoundaryConditions<dim>::traction(const types::boundary_id id) const
  {
    return tractions.has(id) ? tractions.function(id) : *traction_function;
  }



  template <int dim>
  const Function<dim> &
  BoundaryConditions<dim>::body_force() const
  {
    return *body_force_function;
  }



  template <int dim>
  bool
  BoundaryConditions<dim>::has_body_force() const
  {
    return !body_force_is_zero;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::set_time(const double time)
  {
    traction_function->set_time(time);
    tractions.set_time(time);
    body_force_function->set_time(time);
  }



  template <int dim>
  std::string
  BoundaryConditions<dim>::summary() const
  {
    std::string rollers;
    for (const auto &[id, text] : roller_text)
      rollers += (rollers.empty() ? "" : ",") + std::to_string(id) + ":" + text;
    std::set<types::boundary_id> loaded = traction_ids;
    for (const auto id : tractions.ids())
      loaded.insert(id);
    return "clamped " + id_list_text(clamped_ids) + ", rollers {" + rollers
           + "}, traction " + id_list_text(loaded) + ", contact "
           + id_list_text(contact_ids)
           + (free_ids.empty() ? "" : ", free " + id_list_text(free_ids));
  }



  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace VPContact
