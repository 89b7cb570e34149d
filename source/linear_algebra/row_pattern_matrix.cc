// RowPatternMatrix: the patterns of a matrix's rows, found by hashing, and
// the product that reads them; the rest of the Epetra interface passes on to
// the matrix.
#include <vpcontact/linear_algebra/row_pattern_matrix.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parallel.h>

#include <Epetra_Import.h>
#include <Epetra_MpiComm.h>
#include <cstring>
#include <unordered_map>

namespace VPContact
{
  namespace
  {
    /**
     * The share of the matrix's entries that the patterns may hold. Above
     * it the rows repeat too little for the product to read much less than
     * the matrix's (a mesh of unequal cells, where every row is its own
     * pattern), and the matrix's product, without the indirection, is used.
     */
    constexpr double max_pattern_share = 0.25;

    /// A hash of a row: its length, its column offsets and its values'
    /// bits, mixed as FNV-1a mixes bytes, a word at a time.
    std::uint64_t
    row_hash(const int     length,
             const int    *columns,
             const double *entries,
             const int     row)
    {
      constexpr std::uint64_t prime = 0x100000001b3ULL;
      std::uint64_t           hash  = 0xcbf29ce484222325ULL ^ length;
      for (int k = 0; k < length; ++k)
        {
          std::uint64_t bits;
          std::memcpy(&bits, entries + k, sizeof bits);
          hash = (hash ^ static_cast<std::uint32_t>(columns[k] - row)) * prime;
          hash = (hash ^ bits) * prime;
        }
      return hash;
    }
  } // namespace



  RowPatternMatrix::RowPatternMatrix(const Epetra_CrsMatrix &matrix)
    : matrix(matrix)
  {
    update();
  }



  void
  RowPatternMatrix::update()
  {
    find_patterns();
    // Each rank decides from its own rows (on a mesh of unequal cells in
    // one part, a rank's rows may repeat too little while another's
    // repeat); the callers need one answer.
    const auto *mpi  = dynamic_cast<const Epetra_MpiComm *>(&matrix.Comm());
    const int   mine = use_patterns ? 1 : 0;
    used_somewhere   = (mpi ? Utilities::MPI::max(mine, mpi->Comm()) : mine);
  }



  void
  RowPatternMatrix::find_patterns()
  {
    clear_patterns();
    use_patterns = false;
    x_columns.reset();

    // The product below reads the owned rows and writes the owned entries
    // of y: it needs the matrix in Epetra's contiguous storage, with its
    // rows laid out as y (no export of row sums to other ranks).
    int    *row_start = nullptr, *columns = nullptr;
    double *entries = nullptr;
    if (!matrix.Filled() || !matrix.StorageOptimized()
        || matrix.Exporter() != nullptr
        || matrix.ExtractCrsDataPointers(row_start, columns, entries) != 0)
      return;

    const int         n_rows      = matrix.NumMyRows();
    const std::size_t max_entries = static_cast<std::size_t>(
      max_pattern_share * static_cast<double>(matrix.NumMyNonzeros()));
    // Each hash names the first pattern with it; patterns of equal hash
    // (rare) are chained through next_same_hash.
    std::unordered_map<std::uint64_t, std::uint32_t> first_with_hash;
    std::vector<std::uint32_t>                       next_same_hash;
    constexpr std::uint32_t none = static_cast<std::uint32_t>(-1);
    row_pattern.resize(n_rows);
    for (int row = 0; row < n_rows; ++row)
      {
        const Row r{row,
                    row_start[row + 1] - row_start[row],
                    columns + row_start[row],
                    entries + row_start[row]};
        const auto [first, is_new] = first_with_hash.emplace(
          row_hash(r.length, r.columns, r.values, row),
          next_same_hash.size());
        std::uint32_t p    = (is_new ? none : first->second);
        std::uint32_t last = p;
        while (p != none && !is_pattern_of(p, r))
          last = p, p = next_same_hash[p];
        if (p == none)
          {
            p = next_same_hash.size();
            if (!is_new)
              next_same_hash[last] = p;
            next_same_hash.push_back(none);
            add_pattern(r);
            if (offsets.size() > max_entries)
              {
                clear_patterns();
                return;
              }
          }
        row_pattern[row] = p;
      }
    offsets.shrink_to_fit();
    values.shrink_to_fit();
    pattern_start.shrink_to_fit();
    use_patterns = true;
  }



