#include "vtkLightShaftReferenceTriangleTree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
using Vec = vtkLightShaftReferenceTriangleTree::Vec;

Vec Minus(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Triangles a leaf holds at most.
constexpr int LeafSize = 4;
}

/// A segment prepared for the box and triangle tests.
struct vtkLightShaftReferenceTriangleTree::Ray
{
  Vec Origin;
  Vec Direction;
  Vec Inverse;

  Ray(const Vec& from, const Vec& to)
    : Origin(from)
    , Direction(Minus(to, from))
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      // 1 / 0 = inf keeps the slab test right for a segment parallel to a slab.
      this->Inverse[axis] = 1.0 / this->Direction[axis];
    }
  }

  /// Whether the segment meets the box (padded when built: a crossing on its face counts).
  bool Meets(const double bounds[6]) const
  {
    double lo = 0.0;
    double hi = 1.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double a = (bounds[2 * axis] - this->Origin[axis]) * this->Inverse[axis];
      const double b = (bounds[2 * axis + 1] - this->Origin[axis]) * this->Inverse[axis];
      // NaN (0 * inf: the origin on a slab's plane, parallel to it) leaves lo and hi as they
      // are: inside.
      const double t0 = std::min(a, b);
      const double t1 = std::max(a, b);
      lo = t0 > lo ? t0 : lo;
      hi = t1 < hi ? t1 : hi;
      if (lo > hi)
      {
        return false;
      }
    }
    return true;
  }

  /// Moller-Trumbore: the crossing's t in [0, 1], edges included; false when none.
  bool Crosses(const Triangle& triangle, double& t) const
  {
    const Vec p = Cross(this->Direction, triangle.Edge2);
    const double determinant = Dot(triangle.Edge1, p);
    if (determinant == 0.0)
    {
      return false; // parallel to the triangle's plane
    }
    const double inverse = 1.0 / determinant;
    const Vec s = Minus(this->Origin, triangle.A);
    const double u = Dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0)
    {
      return false;
    }
    const Vec q = Cross(s, triangle.Edge1);
    const double v = Dot(this->Direction, q) * inverse;
    if (v < 0.0 || u + v > 1.0)
    {
      return false;
    }
    t = Dot(triangle.Edge2, q) * inverse;
    return t >= 0.0 && t <= 1.0;
  }
};

//------------------------------------------------------------------------------
void vtkLightShaftReferenceTriangleTree::Clear()
{
  this->Triangles.clear();
  this->Nodes.clear();
}

void vtkLightShaftReferenceTriangleTree::Add(const Vec& a, const Vec& b, const Vec& c, int owner)
{
  const Vec edge1 = Minus(b, a);
  const Vec edge2 = Minus(c, a);
  const Vec normal = Cross(edge1, edge2);
  if (Dot(normal, normal) == 0.0)
  {
    return; // no area: no segment crosses it
  }
  this->Triangles.push_back({ a, edge1, edge2, owner });
}

//------------------------------------------------------------------------------
void vtkLightShaftReferenceTriangleTree::Build()
{
  this->Nodes.clear();
  if (this->Triangles.empty())
  {
    return;
  }
  std::vector<Vec> centroids;
  centroids.reserve(this->Triangles.size());
  for (const Triangle& triangle : this->Triangles)
  {
    Vec centroid;
    for (int axis = 0; axis < 3; ++axis)
    {
      centroid[axis] = triangle.A[axis] + (triangle.Edge1[axis] + triangle.Edge2[axis]) / 3.0;
    }
    centroids.push_back(centroid);
  }
  this->Nodes.reserve(2 * this->Triangles.size() / LeafSize + 1);
  this->BuildNode(0, static_cast<int>(this->Triangles.size()), centroids);
}

