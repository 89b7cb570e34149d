// A view of a Trilinos (Epetra) matrix whose products read the entries of
// rows that repeat, as the rows of a mesh of equal cells do, from one stored
// copy instead of from every row: the matrix-vector product that CG and
// ML's finest level take from the displacement matrix.
#ifndef vpcontact_row_pattern_matrix_h
#define vpcontact_row_pattern_matrix_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_RowMatrix.h>
#include <Epetra_Vector.h>
#include <cstdint>
#include <memory>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The product y = K x of a distributed matrix K whose rows fall into few
   * patterns: a row's pattern is its length, the offsets of its columns from
   * its own local index, and its values, bit for bit. On a mesh whose cells
   * are all translates of one (a subdivided box), the unknowns numbered
   * along the rows of the box, every interior row of the elasticity matrix
   * is one of dim patterns; only the rows at the boundary and beside other
   * ranks' columns have their own.
   *
   * The product of a compressed sparse row matrix (Epetra's) reads 12 bytes
   * per entry, its value and its column, for a few floating point operations:
   * at 18 entries a row in 2D it is bound by the memory traffic, and it is
   * most of CG's and ML's work on the finest level. Here a row costs the
   * 4 bytes of its pattern's number; the patterns themselves stay in the
   * cache. Each row sums its entries in the order the matrix stores them,
   * as Epetra's product does, so that y is the same bit for bit.
   *
   * The class is an Epetra_RowMatrix: ML takes it in place of the matrix
   * (its products then come from here, its rows from the matrix), and
   * deal.II's CG through vmult(). Everything but the product is the
   * matrix's own. Where the rows do not repeat enough to save traffic (a
   * mesh of unequal cells), the product is the matrix's.
   *
   * The matrix must outlive this object; after a change of its values,
   * update() takes them in.
   */
  class RowPatternMatrix : public Epetra_RowMatrix
  {
  public:
    explicit RowPatternMatrix(const Epetra_CrsMatrix &matrix);

    /// Take in the values of the matrix again (its pattern is unchanged).
    /// Collective, as the constructor.
    void
    update();

    /**
     * Whether the products read the patterns on some rank; false: they are
     * the matrix's own on every rank. The same on every rank, so that the
     * callers that choose between this object and the matrix by it call
     * the same collective operations everywhere; a rank whose own rows
     * repeat too little takes the matrix's product for them.
     */
    bool
    compressed() const;

    /// The number of distinct rows kept, summed over the ranks.
    std::uint64_t
    n_patterns() const;

    /// dst = K src, for deal.II's solvers.
    void
    vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const;

    int
    Multiply(bool                      transpose,
             const Epetra_MultiVector &X,
             Epetra_MultiVector       &Y) const override;

    int
    Apply(const Epetra_MultiVector &X, Epetra_MultiVector &Y) const override;

    // The rest of Epetra_RowMatrix and Epetra_Operator: the matrix's.
    int
    NumMyRowEntries(int row, int &n_entries) const override;
    int
    MaxNumEntries() const override;
    int
    ExtractMyRowCopy(int     row,
                     int     length,
                     int    &n_entries,
                     double *values,
                     int    *indices) const override;
    int
    ExtractDiagonalCopy(Epetra_Vector &diagonal) const override;
    int
    Solve(bool                      upper,
          bool                      transpose,
          bool                      unit_diagonal,
          const Epetra_MultiVector &X,
          Epetra_MultiVector       &Y) const override;
    int
    InvRowSums(Epetra_Vector &x) const override;
    int
    LeftScale(const Epetra_Vector &x) override;
    int
    InvColSums(Epetra_Vector &x) const override;
    int
    RightScale(const Epetra_Vector &x) override;
    bool
    Filled() const override;
    double
    NormInf() const override;
    double
    NormOne() const override;
    int
    NumGlobalNonzeros() const override;
    long long
    NumGlobalNonzeros64() const override;
    int
    NumGlobalRows() const override;
    long long
    NumGlobalRows64() const override;
    int
    NumGlobalCols() const override;
    long long
    NumGlobalCols64() const override;
    int
    NumGlobalDiagonals() const override;
    long long
    NumGlobalDiagonals64() const override;
    int
    NumMyNonzeros() const override;
    int
    NumMyRows() const override;
    int
    NumMyCols() const override;
    int
    NumMyDiagonals() const override;
    bool
    LowerTriangular() const override;
    bool
    UpperTriangular() const override;
    const Epetra_Map &
    RowMatrixRowMap() const override;
    const Epetra_Map &
    RowMatrixColMap() const override;
    const Epetra_Import *
    RowMatrixImporter() const override;
    int
    SetUseTranspose(bool use_transpose) override;
    int
    ApplyInverse(const Epetra_MultiVector &X,
                 Epetra_MultiVector       &Y) const override;
    const char *
    Label() const override;
    bool
    UseTranspose() const override;
    bool
    HasNormInf() const override;
    const Epetra_Comm &
    Comm() const override;
    const Epetra_Map &
    OperatorDomainMap() const override;
    const Epetra_Map &
    OperatorRangeMap() const override;
    const Epetra_BlockMap &
    Map() const override;

  private:
    /// Rows per task of the product where deal.II runs several threads.
    static constexpr unsigned int rows_per_task = 16384;

    /// One row of the matrix: its local index and its entries.
    struct Row
    {
      int           index;
      int           length;
      const int    *columns;
      const double *values;
    };

    /// The patterns of the owned rows, or none where they would hold
    /// too much (use_patterns false).
    void
    find_patterns();

    void
    clear_patterns();

    /// Whether @p row has the columns (as offsets) and values of @p pattern.
    bool
    is_pattern_of(std::uint32_t pattern, const Row &row) const;

    /// A new pattern of @p row's offsets and values.
    void
    add_pattern(const Row &row);

    /// y = K x on the owned rows, x laid out like the matrix's columns.
    void
    multiply_rows(const double *x, double *y) const;

    /// y = K x on row @p row.
    void
    multiply_row(unsigned int row, const double *x, double *y) const;

    /// y = K x on the rows @p row to @p row + 3, summed side by side where
    /// they are of equal length.
    void
    multiply_four_rows(unsigned int row, const double *x, double *y) const;

    const Epetra_CrsMatrix &matrix;

    /// Per owned row: the number of its pattern.
    std::vector<std::uint32_t> row_pattern;
    /// Per pattern: where its entries start in offsets and values (one
    /// more than patterns, the last the end).
    std::vector<std::uint32_t> pattern_start;
    /// The patterns' entries: column minus row, and value.
    std::vector<int>    offsets;
    std::vector<double> values;

    /// Whether this rank's products read its patterns, and whether some
    /// rank's do.
    bool use_patterns   = false;
    bool used_somewhere = false;

    /// x with the other ranks' entries that the rows read (the matrix's
    /// column layout), where there are such columns.
    mutable std::unique_ptr<Epetra_Vector> x_columns;
  };
} // namespace VPContact

#endif