  void
  RowPatternMatrix::clear_patterns()
  {
    row_pattern.clear();
    pattern_start.assign(1, 0);
    offsets.clear();
    values.clear();
  }



  bool
  RowPatternMatrix::is_pattern_of(const std::uint32_t pattern,
                                  const Row          &row) const
  {
    const std::uint32_t start = pattern_start[pattern];
    if (pattern_start[pattern + 1] - start
        != static_cast<std::uint32_t>(row.length))
      return false;
    for (int k = 0; k < row.length; ++k)
      if (offsets[start + k] != row.columns[k] - row.index)
        return false;
    return std::memcmp(values.data() + start,
                       row.values,
                       row.length * sizeof(double))
           == 0;
  }



  void
  RowPatternMatrix::add_pattern(const Row &row)
  {
    for (int k = 0; k < row.length; ++k)
      offsets.push_back(row.columns[k] - row.index);
    values.insert(values.end(), row.values, row.values + row.length);
    pattern_start.push_back(offsets.size());
  }



  bool
  RowPatternMatrix::compressed() const
  {
    return used_somewhere;
  }



  std::uint64_t
  RowPatternMatrix::n_patterns() const
  {
    const std::uint64_t mine = use_patterns ?
                                 pattern_start.size() - 1 :
                                 static_cast<std::uint64_t>(matrix.NumMyRows());
    const auto *mpi = dynamic_cast<const Epetra_MpiComm *>(&matrix.Comm());
    return mpi ? Utilities::MPI::sum(mine, mpi->Comm()) : mine;
  }



  void
  RowPatternMatrix::vmult(LA::MPI::Vector       &dst,
                          const LA::MPI::Vector &src) const
  {
    const int error
      = Multiply(false, src.trilinos_vector(), dst.trilinos_vector());
    AssertThrow(error == 0, ExcTrilinosError(error));
  }



  int
  RowPatternMatrix::Multiply(const bool                transpose,
                             const Epetra_MultiVector &X,
                             Epetra_MultiVector       &Y) const
  {
    // Only y = K x of one vector into another reads the patterns (K is
    // symmetric here, and the solvers ask for nothing else).
    if (!use_patterns || transpose || X.NumVectors() != 1 || Y.NumVectors() != 1
        || X[0] == Y[0])
      return matrix.Multiply(transpose, X, Y);
    const double *x = X[0];
    if (const Epetra_Import *importer = matrix.Importer())
      {
        // As Epetra's product: x with the other ranks' entries that the
        // owned rows read, in the matrix's column layout (owned first).
        if (!x_columns)
          x_columns = std::make_unique<Epetra_Vector>(matrix.ColMap(), false);
        if (const int error = x_columns->Import(X, *importer, Insert))
          return error;
        x = x_columns->Values();
      }
    multiply_rows(x, Y[0]);
    return 0;
  }



  void
  RowPatternMatrix::multiply_rows(const double *x, double *y) const
  {
    // Each row sums its entries in the matrix's order from zero, as
    // Epetra's product (epetra_dcrsmv) does, for the same bits. A row's
    // sum is a chain of dependent additions, each waiting for the last:
    // four rows of equal length are summed together, four chains at once.
    const auto rows = [&](const unsigned int begin, const unsigned int end) {
      unsigned int row = begin;
      for (; row + 4 <= end; row += 4)
        multiply_four_rows(row, x, y);
      for (; row < end; ++row)
        multiply_row(row, x, y);
    };
    parallel::apply_to_subranges(0u,
                                 static_cast<unsigned int>(row_pattern.size()),
                                 rows,
                                 rows_per_task);
  }



