// The supernodes of a Cholesky factor split into two groups of independent
// subtrees of the elimination tree and the top above them, so that the
// triangular substitutions can run on the two groups at once.
#ifndef vpcontact_supernode_partition_h
#define vpcontact_supernode_partition_h

#include <array>
#include <cholmod.h>
#include <utility>
#include <vector>

namespace VPContact
{
  /**
   * A supernode's rows below its diagonal block are rows of its ancestors
   * in the elimination tree. Two subtrees of which neither contains the
   * other therefore never touch each other's unknowns in a forward or a
   * backward substitution: only the ancestors they share, the top. The
   * partition takes supernodes off the top of the tree, heaviest subtree
   * first, until what hangs below them falls into two groups of about the
   * same work (the number of stored entries of L). For the 2d meshes of
   * the paper scene one supernode does (the last separator of the
   * ordering): measured at 512^2 cells, the top holds 5.7 % of the
   * entries and the two groups 45 % and 49 %.
   *
   * CHOLMOD numbers the supernodes in postorder, so every subtree is a
   * range of consecutive supernodes and a group is a list of ranges. The
   * partition checks this; should the numbering not be a postorder, or the
   * rows below a supernode not put the top's rows last, everything is one
   * group, which is the plain sequential substitution.
   */
  struct SupernodePartition
  {
    /// Split the supernodes of @p factor (supernodal, after
    /// cholmod_factorize()).
    explicit SupernodePartition(const cholmod_factor &factor);

    SupernodePartition() = default;

    /// The two groups: ranges [first, last] of supernodes, each a subtree.
    std::array<std::vector<std::pair<long, long>>, 2> groups;
    /// The supernodes above the groups, in increasing order.
    std::vector<long> top;
    /// The columns of the top supernodes, and for every column its
    /// position among them (or -1).
    std::vector<long> top_columns;
    std::vector<int>  top_slot;
    /// For every supernode, how many of its rows below the diagonal block
    /// come before the first row of the top (all of them for the top's own
    /// supernodes).
    std::vector<long> rows_below_before_top;
  };
} // namespace VPContact

#endif
