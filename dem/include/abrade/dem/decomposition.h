#pragma once
// Spatial domain decomposition of the particles over the ranks by recursive coordinate
// bisection (RCB): the set of ranks is halved, the space cut across its longest particle
// extent at the plane that splits the particles in the ranks' proportion, and each half cut
// again, until every rank has one box. Boxes tile all of space (the outer ones reach to
// infinity), so every position has exactly one owner; the cut planes follow the particles, so
// a bed that settles or is pushed aside by a knife is rebalanced by cutting again.
//
// The cuts are found in parallel (bisection on the cut coordinate with a global count per
// trial plane), so no rank needs all particles.
#include <abrade/dem/parallel.h>
#include <abrade/dem/triangle_mesh.h>

#include <vector>

namespace abrade::dem
{
  struct Box
  {
    Vec3 lo = Vec3::Constant(-std::numeric_limits<double>::infinity());
    Vec3 hi = Vec3::Constant(std::numeric_limits<double>::infinity());
    /// Distance from @p p to the box (0 inside).
    double distance(double x, double y, double z) const
    {
      const double dx = std::max({lo[0] - x, 0.0, x - hi[0]}), dy = std::max({lo[1] - y, 0.0, y - hi[1]}),
                   dz = std::max({lo[2] - z, 0.0, z - hi[2]});
      return std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    /// Distance between this box and @p o (0 if they touch or overlap); symmetric, and never
    /// more than the distance from @p o to a point inside this box.
    double distance(const Box &o) const
    {
      double d2 = 0;
      for (int d = 0; d < 3; ++d)
        {
          const double gap = std::max({o.lo[d] - hi[d], 0.0, lo[d] - o.hi[d]});
          d2 += gap * gap;
        }
      return std::sqrt(d2);
    }
    /// Distance from @p p (inside) to the nearest face.
    double depth(double x, double y, double z) const
    {
      return std::min({x - lo[0], hi[0] - x, y - lo[1], hi[1] - y, z - lo[2], hi[2] - z});
    }
  };

  class Decomposition
  {
  public:
    /// Everything on rank 0 until balance() is called.
    Decomposition() { reset(1); }

    /// Cuts space into one box per rank of @p parallel with equal numbers of the particles at
    /// (x, y, z) (this rank's n of them) in each. Collective.
    void balance(const Parallel &parallel, const double *x, const double *y, const double *z, std::size_t n);

    int owner(double x, double y, double z) const
    {
      int k = 0;
      while (nodes[k].axis >= 0)
        {
          const double p[3] = {x, y, z};
          k = p[nodes[k].axis] < nodes[k].cut ? nodes[k].left : nodes[k].left + 1;
        }
      return nodes[k].rank;
    }
    const Box &box(int rank) const { return boxes[rank]; }
    /// Appends to @p ranks every rank other than @p except whose box is closer than @p cutoff
    /// to (x, y, z), found by a walk of the bisection tree (log P for a point near few boxes).
    void ranks_near(double x, double y, double z, double cutoff, int except, std::vector<int> &ranks) const
    {
      int stack[64], top = 0;
      stack[top++] = 0;
      while (top > 0)
        {
          const Node &node = nodes[stack[--top]];
          if (!(node.box.distance(x, y, z) < cutoff))
            continue;
          if (node.axis < 0)
            {
              if (node.rank != except)
                ranks.push_back(node.rank);
            }
          else
            stack[top++] = node.left, stack[top++] = node.left + 1;
        }
    }
    /// The ranks other than @p rank whose box is closer than @p reach to @p rank's box: the
    /// only ranks that can send @p rank (or receive from it) a ghost within @p reach, or a
    /// particle that moved less than @p reach since the boxes were cut. Symmetric.
    std::vector<int> neighbours(int rank, double reach) const
    {
      std::vector<int> near;
      for (int r = 0; r < n_domains(); ++r)
        if (r != rank && boxes[r].distance(boxes[rank]) < reach)
          near.push_back(r);
      return near;
    }
    int        n_domains() const { return static_cast<int>(boxes.size()); }

  private:
    struct Node
    {
      int    axis = -1; ///< -1: a leaf (one rank's box)
      double cut  = 0;  ///< below: left child, at or above: right child (left + 1)
      int    left = -1;
      int    rank = 0;  ///< leaves only
      Box    box;       ///< the part of space under this node
    };
    std::vector<Node> nodes;
    std::vector<Box>  boxes;

    void reset(int n_ranks);

    // the steps of balance(), one level of the tree at a time
    /// A part of space still to cut: its node of the tree, its ranks [first, last), its box.
    struct Part
    {
      int node, first, last;
      Box box;
    };
    /// How a level cuts its parts, per part: the axis (the particles' longest extent), the
    /// bracket [lo, hi] of the plane, the count of particles to go below it (the ranks'
    /// proportion), the plane.
    struct Cuts
    {
      std::vector<int>    axis;
      std::vector<double> lo, hi, target, cut;
    };
    /// Each part's axis, bracket and target from the particles at @p coordinate (this rank's
    /// @p n of them, in part @p part_of[i], -1: none). Collective.
    static Cuts axes_and_targets(const Parallel &parallel, const double *const coordinate[3], std::size_t n,
                                 const std::vector<Part> &parts, const std::vector<int> &part_of);
    /// Every part's plane at once, by bisection on the global count below it. Collective.
    static void bisect(const Parallel &parallel, const double *const coordinate[3], std::size_t n,
                       const std::vector<int> &part_of, Cuts &cuts);
    /// The parts cut: their children become nodes of the tree (a child of one rank that rank's
    /// box), the particles move into them; returns the children still to cut.
    std::vector<Part> split(const std::vector<Part> &parts, const Cuts &cuts, const double *const coordinate[3],
                            std::size_t n, std::vector<int> &part_of);
  };
} // namespace abrade::dem
