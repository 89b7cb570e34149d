// Unit test: the start vector of the displacement solve (IncrementPredictor).
// The polynomial extrapolation of degree p through the last p + 1 increments
// reproduces increments that are themselves a polynomial of degree p in the
// step number, exactly; a polynomial of higher degree is missed. Until p + 1
// increments are recorded the degree is lowered, and degree 0 leaves the
// previous increment as it is. A jump (the first step's increment a hundred
// times the next ones, as from the paper's u_0 = 0) restarts the history:
// the later predictions use only the increments after it, and are exact
// again from n = 4 on.
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/simulator/increment_predictor.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <functional>
#include <iostream>

using namespace VPContact;

namespace
{
  // Two entries per step n: w_n = (f(n), 2 f(n)).
  LA::MPI::Vector
  increment(const IndexSet                      &owned,
            const std::function<double(double)> &f,
            const int                            n)
  {
    LA::MPI::Vector w(owned, MPI_COMM_WORLD);
    w(0) = f(n);
    w(1) = 2 * f(n);
    w.compress(VectorOperation::insert);
    return w;
  }

  void
  check(const unsigned int                   degree,
        const std::string                   &name,
        const std::function<double(double)> &f)
  {
    ParameterHandler prm;
    IncrementPredictor::declare_parameters(prm);
    prm.enter_subsection("Solver");
    prm.set("Start vector extrapolation degree", std::to_string(degree));
    prm.leave_subsection();
    IncrementPredictor predictor;
    predictor.parse_parameters(prm);
    IndexSet owned = complete_index_set(2);
    predictor.reinit(owned, MPI_COMM_WORLD);

    std::cout << "degree " << degree << ", w_n = " << name << ":";
    for (int n = 1; n <= 5; ++n)
      {
        // The solver's vector holds w_{n-1} before the prediction.
        LA::MPI::Vector start = increment(owned, f, n - 1);
        predictor.predict(start);
        const double error
          = std::abs(start(0) - f(n)) + std::abs(start(1) - 2 * f(n));
        std::cout << "  n = " << n << ": error "
                  << (error < 1e-12 ? std::string("0") : std::to_string(error));
        predictor.record(increment(owned, f, n));
      }
    std::cout << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       constant = [](double) { return 3.; };
  const auto linear    = [](double n) { return 1. + 0.5 * n; };
  const auto quadratic = [](double n) { return 1. + 0.5 * n - 0.25 * n * n; };
  const auto cubic     = [](double n) { return n * n * n; };
  const auto jump
    = [](double n) { return n == 0 ? 0. : (n == 1 ? 100. : 1. + 0.5 * n); };
  check(0, "3", constant);
  check(0, "1 + n/2", linear);
  check(1, "1 + n/2", linear);
  check(1, "1 + n/2 - n^2/4", quadratic);
  check(2, "1 + n/2 - n^2/4", quadratic);
  check(2, "n^3", cubic);
  check(2, "100 at n = 1, then 1 + n/2", jump);
}
