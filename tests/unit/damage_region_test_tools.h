// What the unit tests of DamageRegionSolver share: the names of its
// preconditioners, and (from damage_matrix_tools.h) the damage matrix of a
// model problem and its copy into a Trilinos matrix with given owned rows.
#ifndef vpcontact_tests_damage_region_test_tools_h
#define vpcontact_tests_damage_region_test_tools_h

#include <vpcontact/damage/damage_region_solver.h>

#include "damage_matrix_tools.h"

namespace VPContact
{
  namespace DamageRegionTestTools
  {
    using DamageMatrixTools::DenseMatrix;

    /// The name a test prints for a preconditioner.
    inline const char *
    name(const DamageRegionSolver::Preconditioner kind)
    {
      switch (kind)
        {
          case DamageRegionSolver::Preconditioner::incomplete_cholesky:
            return "IC(0)";
          case DamageRegionSolver::Preconditioner::modified_incomplete_cholesky:
            return "MIC(0)";
          default:
            return "modified diagonal IC (Eisenstat)";
        }
    }

    // The model problem's matrix and its copy into Trilinos, shared with
    // the tests of the damage bounds.
    using DamageMatrixTools::contiguous_rows;
    using DamageMatrixTools::copy_to_trilinos;
    using DamageMatrixTools::q1_damage_matrix;
  } // namespace DamageRegionTestTools
} // namespace VPContact

#endif
