// SupernodalSubstitution: the forward and backward substitutions with a
// supernodal Cholesky factor of CHOLMOD, for one right-hand side.
#ifndef vpcontact_supernodal_substitution_h
#define vpcontact_supernodal_substitution_h

#include <cholmod.h>
#include <cstddef>
#include <vector>

namespace VPContact
{
  /**
   * x = K^{-1} b with the factors P K P^T = L L^T of a supernodal CHOLMOD
   * factorization, as cholmod_solve2() computes it, in one pass through L
   * for each of the two triangular substitutions.
   *
   * With one right-hand side every entry of L is used once, so a
   * substitution is a stream through the factor. cholmod_solve2() hands
   * each supernode to the BLAS (dtrsv, dgemv): on a 2D mesh most supernodes
   * have a few dozen columns, and the calls cost about as much as the
   * arithmetic. Here a supernode's unknowns and its rows below are gathered
   * into one block, each column of L is one vectorised loop over entries
   * stored one after the other, and the two passes are compiled twice, for
   * x86-64-v3 processors (AVX2 and FMA; the loader picks this version on
   * such a processor) and for any other.
   *
   * The factor must stay unchanged and alive between initialize() and the
   * last solve(). solve() allocates nothing and is not reentrant: one solve
   * at a time.
   */
  class SupernodalSubstitution
  {
  public:
    /// Takes @p factor (supernodal, L L^T) and allocates the workspace.
    void
    initialize(const cholmod_factor &factor);

    /// target = K^{-1} source, both of the factor's size.
    void
    solve(const double *source, double *target) const;

  private:
    const cholmod_factor *factor = nullptr;
    /// 1 / L_jj: a substitution multiplies where it would divide.
    std::vector<double> inverse_diagonal;
    /// The permuted right-hand side, solved in place.
    mutable std::vector<double> permuted;
    /// One supernode's unknowns and rows below.
    mutable std::vector<double> block;
  };
} // namespace VPContact

#endif