  void
  RowPatternMatrix::multiply_row(const unsigned int row,
                                 const double      *x,
                                 double            *y) const
  {
    const std::uint32_t p      = row_pattern[row];
    const std::uint32_t start  = pattern_start[p];
    const std::uint32_t length = pattern_start[p + 1] - start;
    const int          *offset = offsets.data() + start;
    const double       *value  = values.data() + start;
    const double       *x_row  = x + row;
    double              sum    = 0.;
    for (std::uint32_t k = 0; k < length; ++k)
      sum += value[k] * x_row[offset[k]];
    y[row] = sum;
  }



  void
  RowPatternMatrix::multiply_four_rows(const unsigned int row,
                                       const double      *x,
                                       double            *y) const
  {
    const std::uint32_t *p      = row_pattern.data() + row;
    const std::uint32_t  length = pattern_start[p[0] + 1] - pattern_start[p[0]];
    for (unsigned int j = 1; j < 4; ++j)
      if (pattern_start[p[j] + 1] - pattern_start[p[j]] != length)
        {
          for (unsigned int i = 0; i < 4; ++i)
            multiply_row(row + i, x, y);
          return;
        }
    const int    *o0 = offsets.data() + pattern_start[p[0]];
    const int    *o1 = offsets.data() + pattern_start[p[1]];
    const int    *o2 = offsets.data() + pattern_start[p[2]];
    const int    *o3 = offsets.data() + pattern_start[p[3]];
    const double *v0 = values.data() + pattern_start[p[0]];
    const double *v1 = values.data() + pattern_start[p[1]];
    const double *v2 = values.data() + pattern_start[p[2]];
    const double *v3 = values.data() + pattern_start[p[3]];
    const double *x0 = x + row;
    double        s0 = 0., s1 = 0., s2 = 0., s3 = 0.;
    for (std::uint32_t k = 0; k < length; ++k)
      {
        s0 += v0[k] * x0[o0[k]];
        s1 += v1[k] * x0[1 + o1[k]];
        s2 += v2[k] * x0[2 + o2[k]];
        s3 += v3[k] * x0[3 + o3[k]];
      }
    y[row]     = s0;
    y[row + 1] = s1;
    y[row + 2] = s2;
    y[row + 3] = s3;
  }



  int
  RowPatternMatrix::Apply(const Epetra_MultiVector &X,
                          Epetra_MultiVector       &Y) const
  {
    return Multiply(false, X, Y);
  }



  // The rest is the matrix's.

  int
  RowPatternMatrix::NumMyRowEntries(const int row, int &n_entries) const
  {
    return matrix.NumMyRowEntries(row, n_entries);
  }

  int
  RowPatternMatrix::MaxNumEntries() const
  {
    return matrix.MaxNumEntries();
  }

  int
  RowPatternMatrix::ExtractMyRowCopy(const int row,
                                     const int length,
                                     int      &n_entries,
                                     double   *values,
                                     int      *indices) const
  {
    return matrix.ExtractMyRowCopy(row, length, n_entries, values, indices);
  }

  int
  RowPatternMatrix::ExtractDiagonalCopy(Epetra_Vector &diagonal) const
  {
    return matrix.ExtractDiagonalCopy(diagonal);
  }

  int
  RowPatternMatrix::Solve(const bool                upper,
                          const bool                transpose,
                          const bool                unit_diagonal,
                          const Epetra_MultiVector &X,
                          Epetra_MultiVector       &Y) const
  {
    return matrix.Solve(upper, transpose, unit_diagonal, X, Y);
  }

  int
  RowPatternMatrix::InvRowSums(Epetra_Vector &x) const
  {
    return matrix.InvRowSums(x);
  }

  int
  RowPatternMatrix::LeftScale(const Epetra_Vector &)
  {
    return -1; // The view does not change the matrix.
  }

