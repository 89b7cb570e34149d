// Memory bandwidth of this machine: the STREAM triad a = b + s c on three
// arrays far larger than the caches, best of 20 sweeps, in GB/s. Run one
// copy alone and then one copy per core at the same time
//   g++ -O3 -march=native -o /tmp/bandwidth scripts/bandwidth.cc
//   /tmp/bandwidth; for i in 1 2; do /tmp/bandwidth & done; wait
// the sum of their rates against the rate of one copy alone is how far a
// bandwidth-bound phase (sparse matrix-vector products, AMG V-cycles) can
// speed up on more ranks of the same machine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int
main(int argc, char **argv)
{
  // 3 x 64 MB by default, twice the 32 MB L3 cache of each array alone.
  const std::size_t   n = (argc > 1 ? std::atol(argv[1]) : 8L << 20);
  std::vector<double> a(n, 0.), b(n, 1.), c(n, 2.);
  double              best = 1e30;
  for (int sweep = 0; sweep < 20; ++sweep)
    {
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < n; ++i)
        a[i] = b[i] + 3. * c[i];
      const std::chrono::duration<double> t
        = std::chrono::steady_clock::now() - start;
      best = std::min(best, t.count());
      std::swap(a, b); // keeps the compiler from hoisting the loop
    }
  // Three arrays of n doubles move per sweep (two read, one written).
  std::printf("%.3f\n", 3. * sizeof(double) * n / best / 1e9);
  return (a[n / 2] > 0 ? 0 : 1);
}
