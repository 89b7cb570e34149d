// Sets the constrained entries of an owned vector from its other entries
// (AffineConstraints::distribute()) without a ghosted copy where none is
// needed.
#ifndef vpcontact_owned_constraints_h
#define vpcontact_owned_constraints_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * x_i = b_i + sum_j w_ij x_j for every constrained entry i of x this
   * rank owns: what constraints.distribute(x) computes.
   *
   * Why not distribute() itself: for a Trilinos vector deal.II 9.4 builds
   * a ghosted copy of the vector and an Epetra_Import into it on every
   * call, a hash lookup per index, even where every constraint reads only
   * entries the rank owns (Dirichlet and contact constraints, or any
   * constraint on one rank). The displacement increment is distributed
   * once per solve, the damage change (where the mesh has hanging nodes)
   * once per damage solve. Here the constraints are read from the owned entries
   * in place when on every rank they read only owned entries (one
   * reduction decides); otherwise distribute() runs as before. Closed
   * constraints read only unconstrained entries, so the order of the
   * writes does not matter.
   */
  void
  distribute_constraints(const AffineConstraints<double> &constraints,
                         LA::MPI::Vector                 &vector);

  /**
   * distribute_constraints() where every constraint of this rank's entries
   * is known to read only owned entries (on one rank, always): in place,
   * without the reduction that decides it, so that a thread other than the
   * one that calls MPI may run it.
   */
  void
  distribute_owned_constraints(const AffineConstraints<double> &constraints,
                               LA::MPI::Vector                 &vector);
} // namespace VPContact

#endif
