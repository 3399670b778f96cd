/**
 * @file   vtkLightShaftReferenceTriangleTree.h
 * @brief  A bounding-volume hierarchy of triangles for the reference's segment queries
 *         (private, not installed).
 */

#ifndef vtkLightShaftReferenceTriangleTree_h
#define vtkLightShaftReferenceTriangleTree_h

#include <array>   // For the points
#include <cstddef> // For size_t
#include <utility> // For the hits
#include <vector>  // For the triangles and nodes

/**
 * @class   vtkLightShaftReferenceTriangleTree
 * @brief   Triangles in world coordinates, each with the index of the surface it belongs to,
 *          in a bounding-volume hierarchy (median splits of the centroids on the longest axis,
 *          four triangles a leaf), queried by segments from -> to, x(t) = from + t (to - from),
 *          t in [0, 1]: the nearest crossing, whether there is any, or all of them.
 *
 * The crossing test is Moller and Trumbore's in double precision, edges and corners included;
 * a segment through an edge or corner shared by triangles of one surface crosses the surface
 * once (All() merges crossings of one surface at the same t). Read-only after Build(): any
 * number of threads may query it at once.
 */
class vtkLightShaftReferenceTriangleTree
{
public:
  using Vec = std::array<double, 3>;

  /// Forget every triangle.
  void Clear();
  /// Add the triangle (a, b, c) of surface `owner` (degenerate triangles are left out).
  void Add(const Vec& a, const Vec& b, const Vec& c, int owner);
  /// Build the hierarchy of the triangles added (before any query).
  void Build();
  bool IsEmpty() const { return this->Triangles.empty(); }
  size_t GetNumberOfTriangles() const { return this->Triangles.size(); }

  /// The nearest crossing of the segment: its t and surface; false when none.
  bool Nearest(const Vec& from, const Vec& to, double& t, int& owner) const;
  /// Whether the segment crosses any triangle.
  bool Any(const Vec& from, const Vec& to) const;
  /// Every crossing of the segment, (t, surface), in order of t, one per surface and t.
  void All(const Vec& from, const Vec& to, std::vector<std::pair<double, int>>& hits) const;
  /// The corners of every triangle the segment crosses (each triangle once, in no order).
  void Crossed(const Vec& from, const Vec& to, std::vector<std::array<Vec, 3>>& corners) const;

private:
  struct Triangle
  {
    Vec A, Edge1, Edge2;
    int Owner;
  };
  struct Node
  {
    double Bounds[6];
    int First; ///< leaf: first triangle; inner: the right child (the left is next)
    int Count; ///< leaf: how many triangles; inner: 0
  };
  struct Ray;
  int BuildNode(int first, int count, std::vector<Vec>& centroids);
  /// Visit the triangles the segment may cross; `visit` returns false to stop.
  template<typename Visit>
  void Traverse(const Ray& ray, Visit&& visit) const;

  std::vector<Triangle> Triangles;
  std::vector<Node> Nodes;
};

#endif