  int
  RowPatternMatrix::InvColSums(Epetra_Vector &x) const
  {
    return matrix.InvColSums(x);
  }

  int
  RowPatternMatrix::RightScale(const Epetra_Vector &)
  {
    return -1; // The view does not change the matrix.
  }

  bool
  RowPatternMatrix::Filled() const
  {
    return matrix.Filled();
  }

  double
  RowPatternMatrix::NormInf() const
  {
    return matrix.NormInf();
  }

  double
  RowPatternMatrix::NormOne() const
  {
    return matrix.NormOne();
  }

  int
  RowPatternMatrix::NumGlobalNonzeros() const
  {
    return matrix.NumGlobalNonzeros();
  }

  long long
  RowPatternMatrix::NumGlobalNonzeros64() const
  {
    return matrix.NumGlobalNonzeros64();
  }

  int
  RowPatternMatrix::NumGlobalRows() const
  {
    return matrix.NumGlobalRows();
  }

  long long
  RowPatternMatrix::NumGlobalRows64() const
  {
    return matrix.NumGlobalRows64();
  }

  int
  RowPatternMatrix::NumGlobalCols() const
  {
    return matrix.NumGlobalCols();
  }

  long long
  RowPatternMatrix::NumGlobalCols64() const
  {
    return matrix.NumGlobalCols64();
  }

  int
  RowPatternMatrix::NumGlobalDiagonals() const
  {
    return matrix.NumGlobalDiagonals();
  }

  long long
  RowPatternMatrix::NumGlobalDiagonals64() const
  {
    return matrix.NumGlobalDiagonals64();
  }

  int
  RowPatternMatrix::NumMyNonzeros() const
  {
    return matrix.NumMyNonzeros();
  }

  int
  RowPatternMatrix::NumMyRows() const
  {
    return matrix.NumMyRows();
  }

  int
  RowPatternMatrix::NumMyCols() const
  {
    return matrix.NumMyCols();
  }

  int
  RowPatternMatrix::NumMyDiagonals() const
  {
    return matrix.NumMyDiagonals();
  }

  bool
  RowPatternMatrix::LowerTriangular() const
  {
    return matrix.LowerTriangular();
  }

  bool
  RowPatternMatrix::UpperTriangular() const
  {
    return matrix.UpperTriangular();
  }

  const Epetra_Map &
  RowPatternMatrix::RowMatrixRowMap() const
  {
    return matrix.RowMatrixRowMap();
  }

  const Epetra_Map &
  RowPatternMatrix::RowMatrixColMap() const
  {
    return matrix.RowMatrixColMap();
  }

  const Epetra_Import *
  RowPatternMatrix::RowMatrixImporter() const
  {
    return matrix.RowMatrixImporter();
  }

  int
  RowPatternMatrix::SetUseTranspose(const bool use_transpose)
  {
    return use_transpose ? -1 : 0; // K is applied as it is.
  }

  int
  RowPatternMatrix::ApplyInverse(const Epetra_MultiVector &,
                                 Epetra_MultiVector &) const
  {
    return -1; // A product, not a solver.
  }

  const char *
  RowPatternMatrix::Label() const
  {
    return "vpcontact row pattern matrix";
  }

  bool
  RowPatternMatrix::UseTranspose() const
  {
    return false;
  }

  bool
  RowPatternMatrix::HasNormInf() const
  {
    return true;
  }

  const Epetra_Comm &
  RowPatternMatrix::Comm() const
  {
    return matrix.Comm();
  }

  const Epetra_Map &
  RowPatternMatrix::OperatorDomainMap() const
  {
    return matrix.OperatorDomainMap();
  }

  const Epetra_Map &
  RowPatternMatrix::OperatorRangeMap() const
  {
    return matrix.OperatorRangeMap();
  }

  const Epetra_BlockMap &
  RowPatternMatrix::Map() const
  {
    return matrix.Map();
  }
} // namespace VPContact