int vtkLightShaftReferenceTriangleTree::BuildNode(int first, int count, std::vector<Vec>& centroids)
{
  const int index = static_cast<int>(this->Nodes.size());
  this->Nodes.push_back(Node());
  Node node;
  double centroidBounds[6];
  for (int axis = 0; axis < 3; ++axis)
  {
    node.Bounds[2 * axis] = centroidBounds[2 * axis] = std::numeric_limits<double>::max();
    node.Bounds[2 * axis + 1] = centroidBounds[2 * axis + 1] =
      std::numeric_limits<double>::lowest();
  }
  for (int i = first; i < first + count; ++i)
  {
    const Triangle& triangle = this->Triangles[i];
    for (int axis = 0; axis < 3; ++axis)
    {
      const double a = triangle.A[axis];
      const double b = a + triangle.Edge1[axis];
      const double c = a + triangle.Edge2[axis];
      node.Bounds[2 * axis] = std::min({ node.Bounds[2 * axis], a, b, c });
      node.Bounds[2 * axis + 1] = std::max({ node.Bounds[2 * axis + 1], a, b, c });
      centroidBounds[2 * axis] = std::min(centroidBounds[2 * axis], centroids[i][axis]);
      centroidBounds[2 * axis + 1] = std::max(centroidBounds[2 * axis + 1], centroids[i][axis]);
    }
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (centroidBounds[2 * k + 1] - centroidBounds[2 * k] >
        centroidBounds[2 * axis + 1] - centroidBounds[2 * axis])
    {
      axis = k;
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    // Padded: a segment that ends on a face, or runs in it, still meets the box.
    const double pad =
      1e-9 * (std::abs(node.Bounds[2 * k]) + std::abs(node.Bounds[2 * k + 1]) + 1.0);
    node.Bounds[2 * k] -= pad;
    node.Bounds[2 * k + 1] += pad;
  }
  if (count <= LeafSize || centroidBounds[2 * axis + 1] <= centroidBounds[2 * axis])
  {
    node.First = first;
    node.Count = count;
    this->Nodes[index] = node;
    return index;
  }
  // The median of the centroids on the longest axis: triangles and centroids move together.
  const int half = count / 2;
  std::vector<int> order(count);
  for (int i = 0; i < count; ++i)
  {
    order[i] = first + i;
  }
  std::nth_element(order.begin(),
    order.begin() + half,
    order.end(),
    [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
  std::vector<Triangle> triangles;
  std::vector<Vec> points;
  for (int i : order)
  {
    triangles.push_back(this->Triangles[i]);
    points.push_back(centroids[i]);
  }
  std::copy(triangles.begin(), triangles.end(), this->Triangles.begin() + first);
  std::copy(points.begin(), points.end(), centroids.begin() + first);
  this->BuildNode(first, half, centroids);
  node.First = this->BuildNode(first + half, count - half, centroids);
  node.Count = 0;
  this->Nodes[index] = node;
  return index;
}

//------------------------------------------------------------------------------
template<typename Visit>
void vtkLightShaftReferenceTriangleTree::Traverse(const Ray& ray, Visit&& visit) const
{
  if (this->Nodes.empty())
  {
    return;
  }
  int stack[128];
  int depth = 0;
  stack[depth++] = 0;
  while (depth > 0)
  {
    const Node& node = this->Nodes[stack[--depth]];
    if (!ray.Meets(node.Bounds))
    {
      continue;
    }
    if (node.Count > 0)
    {
      for (int i = node.First; i < node.First + node.Count; ++i)
      {
        if (!visit(this->Triangles[i]))
        {
          return;
        }
      }
      continue;
    }
    const int left = static_cast<int>(&node - this->Nodes.data()) + 1;
    if (depth + 2 <= 128)
    {
      stack[depth++] = node.First;
      stack[depth++] = left;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceTriangleTree::Nearest(const Vec& from,
  const Vec& to,
  double& t,
  int& owner) const
{
  const Ray ray(from, to);
  bool any = false;
  t = 1.0;
  this->Traverse(ray,
    [&](const Triangle& triangle)
    {
      double hit;
      if (ray.Crosses(triangle, hit) && (!any || hit < t))
      {
        t = hit;
        owner = triangle.Owner;
        any = true;
      }
      return true;
    });
  return any;
}

bool vtkLightShaftReferenceTriangleTree::Any(const Vec& from, const Vec& to) const
{
  const Ray ray(from, to);
  bool any = false;
  this->Traverse(ray,
    [&](const Triangle& triangle)
    {
      double hit;
      any = ray.Crosses(triangle, hit);
      return !any;
    });
  return any;
}

void vtkLightShaftReferenceTriangleTree::All(const Vec& from,
  const Vec& to,
  std::vector<std::pair<double, int>>& hits) const
{
  hits.clear();
  const Ray ray(from, to);
  this->Traverse(ray,
    [&](const Triangle& triangle)
    {
      double hit;
      if (ray.Crosses(triangle, hit))
      {
        hits.emplace_back(hit, triangle.Owner);
      }
      return true;
    });
  std::sort(hits.begin(),
    hits.end(),
    [](const std::pair<double, int>& a, const std::pair<double, int>& b)
    { return a.first < b.first || (a.first == b.first && a.second < b.second); });
  // One crossing per surface where the segment passes through a shared edge or corner.
  auto same = [](const std::pair<double, int>& a, const std::pair<double, int>& b)
  { return a.second == b.second && std::abs(a.first - b.first) <= 1e-12; };
  hits.erase(std::unique(hits.begin(), hits.end(), same), hits.end());
}

void vtkLightShaftReferenceTriangleTree::Crossed(const Vec& from,
  const Vec& to,
  std::vector<std::array<Vec, 3>>& corners) const
{
  corners.clear();
  const Ray ray(from, to);
  this->Traverse(ray,
    [&](const Triangle& triangle)
    {
      double hit;
      if (ray.Crosses(triangle, hit))
      {
        const Vec& a = triangle.A;
        corners.push_back({ a,
          Vec{ a[0] + triangle.Edge1[0], a[1] + triangle.Edge1[1], a[2] + triangle.Edge1[2] },
          Vec{ a[0] + triangle.Edge2[0], a[1] + triangle.Edge2[1], a[2] + triangle.Edge2[2] } });
      }
      return true;
    });
}
